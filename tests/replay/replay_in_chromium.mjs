// cbbg replay's page in a real headless Chromium (Debian's), offline: the replays of an exp1
// and an exp2 run load without console errors or network requests; two moments of a trial
// look different; the pitch the page shows at a logged time is the log's. In a Chromium
// without WebGL the page says so in one line and keeps its plots, readouts and trial list.
// A diverged trial's page (null torques from a tick on, null pitches for a while) shows
// "—" and gaps there and plays on past them. With --mujoco, a robot from its model file (the
// reaction-wheel example) is drawn from the model's own shapes, moving as its log says.
//   node tests/replay/replay_in_chromium.mjs BUILD_DIR [--mujoco]
// It starts each browser itself and stops it by its pid, whatever happens (withChromium).
import { execFileSync } from "node:child_process";
import { copyFileSync, mkdirSync, mkdtempSync, readFileSync, rmSync, writeFileSync } from "node:fs";
import { tmpdir } from "node:os";
import { dirname, join, resolve } from "node:path";
import { fileURLToPath } from "node:url";
import { withChromium, WITHOUT_WEBGL } from "../../replay/page/chromium.mjs";

const root = resolve(dirname(fileURLToPath(import.meta.url)), "..", "..");

const build = resolve(process.argv[2] || join(root, "build"));
const withMujoco = process.argv[3] === "--mujoco";
const cbbg = join(build, "apps", "cbbg");
const scratch = mkdtempSync(join(tmpdir(), "cbbg-replay-"));
const failures = [];
const check = (ok, what) => { if (!ok) failures.push(what); };

function run(args) {
  execFileSync(cbbg, args, { stdio: ["ignore", "ignore", "inherit"] });
}

// steps.csv's header (column name to index) and rows, split.
function steps(directory) {
  const [header, ...rows] = readFileSync(join(directory, "steps.csv"), "utf8").trim().split("\n");
  const at = Object.fromEntries(header.split(",").map((name, i) => [name, i]));
  return { header, at, rows: rows.map((row) => row.split(",")) };
}

function ofTrial(at, fields, arm, seed, trial) {
  return fields[at.arm] === arm && fields[at.seed] === String(seed) && fields[at.trial] === String(trial);
}

// steps.csv's rows of one trial: [{t, theta_b}].
function logged(directory, arm, seed, trial) {
  const { at, rows } = steps(directory);
  return rows.filter((f) => ofTrial(at, f, arm, seed, trial))
    .map((f) => ({ t: Number(f[at.t]), theta_b: f[at.theta_b] }));
}

// A copy of the results directory `run` in which trial `trial` of `arm`, seed 1, diverges:
// its torque is nan or inf from time `from` on, as a diverged controller logs it.
function divergedRun(run, copy, arm, trial, from) {
  mkdirSync(copy);
  for (const file of ["config.yaml", "trials.csv"]) copyFileSync(join(run, file), join(copy, file));
  const { header, at, rows } = steps(run);
  const diverged = rows.map((f, i) => {
    if (!ofTrial(at, f, arm, 1, trial) || Number(f[at.t]) < from) return f;
    return f.map((field, c) => (c === at.a ? (i % 2 ? "nan" : "inf") : field));
  });
  writeFileSync(join(copy, "steps.csv"), [header, ...diverged.map((f) => f.join(","))].join("\n") + "\n");
}

// Makes the first trial's pitch null over [from, to) in the page `file`'s data. cbbg ends a
// trial at its first pose that is not a number, but the page must not count on that.
function nullPitch(file, from, to) {
  const html = readFileSync(file, "utf8");
  const opening = '<script id="cbbg-replay-data" type="application/json">';
  const start = html.indexOf(opening) + opening.length;
  const end = html.indexOf("</script>", start);
  const data = JSON.parse(html.slice(start, end));
  const trial = data.trials[0];
  trial.theta_b = trial.theta_b.map((v, i) => (trial.t[i] >= from && trial.t[i] < to ? null : v));
  writeFileSync(file, html.slice(0, start) + JSON.stringify(data) + html.slice(end));
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

// Pixels of canvas `id` within 40 of `colour` (#rrggbb) in its columns from `from` (a
// fraction of its width) on: how much of a plot's curve is drawn there.
function curvePixels(page, id, colour, from = 0) {
  return page.evaluate(([id, colour, from]) => {
    const plot = document.getElementById(id);
    // Read from a copy: reading the plot's own canvas again and again makes Chromium warn.
    const copy = document.createElement("canvas");
    copy.width = plot.width;
    copy.height = plot.height;
    const g = copy.getContext("2d");
    g.drawImage(plot, 0, 0);
    const want = [1, 3, 5].map((i) => parseInt(colour.slice(i, i + 2), 16));
    const left = Math.floor(from * copy.width);
    const pixels = g.getImageData(left, 0, copy.width - left, copy.height).data;
    let count = 0;
    for (let i = 0; i < pixels.length; i += 4) {
      const distance = want.reduce((sum, c, j) => sum + Math.abs(pixels[i + j] - c), 0);
      if (pixels[i + 3] > 200 && distance < 40) ++count;
    }
    return count;
  }, [id, colour, from]);
}

const PITCH_COLOUR = "#1f6fb4";
const TORQUE_COLOUR = "#d9822b";

// `file` opened at `moment`, once it is ready, with what goes wrong on it gathered in problems.
async function openPage(browser, file, moment) {
  const page = await browser.newPage({ viewport: { width: 1280, height: 760 } });
  const problems = [];
  page.on("console", (m) => { if (m.type() === "error" || m.type() === "warning") problems.push(`console ${m.type()}: ${m.text()}`); });
  page.on("pageerror", (e) => problems.push(`page error: ${e.message}`));
  await page.route("**/*", (route) => {
    if (route.request().url().startsWith("file:")) return route.continue();
    problems.push(`network request: ${route.request().url()}`);
    return route.abort();
  });
  await page.goto(`file://${file}#${moment}`);
  await page.waitForFunction(() => document.body.dataset.ready === "true", null, { timeout: 20000 })
    .catch(() => { throw new Error(`the page never got ready: ${problems.join("; ")}`); });
  return { page, problems };
}

const seek = (page, time) => page.evaluate((t) => window.cbbgReplay.seek(t), time);

// The pitch shown at a logged tick is the log's, digit for digit.
async function checkLoggedPitch(page, label, log) {
  const tick = log[Math.floor(log.length * 0.6)];
  await seek(page, tick.t);
  const shown = await page.textContent("#readout-pitch");
  const value = await page.getAttribute("#readout-pitch", "data-value");
  check(Number(value) === Number(tick.theta_b), `${label}: the page's pitch at ${tick.t} s is ${value}; the log's is ${tick.theta_b}`);
  check(shown === `${Number(tick.theta_b).toFixed(4)} rad`, `${label}: the page shows '${shown}' at ${tick.t} s; the log has ${tick.theta_b}`);
}

// Plays from `from` s at 8× and says whether the clock reached `to` s within 30 s.
async function playsTo(page, from, to) {
  await seek(page, from);
  await page.selectOption("#speed", "8");
  await page.evaluate(() => window.cbbgReplay.play());
  return page.waitForFunction((t) => window.cbbgReplay.state().time >= t, to, { timeout: 30000 })
    .then(() => true, () => false);
}

// Opens `file` at trial `trial` (from 1), checks it (a model's drawing: that it draws `shapes`
// of the model's shapes), and returns the two screenshots' difference.
async function checkReplay(browser, file, label, trial, log, shapes = 0) {
  const { page, problems } = await openPage(browser, file, `pause&trial=${trial}`);
  check(await page.isHidden("#no-webgl"), `${label}: the page says it has no WebGL in a browser that has it`);
  const drawn = (await page.evaluate(() => window.cbbgReplay.state())).shapes;
  check(drawn === shapes, `${label}: the scene draws ${drawn} of a model's shapes; ${shapes} expected`);
  await checkLoggedPitch(page, label, log);

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

// Opens `file` (at trial `trial`, from 1) in a browser without WebGL: one line says the 3-D
// view needs it; the plots, the readouts, the trial list and the clock work.
async function checkWithoutWebgl(browser, file, label, trial, log) {
  const { page, problems } = await openPage(browser, file, `pause&trial=${trial}`);
  const offered = await page.evaluate(() => ["webgl2", "webgl"].filter((kind) => document.createElement("canvas").getContext(kind)));
  check(offered.length === 0, `${label}: the browser meant to have no WebGL offers ${offered.join(", ")}`);
  const notice = (await page.isVisible("#no-webgl")) ? await page.textContent("#no-webgl") : "";
  check(/3-D view needs WebGL/.test(notice), `${label}: without WebGL the page shows '${notice}', not that the 3-D view needs it`);
  check(await page.isHidden("#scene"), `${label}: without WebGL the page still shows the empty 3-D view`);
  const pitch = await curvePixels(page, "pitch-plot", PITCH_COLOUR);
  const torque = await curvePixels(page, "torque-plot", TORQUE_COLOUR);
  check(pitch > 200 && torque > 200, `${label}: without WebGL the curves have ${pitch} and ${torque} pixels`);
  const trials = await page.locator("#trial option").count();
  check(trials >= trial, `${label}: without WebGL the trial list has ${trials} entries`);
  await checkLoggedPitch(page, label, log);
  check(await playsTo(page, 0, log[Math.floor(log.length / 4)].t), `${label}: without WebGL the replay does not play`);
  check(problems.length === 0, `${label}, without WebGL: ${problems.join("; ")}`);
  await page.close();
}

// Opens the page of a trial whose torque is null from `diverged` s on and whose pitch is null
// over [hole, holeEnd) s: "—" and gaps there, the robot held at its last known pose, and the
// replay plays through to the end.
async function checkDiverged(browser, file, label, log, diverged, hole, holeEnd) {
  const { page, problems } = await openPage(browser, file, "pause&trial=1");
  const before = log.filter((tick) => tick.t < hole).at(-1).t;
  const within = log.find((tick) => tick.t > hole && tick.t < holeEnd).t;
  await seek(page, (diverged + hole) / 2);
  const torque = await page.textContent("#readout-torque");
  const pitch = await page.textContent("#readout-pitch");
  check(torque === "—" && pitch !== "—", `${label}: after the torque diverges the page shows torque '${torque}' and pitch '${pitch}'`);
  await seek(page, before);
  const held = await page.locator("#scene").screenshot();
  await seek(page, within);
  const shown = await page.textContent("#readout-pitch");
  check(shown === "—", `${label}: where the pitch is null the page shows '${shown}'`);
  const moved = await differingPixels(browser, held, await page.locator("#scene").screenshot());
  check(moved < 50, `${label}: where the pitch is null the view differs in ${moved} pixels from the last known pose`);
  // The plot's right fifth is well after the torque diverged, half-way through.
  const gap = await curvePixels(page, "torque-plot", TORQUE_COLOUR, 0.8);
  check(gap === 0, `${label}: the torque curve has ${gap} pixels after it diverged`);
  check(await curvePixels(page, "torque-plot", TORQUE_COLOUR) > 100, `${label}: the torque curve before it diverged is missing`);
  const end = log.at(-1).t;
  check(await playsTo(page, 0.9 * diverged, end), `${label}: the replay stops before the trial's end, ${end} s, at ${(await page.evaluate(() => window.cbbgReplay.state())).time} s`);
  check(problems.length === 0, `${label}: ${problems.join("; ")}`);
  await page.close();
}

// Runs one check, so that a check that throws is reported and the others still run.
async function attempt(label, checking) {
  try {
    return await checking();
  } catch (error) {
    failures.push(`${label}: ${String(error.message || error).split("\n")[0]}`);
  }
}

try {
  run(["run", "--set", "plant.kind=analytic", "--seeds", "1", "--out", join(scratch, "exp1")]);
  run(["run", "--experiment", "exp2", "--set", "plant.kind=analytic", "--seeds", "1",
       "--set", "exp2.trials=25", "--no-figures", "--out", join(scratch, "exp2")]);
  run(["replay", join(scratch, "exp2"), "--trial", "1", "25", "-o", join(scratch, "exp2.html")]);
  const exp1Page = join(scratch, "exp1", "figures", "replay_bg_only.html");
  const exp2Page = join(scratch, "exp2.html");
  const exp1Log = logged(join(scratch, "exp1"), "bg_only", 1, 1);
  const exp2Log = logged(join(scratch, "exp2"), "cbbg", 1, 25);

  // The diverged trial: exp2's 25th, long enough to play over many frames, its torque null
  // over its second half and its pitch over a tenth.
  const span = exp2Log.at(-1).t;
  const [diverged, hole, holeEnd] = [0.5 * span, 0.6 * span, 0.7 * span];
  divergedRun(join(scratch, "exp2"), join(scratch, "diverged"), "cbbg", 25, diverged);
  const divergedPage = join(scratch, "diverged.html");
  run(["replay", join(scratch, "diverged"), "--arm", "cbbg", "--trial", "25", "-o", divergedPage]);
  nullPitch(divergedPage, hole, holeEnd);

  const [exp1, exp2] = await withChromium(async (browser) => [
    await attempt("exp1 bg_only", () => checkReplay(browser, exp1Page, "exp1 bg_only", 1, exp1Log)),
    await attempt("exp2 trial 25", () => checkReplay(browser, exp2Page, "exp2 trial 25", 2, exp2Log)),
    await attempt("diverged trial", () => checkDiverged(browser, divergedPage, "diverged trial",
                                                        exp2Log, diverged, hole, holeEnd)),
  ]);
  if (withMujoco) {
    // The reaction wheel's rod (a capsule) and flywheel (a cylinder); its floor is not drawn.
    const examples = join(root, "examples", "mujoco");
    run(["run", "--config", join(examples, "reaction_wheel.yaml"), "--seeds", "1", "--no-figures",
         "--out", join(scratch, "reaction_wheel")]);
    const modelPage = join(scratch, "reaction_wheel.html");
    run(["replay", join(scratch, "reaction_wheel"), "--arm", "bg_only", "-o", modelPage]);
    const modelLog = logged(join(scratch, "reaction_wheel"), "bg_only", 1, 1);
    await withChromium((browser) => attempt("reaction wheel", () =>
      checkReplay(browser, modelPage, "reaction wheel bg_only", 1, modelLog, 2)));
  }
  await withChromium(async (browser) => {
    await attempt("exp1 bg_only, without WebGL",
                  () => checkWithoutWebgl(browser, exp1Page, "exp1 bg_only", 1, exp1Log));
    await attempt("exp2 trial 25, without WebGL",
                  () => checkWithoutWebgl(browser, exp2Page, "exp2 trial 25", 2, exp2Log));
  }, WITHOUT_WEBGL);
  if (failures.length === 0) {
    console.log(`replay_in_chromium: exp1 and exp2 replays load offline; their scenes change in ${exp1} and ${exp2} pixels; ` +
                "without WebGL they keep their plots; a diverged trial plays to its end");
  }
} catch (error) {
  failures.push(String(error.message || error));
} finally {
  rmSync(scratch, { recursive: true, force: true });
}
if (failures.length > 0) {
  for (const failure of failures) console.error(`replay_in_chromium: ${failure}`);
  process.exit(1);
}
