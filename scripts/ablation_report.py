#!/usr/bin/python3
"""The table of an ablation study (scripts/ablation_study.sh): what do the paper's choices buy?

Usage: /usr/bin/python3 scripts/ablation_report.py DIR

DIR/VARIANT/exp1 is a `cbbg run --experiment exp1` and DIR/VARIANT/exp3 an exp3 run, each
read from its summary.json (per arm and seed: failures_before_success; exp3's trials_to_skill,
null where the actor alone never balanced within max_trials), for the variant `paper` (the
paper's blocks) and the others of the study (one block swapped for a built-in alternative).
Writes DIR/ablation.md and DIR/ablation.png (per variant and arm: the median failures before
the first success and the median trials to skill). ablation.md holds, per variant and arm:
  - exp1's failures before the first success per seed: median [min, max], the seeds that
    succeeded (a seed that never did counts all its trials, as cbbg counts it);
  - exp3's trials until the actor alone balances per seed: median [min, max], the seeds that
    got there (a seed that never did counts as max_trials + 1, as summary.json's paired
    comparison and teacher_report.py count it);
  - for every variant but paper, each paired with the paper's learner seed by seed (same
    seed, same arm): the mean difference (variant - paper) with a 95 % bootstrap interval
    (10000 resamples of the seeds, seeded) and the exact two-sided sign test (ties dropped)
    with the seeds where the variant needed more, fewer and the same;
and, per variant, the cerebellum's advantage: bg_only - cbbg, seed by seed.
The table goes to stdout too.

It replaces its outputs only in a study ablation_study.sh made. Needs Debian's
python3-matplotlib (/usr/bin/python3).
Exit status: 0 done, 2 a missing or malformed input (one line on stderr naming the file),
1 the table could not be written.
"""

import os
import statistics
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import plot_results  # noqa: E402  (the summary.json reader, the figure style, publishing)
from plot_results import InputError, plt  # noqa: E402
from study_stats import interval_text, paired, paired_text, sign_counts  # noqa: E402

STUDY_MARKER = ".cbbg-ablation-study"
RUNS = ("exp1", "exp3")
# The figures, by name: what they count, and the run they come from.
FAILURES = "failures before the first success (exp1)"
SKILL = "trials to skill (exp3)"


class ArmRuns:
    """One arm of one variant: per seed, exp1's failures before the first success and exp3's
    trials to skill (the trials run where it never got there), and how many seeds got there."""

    def __init__(self, seeds, failures, succeeded, trials, skilled):
        self.seeds = seeds
        self.values = {FAILURES: failures, SKILL: trials}
        self.reached = {FAILURES: succeeded, SKILL: skilled}


def read_run(folder, run):
    """(summary, path) of DIR/VARIANT/RUN/summary.json, checked to be of that experiment."""
    path = os.path.join(folder, run, "summary.json")
    summary = plot_results.read_summary(path)
    if summary.get("experiment") != run:
        raise InputError(path, f'is of experiment "{summary.get("experiment")}", not {run}')
    if summary.get("seeds") is None or summary.get("max_trials") is None:
        raise InputError(path, 'has no "seeds" or "max_trials"')
    return summary, path


def skill_of(path, arm, entry, count, max_trials):
    """exp3's trials to skill per seed (null: never, counted as max_trials + 1, as
    summary.json's paired comparison counts it)."""
    trials = entry.get("trials_to_skill")
    if not isinstance(trials, list) or len(trials) != count or not all(
            t is None or (isinstance(t, int) and not isinstance(t, bool) and t > 0)
            for t in trials):
        raise InputError(path, f'"arms"."{arm}"."trials_to_skill" must be a list of integers '
                               f'> 0 or null, one per seed')
    return [max_trials + 1 if t is None else t for t in trials], sum(t is not None for t in trials)


def read_variant(folder):
    """{arm: ArmRuns} of one variant, the arms exp1 ran that exp3 ran too."""
    (exp1, path1), (exp3, path3) = (read_run(folder, run) for run in RUNS)
    if exp1["seeds"] != exp3["seeds"]:
        raise InputError(path3, f"has seeds {exp3['seeds']}, its exp1 {exp1['seeds']}")
    arms = {}
    for arm, entry in exp1["arms"].items():
        if arm not in exp3["arms"]:
            raise InputError(path3, f'has no arm "{arm}" (its exp1 has)')
        failures = entry.get("failures_before_success")
        if failures is None:
            raise InputError(path1, f'"arms"."{arm}" has no "failures_before_success"')
        succeeded = sum(entry.get("succeeded", [True] * len(failures)))
        trials, skilled = skill_of(path3, arm, exp3["arms"][arm], len(exp3["seeds"]),
                                   exp3["max_trials"])
        arms[arm] = ArmRuns(exp1["seeds"], failures, succeeded, trials, skilled)
    return arms


def read_study(directory):
    """{variant: {arm: ArmRuns}}, paper first, then the others by name."""
    if not os.path.isdir(directory):
        raise InputError(directory, "not a folder")
    variants = sorted(name for name in os.listdir(directory)
                      if any(os.path.isdir(os.path.join(directory, name, run)) for run in RUNS))
    if "paper" not in variants:
        raise InputError(directory, "has no paper/exp1 (the variants are paired with it)")
    variants.remove("paper")
    study = {}
    for variant in ["paper"] + variants:
        study[variant] = read_variant(os.path.join(directory, variant))
        for arm, runs in study[variant].items():
            paper = study["paper"].get(arm)
            if paper is not None and runs.seeds != paper.seeds:
                raise InputError(os.path.join(directory, variant, "exp1", "summary.json"),
                                 f"has seeds {runs.seeds}, the paper's {paper.seeds} (the "
                                 "variants are paired with it seed by seed)")
    return study


def spread_text(values, reached):
    ordered = sorted(values)
    return (f"{statistics.median(ordered):g} [{ordered[0]:g}, {ordered[-1]:g}], "
            f"{reached}/{len(values)}")


def versus_cells(base, values):
    """The paired cells of `values` against `base`: mean difference [95 % CI], and the sign
    test's p with the seeds greater / less / tied."""
    mean, low, high, p = paired(base, values)
    more, fewer, tied = sign_counts(base, values)
    return [interval_text(mean, low, high), f"{p:.2g} ({more}/{fewer}/{tied})"]


def ablation_table(study):
    lines = ["| variant | arm | failures before the first success (exp1): median [min, max], "
             "succeeded | failures vs paper: mean difference [95 % CI] | failures vs paper: "
             "sign test p (more/fewer/tied) | trials to skill (exp3): median [min, max], skilled "
             "| trials to skill vs paper: mean difference [95 % CI] | trials to skill vs paper: "
             "sign test p (more/fewer/tied) |", "|---|---|---|---|---|---|---|---|"]
    for variant, arms in study.items():
        for arm, runs in arms.items():
            cells = [variant, arm]
            paper = study["paper"].get(arm)
            for figure in (FAILURES, SKILL):
                cells.append(spread_text(runs.values[figure], runs.reached[figure]))
                if variant == "paper":
                    cells += ["", ""]
                elif paper is None:
                    cells += ["no paper arm", ""]
                else:
                    cells += versus_cells(paper.values[figure], runs.values[figure])
            lines.append("| " + " | ".join(cells) + " |")
    return lines


def advantage_table(study):
    lines = ["| variant | failures (exp1): bg_only - cbbg | trials to skill (exp3): bg_only - "
             "cbbg |", "|---|---|---|"]
    for variant, arms in study.items():
        if "cbbg" not in arms or "bg_only" not in arms:
            continue
        cells = [paired_text(arms["cbbg"].values[figure], arms["bg_only"].values[figure])
                 for figure in (FAILURES, SKILL)]
        lines.append(f"| {variant} | " + " | ".join(cells) + " |")
    return lines


def report(study):
    lines = ["## What the paper's choices buy: each variant against the paper's learner", ""]
    lines += ablation_table(study)
    lines += ["", "Per seed and arm; each variant paired with the paper's learner on the same "
              "seed and arm: the mean of variant - paper, its 95 % bootstrap interval, and the "
              "exact two-sided sign test (ties dropped) with the seeds where the variant needed "
              "more / fewer / the same. A seed that never succeeded in exp1 counts all its "
              "trials; one whose actor never balanced alone in exp3 counts as max_trials + 1 "
              "(as summary.json's paired comparison counts it).", "",
              "## The cerebellum's advantage, per variant: bg_only minus cbbg, seed by seed", ""]
    lines += advantage_table(study)
    return "\n".join(lines) + "\n"


def figure(study):
    """Two panels of bars, a group per variant, a bar per arm: the medians over the seeds."""
    variants = list(study)
    arms = list(dict.fromkeys(arm for data in study.values() for arm in data))
    width, height = plot_results.FIGURE_SIZE
    fig, axes = plt.subplots(1, 2, figsize=(width * 1.5, height),
                             dpi=plot_results.FIGURE_DPI, layout="constrained")
    bar = 0.8 / max(1, len(arms))
    for ax, name in zip(axes, (FAILURES, SKILL)):
        for a, arm in enumerate(arms):
            heights = [statistics.median(study[v][arm].values[name]) if arm in study[v]
                       else float("nan") for v in variants]
            offset = (a - (len(arms) - 1) / 2) * bar
            ax.bar([p + offset for p in range(len(variants))], heights, width=bar, label=arm)
        ax.set_xticks(list(range(len(variants))), variants, rotation=20, ha="right",
                      fontsize="small")
        ax.set_title(name + ", median over seeds", fontsize="medium")
        ax.grid(True, axis="y", alpha=0.3)
        ax.legend(fontsize="small")
    fig.suptitle("what the paper's choices buy: each variant against the paper's learner")
    return fig


def main(argv):
    return plot_results.study_report_main(argv, "ablation_report.py", STUDY_MARKER, "ablation_study.sh", "ablation",
                                          read_study, report, figure)


if __name__ == "__main__":
    sys.exit(main(sys.argv))
