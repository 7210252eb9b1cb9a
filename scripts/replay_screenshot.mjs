// A screenshot of a replay page at one moment, in a headless Chromium (Debian's), as the
// picture in docs/plants.md is made:
//   node scripts/replay_screenshot.mjs FILE.html OUT.png [trial=2&t=12]
import { existsSync } from "node:fs";
import { resolve } from "node:path";
import { withChromium } from "../replay/page/chromium.mjs";

const [file, out, moment = "trial=1&t=0"] = process.argv.slice(2);
if (!file || !out) {
  console.error("replay_screenshot.mjs: usage: node replay_screenshot.mjs FILE.html OUT.png [trial=N&t=SECONDS]");
  process.exit(2);
}
if (!existsSync(file)) {
  console.error(`replay_screenshot.mjs: ${file}: no such file`);
  process.exit(2);
}
await withChromium(async (browser) => {
  const page = await browser.newPage({ viewport: { width: 1280, height: 720 } });
  await page.goto(`file://${resolve(file)}#pause&${moment}`);
  await page.waitForFunction(() => document.body.dataset.ready === "true");
  await page.waitForTimeout(500);
  await page.screenshot({ path: out });
});
