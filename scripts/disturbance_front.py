#!/usr/bin/python3
"""The Pareto front of a disturbance search (scripts/disturbance_search.sh).

Usage: /usr/bin/python3 scripts/disturbance_front.py DIR [HOLDING]

DIR is a merged sweep of the transfer protocol trained as exp3 (cbbg.load_sweep reads it: a
row per grid point, arm and seed). Per grid point, for the arm cbbg, it takes the share of
runs balanced under the noise (evaluation.noise_std=0.05) and under the push
(evaluation.push_force=74) and the median trials to the skill (a seed never skilled counts as
max_trials + 1). HOLDING, when given, is a merged sweep of exp2 over the same grid: the share
of a point's seeds holding their ground (none of trials 23-30 fell, their mean forward speed
within 0.1 m/s of standing). It keeps the points no other point beats in all of them (more
noise and push balanced, more seeds holding ground, fewer trials).
Writes DIR/front.md (the front, the paper's point beside it when the grid has it) and
DIR/front.png (push against trials to skill, every point, the front ringed, the teacher's
100 % as a line), replacing them only where it wrote them before (DIR/.cbbg-front marks
them).
Exit status: 0 done, 2 not a sweep it can read (one line), 1 not written.
"""

import csv
import math
import os
import statistics
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import plot_results  # noqa: E402  (the figure style, atomic writes)

NOISE = "evaluation.noise_std=0.05"
PUSH = "evaluation.push_force=74"
NOMINAL = "evaluation.noise_std=0"
MAX_TRIALS = 100
MARKER = ".cbbg-front"  # marks the front's files as this script's
LATE_TRIALS = range(23, 31)  # exp2's trials where a learner holds its ground, or not
HOLDING_SPEED = 0.1  # m/s
# The paper's learner: its view, its units and no training disturbance.
PAPER = {"training.noise_std": 0.0, "training.push_force": 0.0, "training.pitch_spread": 0.0,
         "training.body_mass_spread": 0.0, "training.curriculum_trials": 0.0,
         "normaliser.inputs": "pitch", "normaliser.scale_theta": 0.0581776,
         "normaliser.scale_dtheta": 0.0581776, "rbf.units": "grid", "rbf.width": 0.5}


def grid_keys(table):
    stop = list(table).index("arm")
    return list(table)[1:stop]


def points(table, arm):
    """Per grid point: its settings and the figures of `arm`."""
    keys = grid_keys(table)
    result = []
    for point in sorted(set(table["point"].tolist())):
        rows = (table["point"] == point) & (table["arm"] == arm)
        first = int(np.flatnonzero(rows)[0])
        skill = [MAX_TRIALS + 1 if np.isnan(v) else v for v in table["trials_to_skill"][rows]]

        def rate(condition):
            return (table[f"balanced@{condition}"][rows].sum()
                    / max(table[f"evaluated@{condition}"][rows].sum(), 1))

        result.append({
            "point": point,
            "settings": {key: table[key][first] for key in keys},
            "noise": rate(NOISE), "push": rate(PUSH), "nominal": rate(NOMINAL),
            "skill": statistics.median(skill), "skilled": int(np.sum(~np.isnan(
                table["trials_to_skill"][rows]))), "seeds": int(rows.sum())})
    return result


def holding_by_settings(directory, arm):
    """Per grid point of the exp2 sweep `directory`, keyed by its settings (comparable): the
    share of `arm`'s seeds holding their ground in trials 23-30."""
    with open(os.path.join(directory, "sweep.csv"), newline="") as f:
        rows = [row for row in csv.DictReader(f) if row["arm"] == arm]
    if not rows:
        raise ValueError(f"'{directory}' has no arm {arm}")
    keys = list(rows[0])[1:list(rows[0]).index("arm")]
    shares = {}
    for row in rows:
        late = {}
        with open(os.path.join(directory, "points", row["point"], "trials.csv"), newline="") as f:
            for trial in csv.DictReader(f):
                if trial["arm"] == arm and int(trial["trial"]) in LATE_TRIALS:
                    late.setdefault(trial["seed"], []).append(float(trial["mean_forward_speed"]))
        holds = [all(math.isfinite(v) for v in speeds) and len(speeds) == len(LATE_TRIALS)
                 and abs(statistics.mean(speeds)) < HOLDING_SPEED for speeds in late.values()]
        shares[tuple(comparable(row[k]) for k in keys)] = sum(holds) / max(len(holds), 1)
    return keys, shares


def add_holding(all_points, holding_directory):
    """Each point's share of seeds holding ground, from the exp2 sweep over the same grid."""
    keys, shares = holding_by_settings(holding_directory, "cbbg")
    for p in all_points:
        if list(p["settings"]) != keys:
            raise ValueError(f"'{holding_directory}' sweeps {', '.join(keys)}, not this grid")
        settings = tuple(comparable(p["settings"][k]) for k in keys)
        if settings not in shares:
            raise ValueError(f"'{holding_directory}' lacks the point {describe(p['settings'])}")
        p["holding"] = shares[settings]


def comparable(value):
    """A grid value, a number whether read from text or not: 0.1, 37.0, "pitch"."""
    try:
        return float(value)
    except ValueError:
        return str(value)


def front(all_points):
    """The points no other beats in noise, push, holding ground (where measured) and trials
    to skill together."""
    larger = ["noise", "push"] + (["holding"] if "holding" in all_points[0] else [])

    def beats(a, b):
        better_or_equal = all(a[k] >= b[k] for k in larger) and a["skill"] <= b["skill"]
        return better_or_equal and (any(a[k] > b[k] for k in larger) or a["skill"] < b["skill"])
    return [p for p in all_points if not any(beats(q, p) for q in all_points)]


def is_paper(point):
    """Whether every swept key is at the paper's learner's value."""
    return all(k in PAPER and v == PAPER[k] for k, v in point["settings"].items())


def describe(settings):
    return ", ".join(f"{k.split('.', 1)[1]} {v}" for k, v in settings.items())


def report(all_points, best):
    lines = ["# The disturbance search's front", "",
             f"{len(all_points)} grid points x {all_points[0]['seeds']} seeds; per point, the "
             "runs balanced (seeds x 5 angles) under the noise and the push, median trials to "
             f"skill (never: {MAX_TRIALS + 1}).", "",
             "| point | settings | noise 0.05 | push 74 N | nominal | holding ground in exp2 "
             "| trials to skill | skilled |",
             "|---|---|---|---|---|---|---|---|"]
    paper = [p for p in all_points if is_paper(p)]
    if not paper:
        lines[2:2] = ["The paper's learner is not a point of this grid.", ""]
    for p in paper + sorted(best, key=lambda p: (-p["push"], -p["noise"], p["skill"])):
        name = f"{p['point']:03d}" + (" (the paper's)" if is_paper(p) else "")
        holding = f"{p['holding']:.0%}" if "holding" in p else "not measured"
        lines.append(f"| {name} | {describe(p['settings'])} | {p['noise']:.0%} | "
                     f"{p['push']:.0%} | {p['nominal']:.0%} | {holding} | {p['skill']:g} | "
                     f"{p['skilled']}/{p['seeds']} |")
    return "\n".join(lines) + "\n"


def figure(all_points, best):
    fig, ax = plot_results.new_figure()
    shades = ax.scatter([p["skill"] for p in all_points], [p["push"] for p in all_points],
                        c=[p["noise"] for p in all_points], cmap="viridis", vmin=0, vmax=1, s=18)
    fig.colorbar(shades, ax=ax, label="share balanced under 0.05 rad noise")
    ax.scatter([p["skill"] for p in best], [p["push"] for p in best], facecolors="none",
               edgecolors="red", s=70, label="the front")
    for p in all_points:
        if is_paper(p):
            ax.scatter([p["skill"]], [p["push"]], marker="*", s=160, color="black",
                       label="the paper's learner")
    ax.axhline(1.0, color="grey", linestyle="--", label="the teacher (PD): 100 %")
    ax.set_xscale("log")
    ax.set_xlabel("median trials to skill (log)")
    ax.set_ylabel("share balanced under the 74 N push")
    ax.set_ylim(-0.03, 1.15)
    ax.legend(loc="upper right", fontsize="small")
    return fig


def main(argv):
    if len(argv) not in (2, 3):
        print("usage: disturbance_front.py DIR [HOLDING]", file=sys.stderr)
        return 2
    directory = argv[1]
    import cbbg
    try:
        table = cbbg.load_sweep(directory)
        all_points = points(table, "cbbg")
        if len(argv) == 3:
            add_holding(all_points, argv[2])
    except (ValueError, KeyError, OSError) as error:
        print(f"disturbance_front.py: {directory}: {error}", file=sys.stderr)
        return 2
    best = front(all_points)
    text = report(all_points, best)
    # front.md and front.png are replaced only where this script wrote them (its marker).
    marker = os.path.join(directory, MARKER)
    for name in ("front.md", "front.png"):
        if os.path.exists(os.path.join(directory, name)) and not os.path.isfile(marker):
            print(f"disturbance_front.py: {os.path.join(directory, name)} exists and is not "
                  "this script's: move it away first", file=sys.stderr)
            return 2

    def write_text(path):
        with open(path, "w", encoding="utf-8") as f:
            f.write(text)

    try:
        with open(marker, "a", encoding="utf-8"):
            pass
        plot_results.write_atomically(os.path.join(directory, "front.md"), write_text)
        fig = figure(all_points, best)
        plot_results.write_atomically(os.path.join(directory, "front.png"),
                                      lambda path: fig.savefig(path, format="png"))
    except OSError as error:
        print(f"disturbance_front.py: {directory}: cannot write ({error.strerror})",
              file=sys.stderr)
        return 1
    sys.stdout.write(text)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
