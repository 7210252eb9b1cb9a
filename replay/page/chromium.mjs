// Debian's Chromium, headless, through playwright-core: started for one use and stopped by
// its pid whatever happens (the browser test and the README's screenshot share it).
import { existsSync } from "node:fs";
import { chromium } from "playwright-core";

export const CHROMIUM = "/usr/bin/chromium";

// Runs `use(browser)` and returns what it returns.
export async function withChromium(use) {
  if (!existsSync(CHROMIUM)) {
    throw new Error(`${CHROMIUM} is missing (scripts/setup.sh installs Debian's chromium)`);
  }
  // SwiftShader gives WebGL without a GPU.
  const server = await chromium.launchServer({
    executablePath: CHROMIUM,
    args: ["--no-sandbox", "--enable-unsafe-swiftshader", "--use-angle=swiftshader"],
  });
  const pid = server.process().pid;
  try {
    const browser = await chromium.connect(server.wsEndpoint());
    try {
      return await use(browser);
    } finally {
      await browser.close();
    }
  } finally {
    await server.close().catch(() => {});
    try { process.kill(pid, "SIGKILL"); } catch { /* already gone */ }
  }
}
