#!/usr/bin/python3
"""The table and the figure of a robustness study (scripts/robustness_study.sh).

Usage: /usr/bin/python3 scripts/robustness_report.py DIR

DIR holds one sweep per perturbation (DIR/body_mass_scale/, DIR/com_height_scale/,
DIR/noise_std/, DIR/push_torque/, each with the sweep.csv of `cbbg run --grid`); those
present are read. Writes:
  DIR/robustness.md    per perturbation and value, each arm's balanced evaluation runs out
                       of those run (seeds x evaluation angles), as a Markdown table
  DIR/robustness.png   the balance rate against each perturbation, one line per arm

It replaces its two outputs only in a study robustness_study.sh made.
Exit status: 0 done, 2 a missing or malformed sweep (one line on stderr naming the file),
1 the outputs could not be written. Needs Debian's python3-matplotlib (/usr/bin/python3).
"""

import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import plot_results  # noqa: E402  (the sweep reader, the figure style)
from plot_results import InputError, plt  # noqa: E402

# The file robustness_study.sh leaves in a study it made (the report may replace its own
# outputs there, and only there).
STUDY_MARKER = ".cbbg-robustness-study"

# The perturbations, in the table's order: the sweep's folder, its key, its label.
PERTURBATIONS = [
    ("body_mass_scale", "body mass and inertias x"),
    ("com_height_scale", "centre-of-mass height x"),
    ("noise_std", "pitch and pitch-rate noise std (rad, rad/s)"),
    ("push_torque", "push on each wheel (N m)"),
]


def read_study(directory):
    """[(folder, label, key, rows, config)] of the sweeps present, in PERTURBATIONS' order."""
    if not os.path.isdir(directory):
        raise InputError(directory, "not a folder")
    found = []
    for folder, label in PERTURBATIONS:
        sweep_dir = os.path.join(directory, folder)
        path = os.path.join(sweep_dir, "sweep.csv")
        if not os.path.exists(path):
            continue
        keys, _, rows = plot_results.read_sweep(path)
        key = "evaluation." + folder
        if keys != [key]:
            raise InputError(path, f"sweeps {', '.join(keys)}; expected {key} alone")
        for line, row in enumerate(rows, start=2):
            if not row.get("balance_rate"):
                raise InputError(path, f"line {line}: no balance_rate (an exp1 or exp3 sweep "
                                       "has one)")
        config = plot_results.read_config(os.path.join(sweep_dir, "config.yaml")) or {}
        found.append((folder, label, key, rows, config))
    if not found:
        raise InputError(directory, "holds none of the sweeps " +
                         ", ".join(folder for folder, _ in PERTURBATIONS))
    return found


def arms_of(study):
    return list(dict.fromkeys(row["arm"] for *_, rows, _ in study for row in rows))


def push_label(label, config):
    start, duration = config.get("evaluation.push_start"), config.get("evaluation.push_duration")
    return f"{label[:-1]}, {duration} s from {start} s)" if start and duration else label


def markdown_table(study):
    arms = arms_of(study)
    lines = ["| perturbation | value | " + " | ".join(arms) + " |",
             "|---|---|" + "---|" * len(arms)]
    for folder, label, key, rows, config in study:
        if folder == "push_torque":
            label = push_label(label, config)
        by_value = {}
        for row in rows:
            by_value.setdefault(row[key], {})[row["arm"]] = row
        for value, by_arm in by_value.items():
            cells = [f"{by_arm[a]['balanced']}/{by_arm[a]['evaluated']}" if a in by_arm else ""
                     for a in arms]
            lines.append(f"| {label} | {value} | " + " | ".join(cells) + " |")
    return "\n".join(lines) + "\n"


def figure(study):
    arms = arms_of(study)
    columns = 2 if len(study) > 1 else 1
    grid_rows = (len(study) + columns - 1) // columns
    width, height = plot_results.FIGURE_SIZE
    fig, axes = plt.subplots(grid_rows, columns, figsize=(width * 1.3, height * grid_rows * 0.8),
                             dpi=plot_results.FIGURE_DPI, layout="constrained", squeeze=False)
    for ax, (folder, label, key, rows, config) in zip(axes.flat, study):
        for arm in arms:
            picked = [row for row in rows if row["arm"] == arm]
            ax.plot([float(row[key]) for row in picked],
                    [float(row["balance_rate"]) for row in picked], marker="o", label=arm)
        ax.set_xlabel(push_label(label, config) if folder == "push_torque" else label)
        ax.set_ylabel("balance rate")
        ax.set_ylim(-0.05, 1.05)
        ax.grid(True, alpha=0.3)
        ax.legend(fontsize="small")
    for ax in list(axes.flat)[len(study):]:
        ax.set_visible(False)
    config = study[0][4]
    seeds = study[0][3][0]["seeds"] if study[0][3] else "?"
    fig.suptitle(f"robustness of what was learnt ({config.get('experiment', '?')}, "
                 f"{config.get('plant.kind', '?')} plant, {seeds} seeds)")
    return fig


def write_atomically(path, write):
    """write(temporary path), then the rename: a reader never sees half a file. The temporary
    has cbbg's temporary name, so a report run after a kill removes what the kill left."""
    temporary = plot_results.temporary_name(os.path.dirname(path), os.path.basename(path))
    try:
        write(temporary)
        os.chmod(temporary, 0o644)
        os.replace(temporary, path)
    except BaseException:
        os.unlink(temporary)
        raise


def main(argv):
    if len(argv) != 2:
        print("usage: robustness_report.py DIR", file=sys.stderr)
        return 2
    directory = argv[1]
    try:
        study = read_study(directory)
    except InputError as error:
        print(f"robustness_report.py: {error}", file=sys.stderr)
        return 2
    outputs = [os.path.join(directory, name) for name in ("robustness.md", "robustness.png")]
    made_here = os.path.isfile(os.path.join(directory, STUDY_MARKER))
    for path in outputs:
        if os.path.exists(path) and not made_here:
            print(f"robustness_report.py: {path} exists and this is not a study of "
                  "robustness_study.sh: move it away first", file=sys.stderr)
            return 2
    table = markdown_table(study)
    plot_results.remove_stale_temporaries(directory, ["robustness.md", "robustness.png"])

    def write_table(path):
        with open(path, "w", encoding="utf-8") as file:
            file.write(table)

    try:
        write_atomically(outputs[0], write_table)
        fig = figure(study)
        write_atomically(outputs[1], lambda path: fig.savefig(path, format="png"))
    except OSError as error:
        print(f"robustness_report.py: {directory}: cannot write the report ({error.strerror})",
              file=sys.stderr)
        return 1
    sys.stdout.write(table)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
