#!/usr/bin/python3
"""The table of a baseline study (scripts/baseline_study.sh): the paper's learner against PPO.

Usage: /usr/bin/python3 scripts/baseline_report.py DIR

For ARM cbbg (the paper's learner) and bg_only (its actor-critic without the teacher),
DIR/paper/exp1_ARM is an exp1 run (trials.csv: each trial's steps, until the first success),
DIR/paper/transfer_ARM a transfer run trained as exp3 (figures.csv: balanced@C per
condition), DIR/paper/NAME.cpu_s their CPU seconds where they ran in one go; DIR/ppo/seed_N.json
are the baseline's reports (python/examples/ppo_balance.py). Writes DIR/baseline.md and
DIR/baseline.png:
  - simulated seconds of experience until the first trial (episode) balanced for 20 s, per
    learner: median, range and the seeds that reached it (exp1's trials until its first
    success; PPO's episodes of all its robots until the first truncation);
  - the final policy's runs balanced under each condition (cbbg and bg_only: the actor alone
    after exp3's training; PPO: its mean action after its step budget), of seeds x angles;
  - CPU seconds per seed.

It replaces its outputs only in a study baseline_study.sh made. Exit status: 0 done, 2 a
missing or malformed input (one line on stderr naming the file), 1 not written.
"""

import json
import os
import statistics
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import plot_results  # noqa: E402  (the readers, the figure style, publishing)
from plot_results import InputError  # noqa: E402

STUDY_MARKER = ".cbbg-baseline-study"
LABELS = {"evaluation.noise_std=0": "nominal", "evaluation.body_mass_scale=1.3": "+30 % mass",
          "evaluation.com_height_scale=1.3": "+30 % CoM height",
          "evaluation.noise_std=0.05": "noise 0.05 rad", "evaluation.push_force=74": "push 74 N"}


ARMS = {"cbbg": "cbbg, the paper's learner", "bg_only": "bg_only, without the teacher"}


def read_arm(directory, arm):
    """An arm of cbbg: experience per seed (None: no success), balanced/evaluated per
    condition, CPU seconds per run (None where unknown)."""
    exp1 = os.path.join(directory, "paper", f"exp1_{arm}")
    trials = plot_results.read_trials(os.path.join(exp1, "trials.csv"))
    config_path = os.path.join(exp1, "config.yaml")
    period = plot_results.config_number(plot_results.read_config(config_path), "trial.period",
                                        config_path)
    if period is None:
        raise InputError(config_path, "has no trial.period")
    experience = {}
    for trial in trials:
        seen, done = experience.get(trial.seed, (0, False))
        if not done:
            experience[trial.seed] = (seen + trial.steps, trial.succeeded)
    seconds = [steps * period if done else None for steps, done in experience.values()]
    path = os.path.join(directory, "paper", f"transfer_{arm}", "figures.csv")
    names, rows = plot_results.read_figures(path)
    balanced = {}
    for name in names:
        if name.startswith("balanced@"):
            condition = name[len("balanced@"):]
            evaluated = "evaluated@" + condition
            if evaluated not in names:
                raise InputError(path, f"has {name} but no {evaluated}")
            balanced[condition] = (int(sum(row[name] or 0 for row in rows)),
                                   int(sum(row[evaluated] or 0 for row in rows)))
    cpu = {run: read_cpu(os.path.join(directory, "paper", f"{run}_{arm}.cpu_s"))
           for run in ("exp1", "transfer")}
    return {"seconds": seconds, "balanced": balanced, "cpu": cpu, "seeds": len(experience)}


def read_cpu(path):
    try:
        with open(path, encoding="utf-8") as f:
            return float(f.read())
    except FileNotFoundError:
        return None
    except (OSError, ValueError) as error:
        raise InputError(path, f"unreadable CPU time ({error})")


def read_ppo(directory):
    """The baseline's reports, seed by seed."""
    folder = os.path.join(directory, "ppo")
    reports = []
    for name in sorted(os.listdir(folder) if os.path.isdir(folder) else []):
        if not (name.startswith("seed_") and name.endswith(".json")):
            continue
        path = os.path.join(folder, name)
        try:
            with open(path, encoding="utf-8") as f:
                report = json.load(f)
            report["balanced"], report["train_cpu_s"], report["evaluate_cpu_s"]
        except (OSError, ValueError, KeyError, TypeError) as error:
            raise InputError(path, f"not a baseline report ({error})")
        reports.append(report)
    if not reports:
        raise InputError(folder, "holds no seed_N.json report")
    balanced = {}
    for report in reports:
        for condition, (good, runs) in report["balanced"].items():
            condition = condition.split(";")[0]  # the push's duration is the study's
            total = balanced.setdefault(condition, [0, 0])
            total[0] += good
            total[1] += runs
    return {"reports": reports, "balanced": {k: tuple(v) for k, v in balanced.items()},
            "seconds": [r["experience_to_first_success_s"] for r in reports],
            "seeds": len(reports), "steps": reports[0]["steps"]}


def read_study(directory):
    study = {arm: read_arm(directory, arm) for arm in ARMS}
    study["ppo"] = read_ppo(directory)
    return study


def spread(values):
    reached = sorted(v for v in values if v is not None)
    if not reached:
        return "never", f"0/{len(values)}"
    text = f"{statistics.median(reached):.0f} ({reached[0]:.0f}–{reached[-1]:.0f})"
    return text, f"{len(reached)}/{len(values)}"


def per_seed(total, seeds):
    return "" if total is None else f"{total / seeds:.3g}"


def report(study):
    cbbg, ppo = study["cbbg"], study["ppo"]
    conditions = list(cbbg["balanced"])
    head = ["learner", "experience to the first 20 s trial, s: median (range)", "seeds"]
    head += [LABELS.get(c, c) for c in conditions]
    head += ["CPU s per seed: to the first success", "training and evaluation"]
    lines = ["# The paper's learner against a deep-RL baseline (PPO)", "",
             "| " + " | ".join(head) + " |", "|" + "---|" * len(head)]

    def row(name, data, cpu_first, cpu_all):
        text, reached = spread(data["seconds"])
        cells = [name, text, reached]
        for condition in conditions:
            good, runs = data["balanced"].get(condition, (0, 0))
            cells.append(f"{good}/{runs}" if runs else "")
        return "| " + " | ".join(cells + [cpu_first, cpu_all]) + " |"

    for arm, label in ARMS.items():
        data = study[arm]
        lines.append(row(label, data, per_seed(data["cpu"]["exp1"], data["seeds"]),
                         per_seed(data["cpu"]["transfer"], data["seeds"])))
    first = [r["cpu_to_first_success_s"] for r in ppo["reports"]
             if r.get("cpu_to_first_success_s") is not None]
    lines.append(row(f"PPO, {ppo['steps']} steps", ppo,
                     f"{statistics.median(first):.3g} (median)" if first else "",
                     per_seed(sum(r["train_cpu_s"] + r["evaluate_cpu_s"]
                                  for r in ppo["reports"]), ppo["seeds"])))
    lines += ["", f"{cbbg['seeds']} seeds of each arm of cbbg, {ppo['seeds']} of PPO; runs "
              "balanced of seeds x evaluation.angles, by the actor alone after exp3's "
              "training (cbbg, bg_only) or PPO's mean action after its budget. CPU of cbbg's "
              "arms: the exp1 run, and the transfer run (training to skill and every "
              "condition), over the seeds; PPO's: the median to its first success, and its "
              "whole budget with its evaluation.", ""]
    return "\n".join(lines)


def figure(study):
    fig, (left, right) = plot_results.new_figure(ncols=2)
    names = (*ARMS, "ppo")
    labels = [*ARMS, "PPO"]
    for index, name in enumerate(names):
        values = [v for v in study[name]["seconds"] if v is not None]
        left.scatter([index] * len(values), values, alpha=0.6)
    left.set_xticks(range(len(names)), labels)
    left.set_yscale("log")
    left.set_ylabel("simulated seconds until the first 20 s trial")
    left.set_title("experience to the first success, per seed")
    conditions = list(study["cbbg"]["balanced"])
    width = 0.8 / len(names)
    for index, (name, label) in enumerate(zip(names, labels)):
        rates = []
        for condition in conditions:
            good, runs = study[name]["balanced"].get(condition, (0, 0))
            rates.append(good / runs if runs else 0.0)
        offset = (index - (len(names) - 1) / 2) * width
        right.bar([i + offset for i in range(len(conditions))], rates, width, label=label)
    right.set_xticks(range(len(conditions)), [LABELS.get(c, c) for c in conditions],
                     rotation=30, ha="right")
    right.set_ylabel("share of runs balanced")
    right.set_title("the final policy under each condition")
    right.set_ylim(0, 1.2)
    right.legend(loc="upper center", ncol=3)
    return fig


def main(argv):
    return plot_results.study_report_main(argv, "baseline_report.py", STUDY_MARKER,
                                          "baseline_study.sh", "baseline", read_study, report,
                                          figure)


if __name__ == "__main__":
    sys.exit(main(sys.argv))
