// The replay page: the trials embedded in the page (written by `cbbg replay`), played in the
// 3-D scene with the pitch and the torque plotted beside it.
//
// The page takes, after '#', trial=N (from 1), t=SECONDS and pause, so that a link or a
// test can open it at one moment; window.cbbgReplay offers the same to scripts.
//
// It degrades rather than stop: without WebGL it says so and keeps the plots and readouts;
// a diverged trial's values that are not numbers (null in the page's data) are gaps in the
// plots, "—" in the readouts, and the robot stays at its last known pose.

import { openRobotScene } from "./robot_scene.js";
import { TimePlot } from "./time_plot.js";

const data = JSON.parse(document.getElementById("cbbg-replay-data").textContent);
const $ = (id) => document.getElementById(id);

// The last logged tick at or before `time` (the log's value there is what the page shows).
function tickAt(trial, time) {
  const t = trial.t;
  let low = 0;
  let high = t.length - 1;
  if (time <= t[0]) return 0;
  if (time >= t[high]) return high;
  while (high - low > 1) {
    const middle = (low + high) >> 1;
    if (t[middle] <= time) low = middle; else high = middle;
  }
  return low;
}

const POSE = ["x", "y", "yaw", "theta_b", "phi_l", "phi_r"];

function knownPose(trial, k) {
  return POSE.every((name) => Number.isFinite(trial[name][k]));
}

// The pose at `time`, linear between ticks, for a smooth picture; or, where the log's pose
// there is not all numbers, the last pose before it that is (null when there is none).
function poseAt(trial, time) {
  let k = tickAt(trial, time);
  while (k >= 0 && !knownPose(trial, k)) --k;
  if (k < 0) return null;
  const next = k + 1 < trial.t.length && knownPose(trial, k + 1) ? k + 1 : k;
  const span = trial.t[next] - trial.t[k];
  const w = span > 0 ? Math.min(1, Math.max(0, (time - trial.t[k]) / span)) : 0;
  const lerp = (name) => trial[name][k] + w * (trial[name][next] - trial[name][k]);
  return Object.fromEntries(POSE.map((name) => [name, lerp(name)]));
}

// `value` with `decimals` and its unit, or "—" when it is not a number.
function reading(value, decimals, unit) {
  return Number.isFinite(value) ? `${value.toFixed(decimals)} ${unit}` : "—";
}

// The forward speed at tick k, m/s: the axle's travel along its heading between the ticks
// either side.
function speedAt(trial, k) {
  const before = Math.max(0, k - 1);
  const after = Math.min(trial.t.length - 1, k + 1);
  const span = trial.t[after] - trial.t[before];
  if (!(span > 0)) return 0;
  const heading = trial.yaw[k];
  return ((trial.x[after] - trial.x[before]) * Math.cos(heading) +
          (trial.y[after] - trial.y[before]) * Math.sin(heading)) / span;
}

function describe(trial) {
  const end = trial.t[trial.t.length - 1];
  const how = trial.status === "success" ? "balanced the whole trial"
                                         : `${trial.status} at ${end.toFixed(2)} s`;
  const thinned = trial.stride > 1 ? ` (every ${trial.stride}th tick)` : "";
  return `${trial.arm}, seed ${trial.seed}, trial ${trial.trial}: ${how}${thinned}`;
}

class Replay {
  constructor() {
    this.scene = openRobotScene($("scene"), data.robot); // null without WebGL
    if (!this.scene) {
      $("scene").hidden = true;
      $("no-webgl").hidden = false;
    }
    this.pitch = new TimePlot($("pitch-plot"), { title: "pitch θ_b", unit: "rad",
                                                  limit: data.robot.failure_angle,
                                                  colour: "#1f6fb4" });
    this.torque = new TimePlot($("torque-plot"), { title: "torque a, commanded", unit: "N m",
                                                    limit: data.robot.torque_limit,
                                                    colour: "#d9822b" });
    this.playing = false;
    this.speed = 1;
    this.time = 0;
    this.index = 0;
    for (const plot of [this.pitch, this.torque]) plot.onSeek = (t) => this.seek(t);
    this.wireControls();
  }

  get trial() { return data.trials[this.index]; }
  get end() { return this.trial.t[this.trial.t.length - 1]; }

  wireControls() {
    data.trials.forEach((trial, i) => $("trial").add(new Option(describe(trial), String(i))));
    $("trial").addEventListener("change", (e) => this.select(Number(e.target.value)));
    $("play").addEventListener("click", () => (this.playing ? this.pause() : this.play()));
    $("speed").addEventListener("change", (e) => { this.speed = Number(e.target.value); });
    $("time").addEventListener("input", (e) => this.seek(Number(e.target.value)));
    window.addEventListener("keydown", (e) => {
      if (e.code === "Space" && e.target.tagName !== "SELECT") {
        e.preventDefault();
        this.playing ? this.pause() : this.play();
      }
    });
    window.addEventListener("resize", () => this.layout());
  }

  select(index) {
    this.index = Math.min(Math.max(0, index), data.trials.length - 1);
    $("trial").value = String(this.index);
    const trial = this.trial;
    $("time").max = String(this.end);
    $("time").step = String(trial.t.length > 1 ? trial.t[1] - trial.t[0] : 0.01);
    this.scene?.setPath(trial.x, trial.y);
    this.pitch.setSeries(trial.t, trial.theta_b);
    this.torque.setSeries(trial.t, trial.a);
    this.seek(0);
  }

  play() {
    if (this.time >= this.end) this.seek(0);
    this.playing = true;
    this.last = performance.now();
    $("play").textContent = "❚❚ pause";
  }

  pause() {
    this.playing = false;
    $("play").textContent = "▶ play";
  }

  seek(time) {
    this.time = Math.min(Math.max(0, time), this.end);
    this.update();
  }

  update() {
    const trial = this.trial;
    const pose = poseAt(trial, this.time);
    if (pose) this.scene?.show(pose);
    const k = tickAt(trial, this.time);
    $("time").value = String(this.time);
    $("readout-time").textContent = reading(trial.t[k], 2, "s");
    $("readout-pitch").textContent = reading(trial.theta_b[k], 4, "rad");
    $("readout-pitch").dataset.value = String(trial.theta_b[k] ?? "");
    $("readout-torque").textContent = reading(trial.a[k], 3, "N m");
    $("readout-x").textContent = reading(trial.x[k], 3, "m");
    $("readout-speed").textContent = reading(speedAt(trial, k), 2, "m/s");
    $("readout-yaw").textContent = reading(trial.yaw[k], 3, "rad");
    this.pitch.showCursor(this.time);
    this.torque.showCursor(this.time);
  }

  frame(now) {
    // Asked for first, so that one frame's failure does not end the replay.
    requestAnimationFrame((t) => this.frame(t));
    if (this.playing) {
      this.time += ((now - this.last) / 1000) * this.speed;
      this.last = now;
      if (this.time >= this.end) {
        this.time = this.end;
        this.pause();
      }
      this.update();
    }
    this.scene?.render();
  }

  layout() {
    const view = $("scene");
    this.scene?.resize(view.clientWidth, view.clientHeight);
    this.pitch.drawPicture();
    this.torque.drawPicture();
    if (this.trial) this.update();
  }
}

function fromHash(replay) {
  const options = new URLSearchParams(window.location.hash.slice(1));
  replay.select(options.has("trial") ? Number(options.get("trial")) - 1 : 0);
  if (options.has("t")) replay.seek(Number(options.get("t")));
  if (!options.has("pause")) replay.play();
}

const replay = new Replay();
$("title").textContent = data.title;
fromHash(replay);
replay.layout();
requestAnimationFrame((t) => replay.frame(t));

// For scripts and tests: the same moves as the controls.
window.cbbgReplay = {
  trials: data.trials.map(describe),
  select: (index) => replay.select(index),
  seek: (time) => { replay.seek(time); replay.scene?.render(); },
  play: () => replay.play(),
  pause: () => replay.pause(),
  // shapes: how many of a model file's shapes the scene draws (0: the plant's own drawing).
  state: () => ({ trial: replay.index, time: replay.time, playing: replay.playing,
                  shapes: replay.scene ? replay.scene.shapeCount : 0 }),
};
document.body.dataset.ready = "true";
