// Debian's Chromium, headless, through playwright-core: started for one use and stopped by
// its pid whatever happens (the browser test and docs/plants.md's screenshot share it).
import { existsSync } from "node:fs";
import { chromium } from "playwright-core";

export const CHROMIUM = "/usr/bin/chromium";

// SwiftShader gives WebGL without a GPU.
export const WITH_WEBGL = ["--enable-unsafe-swiftshader", "--use-angle=swiftshader"];
// A browser that offers no WebGL at all, as some do (no GPU, or WebGL turned off).
export const WITHOUT_WEBGL = ["--disable-webgl", "--disable-3d-apis"];

// Runs `use(browser)` and returns what it returns; `graphics` chooses the browser's WebGL.
export async function withChromium(use, graphics = WITH_WEBGL) {
  if (!existsSync(CHROMIUM)) {
    throw new Error(`${CHROMIUM} is missing (scripts/setup.sh installs Debian's chromium)`);
  }
  const server = await chromium.launchServer({
    executablePath: CHROMIUM,
    args: ["--no-sandbox", ...graphics],
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
