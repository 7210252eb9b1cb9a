// A screenshot of a replay page at one moment, in a headless Chromium (Debian's), as the
// README's picture is made:
//   node scripts/replay_screenshot.mjs FILE.html OUT.png [trial=2&t=12]
// The browser is started here and stopped by its pid.
import { existsSync } from "node:fs";
import { createRequire } from "node:module";
import { dirname, join, resolve } from "node:path";
import { fileURLToPath } from "node:url";

const root = resolve(dirname(fileURLToPath(import.meta.url)), "..");
const { chromium } = createRequire(join(root, "replay", "page", "package.json"))("playwright-core");
const [file, out, moment = "trial=1&t=0"] = process.argv.slice(2);
if (!file || !out) {
  console.error("replay_screenshot.mjs: usage: node replay_screenshot.mjs FILE.html OUT.png [trial=N&t=SECONDS]");
  process.exit(2);
}
if (!existsSync(file)) {
  console.error(`replay_screenshot.mjs: ${file}: no such file`);
  process.exit(2);
}
const server = await chromium.launchServer({
  executablePath: "/usr/bin/chromium",
  args: ["--no-sandbox", "--enable-unsafe-swiftshader", "--use-angle=swiftshader"],
});
const pid = server.process().pid;
try {
  const browser = await chromium.connect(server.wsEndpoint());
  const page = await browser.newPage({ viewport: { width: 1280, height: 720 } });
  await page.goto(`file://${resolve(file)}#pause&${moment}`);
  await page.waitForFunction(() => document.body.dataset.ready === "true");
  await page.waitForTimeout(500);
  await page.screenshot({ path: out });
  await browser.close();
} finally {
  await server.close().catch(() => {});
  try { process.kill(pid, "SIGKILL"); } catch { /* already gone */ }
}
