#!/usr/bin/python3
"""The table and the figure of a robustness study (scripts/robustness_study.sh).

Usage: /usr/bin/python3 scripts/robustness_report.py DIR

DIR/transfer/ is the results directory of a `cbbg run --experiment transfer` whose
transfer.conditions each set one evaluation key; its figures.csv holds, per arm and seed and
condition, the evaluation runs that balanced (balanced@CONDITION) and those run
(evaluated@CONDITION). Writes:
  DIR/robustness.md    per perturbation and value, each arm's balanced evaluation runs out
                       of those run (seeds x evaluation angles), as a Markdown table
  DIR/robustness.png   the balance rate against each perturbation, one line per arm

It replaces its two outputs only in a study robustness_study.sh made.
Exit status: 0 done, 2 a missing or malformed input (one line on stderr naming the file),
1 the outputs could not be written. Needs Debian's python3-matplotlib (/usr/bin/python3).
"""

import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import plot_results  # noqa: E402  (the figures.csv reader, the figure style)
from plot_results import InputError, plt  # noqa: E402

# The file robustness_study.sh leaves in a study it made (the report may replace its own
# outputs there, and only there).
STUDY_MARKER = ".cbbg-robustness-study"

# The labels of the perturbations the study makes, by key; another key is its own label.
LABELS = {
    "evaluation.body_mass_scale": "body mass and inertias x",
    "evaluation.com_height_scale": "centre-of-mass height x",
    "evaluation.noise_std": "pitch and pitch-rate noise std (rad, rad/s)",
    "evaluation.push_force": "push at the centre of mass, from outside (N)",
    "evaluation.push_pitch_torque": "torque on the body, from outside (N m)",
    "evaluation.push_torque": "push through the motors, on each wheel (N m)",
}
PUSH_KEYS = {"evaluation.push_force", "evaluation.push_pitch_torque", "evaluation.push_torque"}


def read_study(directory):
    """(perturbations, arms, config): perturbations [(key, label, [(value, {arm: (balanced,
    evaluated)})])] in the order of transfer.conditions."""
    if not os.path.isdir(directory):
        raise InputError(directory, "not a folder")
    run = os.path.join(directory, "transfer")
    path = os.path.join(run, "figures.csv")
    names, rows = plot_results.read_figures(path)
    conditions = [name[len("balanced@"):] for name in names if name.startswith("balanced@")]
    if not conditions:
        raise InputError(path, "has no balanced@ column (a transfer run has one per condition)")
    for condition in conditions:
        if "evaluated@" + condition not in names:
            raise InputError(path, f"has no evaluated@{condition} column")
    arms = list(dict.fromkeys(row["arm"] for row in rows))
    perturbations = []
    for condition in conditions:
        key, _, value = condition.partition("=")
        if ";" in condition or not perturbations or perturbations[-1][0] != key:
            perturbations.append((key, LABELS.get(key, key), []))
        counts = {}
        for arm in arms:
            picked = [row for row in rows if row["arm"] == arm]
            counts[arm] = (sum(int(row["balanced@" + condition]) for row in picked),
                           sum(int(row["evaluated@" + condition]) for row in picked))
        perturbations[-1][2].append((value, counts))
    config = plot_results.read_config(os.path.join(run, "config.yaml")) or {}
    return perturbations, arms, config


def push_label(label, config):
    start, duration = config.get("evaluation.push_start"), config.get("evaluation.push_duration")
    return f"{label[:-1]}, {duration} s from {start} s)" if start and duration else label


def label_of(key, label, config):
    return push_label(label, config) if key in PUSH_KEYS else label


def markdown_table(study):
    perturbations, arms, config = study
    lines = ["| perturbation | value | " + " | ".join(arms) + " |",
             "|---|---|" + "---|" * len(arms)]
    for key, label, values in perturbations:
        for value, counts in values:
            cells = [f"{counts[arm][0]}/{counts[arm][1]}" for arm in arms]
            lines.append(f"| {label_of(key, label, config)} | {value} | " + " | ".join(cells) +
                         " |")
    return "\n".join(lines) + "\n"


def figure(study):
    perturbations, arms, config = study
    columns = 2 if len(perturbations) > 1 else 1
    grid_rows = (len(perturbations) + columns - 1) // columns
    width, height = plot_results.FIGURE_SIZE
    fig, axes = plt.subplots(grid_rows, columns, figsize=(width * 1.3, height * grid_rows * 0.8),
                             dpi=plot_results.FIGURE_DPI, layout="constrained", squeeze=False)
    for ax, (key, label, values) in zip(axes.flat, perturbations):
        positions, ticks = plot_results.axis_positions([value for value, _ in values])
        for arm in arms:
            rates = [counts[arm][0] / counts[arm][1] if counts[arm][1] else float("nan")
                     for _, counts in values]
            ax.plot(positions, rates, marker="o", label=arm)
        if ticks is not None:
            ax.set_xticks(positions, ticks)
        ax.set_xlabel(label_of(key, label, config))
        ax.set_ylabel("balance rate")
        ax.set_ylim(-0.05, 1.05)
        ax.grid(True, alpha=0.3)
        ax.legend(fontsize="small")
    for ax in list(axes.flat)[len(perturbations):]:
        ax.set_visible(False)
    fig.suptitle(f"robustness of what was learnt (trained as {config.get('transfer.training', '?')}"
                 f", {config.get('plant.kind', '?')} plant, {config.get('seeds', '?')} seeds)")
    return fig


def main(argv):
    return plot_results.study_report_main(argv, "robustness_report.py", STUDY_MARKER, "robustness_study.sh", "robustness",
                                          read_study, markdown_table, figure)


if __name__ == "__main__":
    sys.exit(main(sys.argv))
