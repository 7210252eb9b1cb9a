// A signal against time on a 2-D canvas, with limit lines and a cursor at the replay's time.
// The curve is drawn once per trial; a cursor move redraws from that picture. A value that
// is not a number (a diverged trial's null) is a gap in the curve.

const MARGIN = { left: 52, right: 10, top: 22, bottom: 26 };

// About `count` round values from low to high, and the decimals their step needs.
function niceTicks(low, high, count) {
  const span = high - low || 1;
  const raw = span / count;
  const power = Math.pow(10, Math.floor(Math.log10(raw)));
  const step = [1, 2, 5, 10].map((m) => m * power).find((s) => s >= raw);
  const values = [];
  for (let k = Math.ceil(low / step); k * step <= high + 1e-12; ++k) values.push(k * step);
  return { values, decimals: Math.max(0, -Math.floor(Math.log10(step) + 1e-9)) };
}

export class TimePlot {
  // options: {title, unit, limit (drawn at +-limit, dashed), colour}
  constructor(canvas, options) {
    this.canvas = canvas;
    this.options = options;
    this.picture = null; // a canvas
    this.onSeek = null;
    canvas.addEventListener("click", (event) => {
      if (!this.onSeek || !this.t) return;
      const box = canvas.getBoundingClientRect();
      this.onSeek(this.timeAt(event.clientX - box.left));
    });
  }

  setSeries(t, values) {
    this.t = t;
    this.values = values;
    const finite = values.filter(Number.isFinite);
    const limit = this.options.limit || 0;
    this.low = Math.min(-limit, ...finite);
    this.high = Math.max(limit, ...finite);
    const pad = 0.05 * (this.high - this.low || 1);
    this.low -= pad;
    this.high += pad;
    this.drawPicture();
  }

  width() { return this.canvas.clientWidth; }
  height() { return this.canvas.clientHeight; }
  xOf(time) {
    const end = this.t[this.t.length - 1] || 1;
    return MARGIN.left + (time / end) * (this.width() - MARGIN.left - MARGIN.right);
  }
  timeAt(x) {
    const end = this.t[this.t.length - 1] || 1;
    const fraction = (x - MARGIN.left) / (this.width() - MARGIN.left - MARGIN.right);
    return Math.min(end, Math.max(0, fraction * end));
  }
  yOf(value) {
    const inner = this.height() - MARGIN.top - MARGIN.bottom;
    return MARGIN.top + (1 - (value - this.low) / (this.high - this.low)) * inner;
  }

  drawAxes(g) {
    g.strokeStyle = "#c4cad1";
    g.fillStyle = "#495057";
    g.font = "11px sans-serif";
    g.lineWidth = 1;
    const vertical = niceTicks(this.low, this.high, 4);
    for (const v of vertical.values) {
      const y = this.yOf(v);
      g.beginPath(); g.moveTo(MARGIN.left, y); g.lineTo(this.width() - MARGIN.right, y); g.stroke();
      g.fillText(v.toFixed(vertical.decimals), 4, y + 4);
    }
    const end = this.t[this.t.length - 1] || 1;
    const horizontal = niceTicks(0, end, 8);
    for (const v of horizontal.values) {
      g.fillText(`${v.toFixed(horizontal.decimals)} s`, this.xOf(v) - 8, this.height() - 8);
    }
    g.font = "bold 12px sans-serif";
    g.fillText(`${this.options.title} (${this.options.unit})`, MARGIN.left, 14);
  }

  drawLimits(g) {
    const limit = this.options.limit;
    if (!limit) return;
    g.save();
    g.setLineDash([5, 4]);
    g.strokeStyle = "#d94f4f";
    for (const v of [limit, -limit]) {
      const y = this.yOf(v);
      g.beginPath(); g.moveTo(MARGIN.left, y); g.lineTo(this.width() - MARGIN.right, y); g.stroke();
    }
    g.restore();
  }

  // The series as a polyline, broken where a value is not a number (null in a diverged
  // log), so that a gap shows as a gap.
  drawCurve(g) {
    g.strokeStyle = this.options.colour;
    g.lineWidth = 1.5;
    g.beginPath();
    let joined = false;
    this.values.forEach((v, i) => {
      if (!Number.isFinite(v)) {
        joined = false;
        return;
      }
      const x = this.xOf(this.t[i]);
      const y = this.yOf(v);
      if (joined) g.lineTo(x, y); else g.moveTo(x, y);
      joined = true;
    });
    g.stroke();
  }

  drawPicture() {
    if (!this.t) return;
    const ratio = window.devicePixelRatio || 1;
    this.canvas.width = Math.round(this.width() * ratio);
    this.canvas.height = Math.round(this.height() * ratio);
    const g = this.canvas.getContext("2d");
    g.setTransform(ratio, 0, 0, ratio, 0, 0);
    g.clearRect(0, 0, this.width(), this.height());
    this.drawAxes(g);
    this.drawLimits(g);
    this.drawCurve(g);
    // Kept as a picture: a cursor move copies it back and draws the cursor over it.
    this.picture = this.picture || document.createElement("canvas");
    this.picture.width = this.canvas.width;
    this.picture.height = this.canvas.height;
    this.picture.getContext("2d").drawImage(this.canvas, 0, 0);
  }

  showCursor(time) {
    if (!this.picture) return;
    const g = this.canvas.getContext("2d");
    g.save();
    g.setTransform(1, 0, 0, 1, 0, 0);
    g.clearRect(0, 0, this.canvas.width, this.canvas.height);
    g.drawImage(this.picture, 0, 0);
    g.restore();
    const x = this.xOf(time);
    g.strokeStyle = "#212529";
    g.lineWidth = 1;
    g.beginPath(); g.moveTo(x, MARGIN.top); g.lineTo(x, this.height() - MARGIN.bottom); g.stroke();
  }
}
