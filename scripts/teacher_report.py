#!/usr/bin/python3
"""The table of a teacher study (scripts/teacher_study.sh): can the learner outgrow its teacher?

Usage: /usr/bin/python3 scripts/teacher_report.py DIR

DIR/VARIANT/transfer is a `cbbg run --experiment transfer` trained as exp3 (figures.csv: per
arm and seed, skilled, trials_to_skill and balanced@/evaluated@ per condition) and
DIR/VARIANT/exp2 an exp2 run (trials.csv: mean_forward_speed and pitch_rms per trial), for
the variant `paper` and the others of the study. Writes DIR/teacher.md and DIR/teacher.png
(per variant and arm: trials to skill, the share balanced under the noise and under the push,
with the teacher's, and the share of seeds holding their ground in exp2). teacher.md holds:
  - trials to skill per variant and arm, and bg_only's extra trials over cbbg's;
  - balanced runs under each condition (the PD supervisor alone from the paper's run);
  - exp2's trials 23-30 (exp2 trains cbbg): mean forward speed and pitch RMS of the trials
    that balanced, and those that fell;
  - the moonshot: >= 90 % balanced under the noise and under the push the teacher survives,
    and >= 90 % of the seeds holding their ground in exp2's trials 23-30 (none fell, and
    their mean speed is within 0.1 m/s of standing);
each variant paired with the paper's learner seed by seed: the mean difference with a 95 %
bootstrap interval (10000 resamples of the seeds, seeded) and the exact two-sided sign test.

It replaces its outputs only in a study teacher_study.sh made. Needs Debian's
python3-matplotlib (/usr/bin/python3).
Exit status: 0 done, 2 a missing or malformed input (one line on stderr naming the file),
1 the table could not be written.
"""

import csv
import math
import os
import statistics
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import plot_results  # noqa: E402  (the figures.csv reader, the figure style, publishing)
from plot_results import InputError, plt  # noqa: E402
from study_stats import paired, paired_text  # noqa: E402  (seed by seed, shared)

STUDY_MARKER = ".cbbg-teacher-study"
ARMS = ("cbbg", "bg_only")
LATE_TRIALS = range(23, 31)  # exp2's trials 23-30: the learner alone (omega = 1)
MOONSHOT_RATE = 0.9          # of the runs: 45/50 in the 10 seeds x 5 angles
MOONSHOT_SPEED = 0.1         # m/s


def read_transfer(directory):
    """(conditions, {arm: rows}) of DIR/transfer/figures.csv; a seed that never came to the
    skill (no trials_to_skill) counts as max_trials + 1, as summary.json's paired
    comparison counts it."""
    path = os.path.join(directory, "transfer", "figures.csv")
    names, rows = plot_results.read_figures(path)
    for needed in ("skilled", "trials_to_skill"):
        if needed not in names:
            raise InputError(path, f"has no {needed} column (transfer trained as exp3 has one)")
    summary_path = os.path.join(directory, "transfer", "summary.json")
    max_trials = plot_results.read_summary(summary_path).get("max_trials")
    if not isinstance(max_trials, int):
        raise InputError(summary_path, 'has no "max_trials"')
    for row in rows:
        if row["trials_to_skill"] is None:
            row["trials_to_skill"] = max_trials + 1
    conditions = [name[len("balanced@"):] for name in names if name.startswith("balanced@")]
    by_arm = {}
    for row in rows:
        by_arm.setdefault(row["arm"], []).append(row)
    return conditions, by_arm


def read_late_exp2(directory):
    """{arm: {seed: [(mean forward speed, pitch RMS) of each of trials 23-30]}} from exp2's
    trials.csv; a trial that fell before the settle time has NaN for both."""
    path = os.path.join(directory, "exp2", "trials.csv")
    try:
        file = open(path, newline="")
    except OSError as error:
        raise InputError(path, f"cannot be read ({error.strerror})")
    late = {}
    with file:
        reader = csv.DictReader(file)
        missing = {"arm", "seed", "trial", "mean_forward_speed", "pitch_rms"} - set(
            reader.fieldnames or [])
        if missing:
            raise InputError(path, "has no " + ", ".join(sorted(missing)) + " column")
        for line, row in enumerate(reader, start=2):
            trial = plot_results.parse_integer(path, line, "trial", row["trial"], 1)
            if trial not in LATE_TRIALS:
                continue
            speed = plot_results.parse_number(path, line, "mean_forward_speed",
                                              row["mean_forward_speed"])
            rms = plot_results.parse_number(path, line, "pitch_rms", row["pitch_rms"])
            late.setdefault(row["arm"], {}).setdefault(row["seed"], []).append((speed, rms))
    return late


class LateSeed:
    """One seed's exp2 trials 23-30: those that balanced past the settle time, their mean
    speed and pitch RMS (NaN when none did), and whether it held its ground."""

    def __init__(self, trials):
        kept = [(v, r) for v, r in trials if math.isfinite(v) and math.isfinite(r)]
        self.fell = len(trials) - len(kept)
        self.speed = sum(v for v, _ in kept) / len(kept) if kept else math.nan
        self.rms = sum(r for _, r in kept) / len(kept) if kept else math.nan
        self.holds = self.fell == 0 and abs(self.speed) < MOONSHOT_SPEED


def read_study(directory):
    if not os.path.isdir(directory):
        raise InputError(directory, "not a folder")
    variants = sorted(name for name in os.listdir(directory)
                      if os.path.isdir(os.path.join(directory, name, "transfer")))
    if "paper" not in variants:
        raise InputError(directory, "has no paper/transfer (the variants are paired with it)")
    variants.remove("paper")
    study = {}
    for variant in ["paper"] + variants:
        folder = os.path.join(directory, variant)
        conditions, transfer = read_transfer(folder)
        study[variant] = {"conditions": conditions, "transfer": transfer,
                          "exp2": read_late_exp2(folder)}
    return study


def column(rows, name):
    return [row[name] for row in rows]


def skill_table(study):
    lines = ["| variant | arm | trials to skill: median [min, max] | skilled | vs paper "
             "(mean difference [95 % CI], sign test) |", "|---|---|---|---|---|"]
    paper = study["paper"]["transfer"]
    for variant, data in study.items():
        for arm in ARMS:
            rows = data["transfer"].get(arm, [])
            if not rows:
                continue
            trials = sorted(column(rows, "trials_to_skill"))
            skilled = int(sum(column(rows, "skilled")))
            versus = "" if variant == "paper" else paired_text(
                column(paper[arm], "trials_to_skill"), column(rows, "trials_to_skill"))
            median = statistics.median(trials)
            lines.append(f"| {variant} | {arm} | {median:g} [{trials[0]:g}, {trials[-1]:g}] | "
                         f"{skilled}/{len(rows)} | {versus} |")
    lines += ["", "The cerebellum's advantage, per variant: bg_only's trials to skill minus "
              "cbbg's, seed by seed.", "", "| variant | bg_only - cbbg |", "|---|---|"]
    for variant, data in study.items():
        transfer = data["transfer"]
        difference = paired_text(column(transfer["cbbg"], "trials_to_skill"),
                                 column(transfer["bg_only"], "trials_to_skill"))
        lines.append(f"| {variant} | {difference} |")
    return lines


def balanced_text(rows, condition):
    return (f"{int(sum(column(rows, 'balanced@' + condition)))}/"
            f"{int(sum(column(rows, 'evaluated@' + condition)))}")


def robustness_table(study):
    conditions = study["paper"]["conditions"]
    lines = ["| variant | arm | " + " | ".join(conditions) + " |",
             "|---|---|" + "---|" * len(conditions)]
    paper = study["paper"]["transfer"]
    if "pd_only" in paper:
        lines.append("| PD supervisor | pd_only | " + " | ".join(
            balanced_text(paper["pd_only"], c) for c in conditions) + " |")
    for variant, data in study.items():
        for arm in ARMS:
            rows = data["transfer"].get(arm, [])
            cells = []
            for condition in conditions:
                cell = balanced_text(rows, condition)
                if variant != "paper":
                    _, _, _, p = paired(column(paper[arm], "balanced@" + condition),
                                        column(rows, "balanced@" + condition))
                    cell += f" (p = {p:.2g})"
                cells.append(cell)
            lines.append(f"| {variant} | {arm} | " + " | ".join(cells) + " |")
    return lines


def finite_pairs(a, b):
    """The seeds where both values are finite, as two lists."""
    kept = [(x, y) for x, y in zip(a, b) if math.isfinite(x) and math.isfinite(y)]
    return [x for x, _ in kept], [y for _, y in kept]


def mean_of(values):
    kept = [v for v in values if math.isfinite(v)]
    return sum(kept) / len(kept) if kept else math.nan


def late_seeds(data, arm):
    seeds = data["exp2"].get(arm, {})
    return [LateSeed(seeds[s]) for s in sorted(seeds, key=int)]


def drift_table(study):
    lines = ["| variant | arm | mean abs speed, m/s | median speed, m/s | seeds holding ground "
             "(abs speed < 0.1, none fell) | late trials that fell | pitch RMS, rad | abs speed "
             "vs paper | pitch RMS vs paper |", "|---|---|---|---|---|---|---|---|---|"]
    for variant, data in study.items():
        for arm in ARMS:
            seeds = late_seeds(data, arm)
            if not seeds:
                continue
            speeds = sorted(seed.speed for seed in seeds if math.isfinite(seed.speed))
            median = speeds[len(speeds) // 2] if speeds else math.nan
            versus = ["", ""]
            if variant != "paper":
                base = late_seeds(study["paper"], arm)
                pairs = [finite_pairs([abs(b.speed) for b in base], [abs(v.speed) for v in seeds]),
                         finite_pairs([b.rms for b in base], [v.rms for v in seeds])]
                versus = [paired_text(*pairs[0], 2) if pairs[0][0] else "no pair",
                          paired_text(*pairs[1], 4) if pairs[1][0] else "no pair"]
            lines.append(
                f"| {variant} | {arm} | {mean_of([abs(seed.speed) for seed in seeds]):.2f} | "
                f"{median:+.2f} | {sum(seed.holds for seed in seeds)}/{len(seeds)} | "
                f"{sum(seed.fell for seed in seeds)}/{len(seeds) * len(LATE_TRIALS)} | "
                f"{mean_of([seed.rms for seed in seeds]):.4f} | {versus[0]} | {versus[1]} |")
    return lines


def moonshot_lines(study):
    conditions = study["paper"]["conditions"]
    noise = next((c for c in conditions if c == "evaluation.noise_std=0.05"), None)
    push = next((c for c in conditions if c.startswith("evaluation.push_force=")), None)
    lines = ["| variant | arm | balanced under noise 0.05 | balanced under the push | seeds "
             "holding ground in exp2 | all three >= 90 % |", "|---|---|---|---|---|---|"]
    for variant, data in study.items():
        for arm in ARMS:
            rows = data["transfer"].get(arm, [])
            seeds = late_seeds(data, arm)
            if not rows or not seeds or noise is None or push is None:
                continue

            def rate(condition):
                return (sum(column(rows, "balanced@" + condition)) /
                        sum(column(rows, "evaluated@" + condition)))
            holding = sum(seed.holds for seed in seeds) / len(seeds)
            reached = min(rate(noise), rate(push), holding) >= MOONSHOT_RATE
            lines.append(f"| {variant} | {arm} | {rate(noise):.0%} | {rate(push):.0%} | "
                         f"{holding:.0%} | {'**yes**' if reached else 'no'} |")
    return lines


def figure(study):
    """Four panels of bars, a group per variant, a bar per arm."""
    variants = list(study)
    conditions = study["paper"]["conditions"]
    noise = "evaluation.noise_std=0.05"
    push = next((c for c in conditions if c.startswith("evaluation.push_force=")), None)
    width, height = plot_results.FIGURE_SIZE
    fig, axes = plt.subplots(2, 2, figsize=(width * 1.5, height * 1.4),
                             dpi=plot_results.FIGURE_DPI, layout="constrained")

    def rate(rows, condition):
        evaluated = sum(column(rows, "evaluated@" + condition))
        return sum(column(rows, "balanced@" + condition)) / evaluated if evaluated else math.nan

    def holding(data, arm):
        seeds = late_seeds(data, arm)
        return sum(seed.holds for seed in seeds) / len(seeds) if seeds else math.nan

    panels = [
        ("trials to skill (median over seeds)",
         lambda data, arm: statistics.median(column(data["transfer"][arm], "trials_to_skill")),
         None),
        ("balanced under pitch noise 0.05 rad",
         lambda data, arm: rate(data["transfer"][arm], noise), noise),
        (f"balanced under a push of {push.partition('=')[2] if push else '?'} N from outside",
         lambda data, arm: rate(data["transfer"][arm], push) if push else math.nan, push),
        ("seeds holding their ground in exp2 (trials 23-30)", holding, None),
    ]
    positions = range(len(variants))
    for ax, (title, value, condition) in zip(axes.flat, panels):
        for offset, arm in ((-0.2, "cbbg"), (0.2, "bg_only")):
            heights = [value(study[v], arm) if arm in study[v]["transfer"] else math.nan
                       for v in variants]
            if all(math.isnan(h) for h in heights):
                continue  # exp2 trains cbbg alone
            ax.bar([p + offset for p in positions], heights, width=0.4, label=arm)
        paper = study["paper"]["transfer"]
        if condition is not None and "pd_only" in paper:
            ax.axhline(rate(paper["pd_only"], condition), color="black", linestyle="--",
                       label="PD supervisor (the teacher)")
        ax.set_xticks(list(positions), variants, rotation=20, ha="right", fontsize="small")
        ax.set_title(title, fontsize="medium")
        ax.grid(True, axis="y", alpha=0.3)
        ax.legend(fontsize="small")
    fig.suptitle("can the learner outgrow its teacher? each variant against the paper's learner")
    return fig


def report(study):
    lines = ["## Trials to skill (exp3's training)", ""] + skill_table(study)
    lines += ["", "## Balanced runs under each condition (seeds x evaluation angles)", ""]
    lines += robustness_table(study)
    lines += ["", "## exp2, trials 23-30: drift and oscillation", ""] + drift_table(study)
    lines += ["", "## The moonshot: as robust as the teacher, and holding its ground", ""]
    lines += moonshot_lines(study)
    return "\n".join(lines) + "\n"


def main(argv):
    return plot_results.study_report_main(argv, "teacher_report.py", STUDY_MARKER, "teacher_study.sh", "teacher",
                                          read_study, report, figure)


if __name__ == "__main__":
    sys.exit(main(sys.argv))
