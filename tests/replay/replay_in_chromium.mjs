// cbbg replay's page in a real headless Chromium (Debian's), offline: the replays of an exp1
// and an exp2 run load without console errors or network requests; two moments of a trial
// look different; the pitch the page shows at a logged time is the log's.
//   node tests/replay/replay_in_chromium.mjs BUILD_DIR
// It starts the browser itself and stops it by its pid, whatever happens (withChromium).
import { execFileSync } from "node:child_process";
import { mkdtempSync, readFileSync, rmSync } from "node:fs";
import { tmpdir } from "node:os";
import { dirname, join, resolve } from "node:path";
import { fileURLToPath } from "node:url";
import { withChromium } from "../../replay/page/chromium.mjs";

const root = resolve(dirname(fileURLToPath(import.meta.url)), "..", "..");

const build = resolve(process.argv[2] || join(root, "build"));
const cbbg = join(build, "apps", "cbbg");
const scratch = mkdtempSync(join(tmpdir(), "cbbg-replay-"));
const failures = [];
const check = (ok, what) => { if (!ok) failures.push(what); };

function run(args) {
  execFileSync(cbbg, args, { stdio: ["ignore", "ignore", "inherit"] });
}

// steps.csv's rows of one trial: [{t, theta_b}].
function logged(directory, arm, seed, trial) {
  const [header, ...rows] = readFileSync(join(directory, "steps.csv"), "utf8").trim().split("\n");
  const at = Object.fromEntries(header.split(",").map((name, i) => [name, i]));
  return rows.map((row) => row.split(","))
    .filter((f) => f[at.arm] === arm && f[at.seed] === String(seed) && f[at.trial] === String(trial))
    .map((f) => ({ t: Number(f[at.t]), theta_b: f[at.theta_b] }));
}

// Pixels that differ between two PNG screenshots, counted in a blank page's canvas.
async function differingPixels(browser, first, second) {
  const page = await browser.newPage();
  const count = await page.evaluate(async ([a, b]) => {
    const load = (data) => new Promise((done) => {
      const image = new Image();
      image.onload = () => done(image);
      image.src = "data:image/png;base64," + data;
    });
    const [one, two] = await Promise.all([load(a), load(b)]);
    const pixels = (image) => {
      const canvas = document.createElement("canvas");
      canvas.width = image.width;
      canvas.height = image.height;
      const g = canvas.getContext("2d");
      g.drawImage(image, 0, 0);
      return g.getImageData(0, 0, image.width, image.height).data;
    };
    const p = pixels(one);
    const q = pixels(two);
    let differ = 0;
    for (let i = 0; i < p.length; i += 4) {
      if (Math.abs(p[i] - q[i]) + Math.abs(p[i + 1] - q[i + 1]) + Math.abs(p[i + 2] - q[i + 2]) > 30) ++differ;
    }
    return differ;
  }, [first.toString("base64"), second.toString("base64")]);
  await page.close();
  return count;
}

// Opens `file` at trial `trial` (from 1), checks it, and returns the two screenshots' difference.
async function checkReplay(browser, file, label, trial, log) {
  const page = await browser.newPage({ viewport: { width: 1280, height: 760 } });
  const problems = [];
  page.on("console", (m) => { if (m.type() === "error" || m.type() === "warning") problems.push(`console ${m.type()}: ${m.text()}`); });
  page.on("pageerror", (e) => problems.push(`page error: ${e.message}`));
  await page.route("**/*", (route) => {
    if (route.request().url().startsWith("file:")) return route.continue();
    problems.push(`network request: ${route.request().url()}`);
    return route.abort();
  });
  await page.goto(`file://${file}#pause&trial=${trial}`);
  await page.waitForFunction(() => document.body.dataset.ready === "true", null, { timeout: 20000 });

  // The pitch shown at a logged tick is the log's, digit for digit.
  const tick = log[Math.floor(log.length * 0.6)];
  await page.evaluate((t) => window.cbbgReplay.seek(t), tick.t);
  const shown = await page.textContent("#readout-pitch");
  const value = await page.getAttribute("#readout-pitch", "data-value");
  check(Number(value) === Number(tick.theta_b), `${label}: the page's pitch at ${tick.t} s is ${value}; the log's is ${tick.theta_b}`);
  check(shown === `${Number(tick.theta_b).toFixed(4)} rad`, `${label}: the page shows '${shown}' at ${tick.t} s; the log has ${tick.theta_b}`);

  const view = page.locator("#scene");
  await page.evaluate(() => window.cbbgReplay.seek(0));
  const early = await view.screenshot();
  await page.evaluate((t) => window.cbbgReplay.seek(t), log[log.length - 1].t);
  const late = await view.screenshot();
  const differ = await differingPixels(browser, early, late);
  check(differ > 2000, `${label}: the scene at 0 s and at the trial's end differ in ${differ} pixels only`);
  check(problems.length === 0, `${label}: ${problems.join("; ")}`);
  await page.close();
  return differ;
}

try {
  run(["run", "--set", "plant.kind=analytic", "--seeds", "1", "--out", join(scratch, "exp1")]);
  run(["run", "--experiment", "exp2", "--set", "plant.kind=analytic", "--seeds", "1",
       "--set", "exp2.trials=25", "--no-figures", "--out", join(scratch, "exp2")]);
  run(["replay", join(scratch, "exp2"), "--trial", "1", "25", "-o", join(scratch, "exp2.html")]);

  const [exp1, exp2] = await withChromium(async (browser) => [
    await checkReplay(browser, join(scratch, "exp1", "figures", "replay_bg_only.html"),
                      "exp1 bg_only", 1, logged(join(scratch, "exp1"), "bg_only", 1, 1)),
    await checkReplay(browser, join(scratch, "exp2.html"), "exp2 trial 25", 2,
                      logged(join(scratch, "exp2"), "cbbg", 1, 25)),
  ]);
  console.log(`replay_in_chromium: exp1 and exp2 replays load offline; their scenes change in ${exp1} and ${exp2} pixels`);
} catch (error) {
  failures.push(String(error.message || error));
} finally {
  rmSync(scratch, { recursive: true, force: true });
}
if (failures.length > 0) {
  for (const failure of failures) console.error(`replay_in_chromium: ${failure}`);
  process.exit(1);
}
