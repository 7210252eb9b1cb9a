#!/usr/bin/python3
"""Draw the figures of a cbbg results directory into DIR/figures/ (paper Figs. 11-14).

Usage: /usr/bin/python3 scripts/plot_results.py DIR      (what `cbbg plot DIR` runs)

Reads DIR/schema.json, DIR/summary.json, DIR/trials.csv, DIR/config.yaml and, when the run
logged ticks, DIR/steps.csv. It draws what the results' schema names in "plots" (a
protocol's declaration, whatever its name; for results written before schema.json, what
their files call for):
  pitch       pitch_<arm>.png: theta_b(t) of the first seed's first trial and first
              successful trial
  failures    failures.png: failures before the first success, one point per seed, per arm
  skill       skill.png: per arm, failures and trials to the first success and to the skill
              (summary.json's trials_to_skill and failures_to_skill), one point per seed
  annealing   temperature_entropy.png: mean temperature and entropy per trial;
              pitch_early_late.png: theta_b(t) of early against late trials of the first
              seed; oscillation.png: trials.csv's pitch_rms, pitch_peak_to_peak and
              mean_forward_speed per trial, when it has them
  evaluation  evaluation.png: per arm and initial angle, the evaluation runs that balanced
  figures     figures.png: each of figures.csv's figures per arm: balanced@C / evaluated@C
              as a rate per condition C, any other figure as its mean over the seeds that
              have one
and for a sweep (a directory with sweep.csv, written by cbbg merge):
  sweep_<key>.png      the headline figure (median and range over seeds) against each
                       swept key, one line per arm and per value of the other keys, and
                       beside it the evaluation's balance rate where sweep.csv has one

The figures are drawn into a staging folder and moved into DIR/figures only when all of
them are written. DIR/figures may hold files of yours: they are never replaced or removed.
DIR/figures/.cbbg-written lists the files cbbg wrote there; a figure whose name is taken by
a file not listed is refused before anything moves. Exit status: 0 done, 2 a missing or
malformed input file or a figure's name taken by a file of yours (one line on stderr naming
the file), 1 the figures could not be written.

Needs Debian's python3-numpy and python3-matplotlib: run it with /usr/bin/python3.
"""

import csv
import json
import math
import os
import re
import shutil
import socket
import sys
from dataclasses import dataclass

MISSING_MODULE = None  # numpy or matplotlib absent: main() says so instead of a traceback
try:
    import numpy as np
    import matplotlib

    matplotlib.use("Agg")  # files only, no display
    import matplotlib.pyplot as plt
except ImportError as error:
    MISSING_MODULE = error.name

TRIALS_COLUMNS = ("arm", "seed", "trial", "failed", "steps", "mean_temperature",
                  "mean_entropy", "final_theta", "status")
STEPS_KEY_COLUMNS = ("arm", "seed", "trial")
STEPS_PITCH_COLUMNS = ("t", "theta_b")
STATUSES = ("success", "failed", "diverged", "stopped")

FIGURE_SIZE = (8.0, 4.5)  # inches
FIGURE_DPI = 100


class InputError(Exception):
    """A missing or malformed input file: reported as 'FILE: what is wrong', exit 2."""

    def __init__(self, path, what):
        super().__init__(f"{path}: {what}")


def note(text):
    print(f"note: {text}")


# ----------------------------------------------------------------------------- inputs

def read_summary(path):
    try:
        with open(path, encoding="utf-8") as f:
            summary = json.load(f)
    except FileNotFoundError:
        raise InputError(path, "missing (the run writes it at the end: did it finish?)")
    except OSError as error:
        raise InputError(path, f"cannot be read ({error.strerror})")
    except UnicodeDecodeError:
        raise InputError(path, "not UTF-8 text")
    except json.JSONDecodeError as error:
        raise InputError(path, f"not valid JSON (line {error.lineno} column {error.colno}: "
                               f"{error.msg})")
    if not isinstance(summary, dict):
        raise InputError(path, "expected a JSON object at the top level")

    def check(condition, what):
        if not condition:
            raise InputError(path, what)

    def is_int(value):
        return isinstance(value, int) and not isinstance(value, bool)

    def is_number(value):
        return (isinstance(value, (int, float)) and not isinstance(value, bool)
                and math.isfinite(value))

    check(isinstance(summary.get("experiment", ""), str), '"experiment" must be a string')
    check(isinstance(summary.get("plant", ""), str), '"plant" must be a string')
    max_trials = summary.get("max_trials")
    check(max_trials is None or (is_int(max_trials) and max_trials > 0),
          '"max_trials" must be an integer > 0')
    seeds = summary.get("seeds")
    check(seeds is None or (isinstance(seeds, list) and all(is_int(s) for s in seeds)),
          '"seeds" must be a list of integers')
    arms = summary.get("arms", {})
    check(isinstance(arms, dict), '"arms" must be an object mapping arm names to results')
    for arm, result in arms.items():
        where = f'"arms"."{arm}"'
        check(isinstance(result, dict), f"{where} must be an object")
        failures = result.get("failures_before_success")
        succeeded = result.get("succeeded")
        check(failures is None or (isinstance(failures, list)
                                   and all(is_int(n) and n >= 0 for n in failures)),
              f'{where}."failures_before_success" must be a list of integers >= 0')
        check(succeeded is None or (isinstance(succeeded, list)
                                    and all(isinstance(b, bool) for b in succeeded)),
              f'{where}."succeeded" must be a list of true/false')
        if failures is not None and succeeded is not None:
            check(len(failures) == len(succeeded),
                  f'{where}: "failures_before_success" has {len(failures)} entries but '
                  f'"succeeded" has {len(succeeded)}')
        if failures is not None and seeds is not None:
            check(len(failures) == len(seeds),
                  f'{where}: "failures_before_success" has {len(failures)} entries but '
                  f'"seeds" has {len(seeds)}')
        median = result.get("median")
        check(median is None or is_number(median), f'{where}."median" must be a number')
    paper = summary.get("paper", {})
    check(isinstance(paper, dict) and all(is_number(v) for v in paper.values()),
          '"paper" must be an object mapping arm names to numbers')
    return summary


def parse_config(text):
    """The few keys the figures use from the resolved config.yaml, without a YAML library.

    Returns {"experiment": str, "trial.failure_angle": str, ...} for scalar keys (top level
    and one section deep, block or flow style) and "annealing": [(from_trial, k1), ...].
    """
    values = {}
    annealing = []
    section = ""
    for raw_line in text.splitlines():
        line = raw_line.split("#", 1)[0].rstrip()
        if not line.strip():
            continue
        indented = line[0] in " \t"
        body = line.strip()
        if not indented:
            key, _, rest = body.partition(":")
            section, rest = key.strip(), rest.strip()
            if rest.startswith("{"):
                for item in rest.strip("{}").split(","):
                    sub, _, value = item.partition(":")
                    values[f"{section}.{sub.strip()}"] = value.strip()
            elif rest:
                values[section] = rest
            continue
        if section == "annealing":
            from_trial = re.search(r"from_trial:\s*([-+0-9.eE]+)", body)
            k1 = re.search(r"k1:\s*([-+0-9.eE]+)", body)
            if body.startswith("-") and from_trial and k1:
                annealing.append((from_trial.group(1), k1.group(1)))
            continue
        key, _, value = body.partition(":")
        if value.strip():
            values[f"{section}.{key.strip()}"] = value.strip()
    values = {key: value.strip("'\"") for key, value in values.items()}
    values["annealing"] = annealing
    return values


def read_config(path):
    """The parsed config.yaml, or None (with a note) when the run did not write one."""
    try:
        with open(path, encoding="utf-8") as f:
            text = f.read()
    except FileNotFoundError:
        note(f"{path} absent: figures drawn without the failure angle and annealing stages")
        return None
    except OSError as error:
        raise InputError(path, f"cannot be read ({error.strerror})")
    except UnicodeDecodeError:
        raise InputError(path, "not UTF-8 text")
    return parse_config(text)


def config_number(config, key, path):
    """A number from config.yaml, or None when the key is absent."""
    if config is None or key not in config:
        return None
    try:
        value = float(config[key])
    except ValueError:
        raise InputError(path, f"{key} is '{config[key]}', not a number")
    if not math.isfinite(value):
        raise InputError(path, f"{key} is '{config[key]}', not a finite number")
    return value


def annealing_stages(config, path):
    """[(from_trial, k1), ...] of config.yaml's annealing schedule, sorted by trial."""
    if config is None:
        return []
    stages = []
    for from_trial, k1 in config["annealing"]:
        try:
            stages.append((int(from_trial), float(k1)))
        except ValueError:
            raise InputError(path, f"annealing entry {{from_trial: {from_trial}, k1: {k1}}} "
                                   "is not an integer trial and a number")
    return sorted(stages)


@dataclass(frozen=True)
class Trial:
    arm: str
    seed: int
    trial: int
    failed: bool
    steps: int
    mean_temperature: float
    mean_entropy: float
    final_theta: float
    status: str

    @property
    def succeeded(self):
        return self.status == "success"


def open_csv(path, required, optional_file):
    """(file, reader, header index) of a CSV file whose header holds the required columns."""
    try:
        f = open(path, newline="", encoding="utf-8")
    except FileNotFoundError:
        if optional_file:
            return None
        raise InputError(path, "missing")
    except OSError as error:
        raise InputError(path, f"cannot be read ({error.strerror})")
    reader = csv.reader(f)
    try:
        header = next(reader, None)
    except (csv.Error, UnicodeDecodeError) as error:
        f.close()
        raise InputError(path, f"line 1: unreadable header ({error})")
    if not header:
        f.close()
        raise InputError(path, "empty (expected a header line)")
    header = [name.strip() for name in header]
    lacking = [name for name in required if name not in header]
    if lacking:
        f.close()
        raise InputError(path, f"header lacks column(s) {', '.join(lacking)} "
                               f"(header is: {','.join(header)})")
    return f, reader, {name: header.index(name) for name in header}, len(header)


def parse_integer(path, line, name, text, minimum):
    try:
        value = int(text)
    except ValueError:
        raise InputError(path, f"line {line}: {name} '{text}' is not an integer")
    if value < minimum:
        raise InputError(path, f"line {line}: {name} is {value}; must be >= {minimum}")
    return value


def parse_number(path, line, name, text):
    try:
        return float(text)
    except ValueError:
        raise InputError(path, f"line {line}: {name} '{text}' is not a number")


def parse_trial_row(path, line, field):
    """One trials.csv row (a dict of its stripped fields) as a Trial."""
    if not field["arm"]:
        raise InputError(path, f"line {line}: arm is empty")
    failed = parse_integer(path, line, "failed", field["failed"], 0)
    if failed > 1:
        raise InputError(path, f"line {line}: failed is {failed}; must be 0 or 1")
    if field["status"] not in STATUSES:
        raise InputError(path, f"line {line}: status '{field['status']}' is not one of "
                               f"{'|'.join(STATUSES)}")
    return Trial(arm=field["arm"],
                 seed=parse_integer(path, line, "seed", field["seed"], 0),
                 trial=parse_integer(path, line, "trial", field["trial"], 1),
                 failed=bool(failed),
                 steps=parse_integer(path, line, "steps", field["steps"], 0),
                 mean_temperature=parse_number(path, line, "mean_temperature",
                                               field["mean_temperature"]),
                 mean_entropy=parse_number(path, line, "mean_entropy", field["mean_entropy"]),
                 final_theta=parse_number(path, line, "final_theta", field["final_theta"]),
                 status=field["status"])


def read_trials(path):
    """Every row of trials.csv as a Trial, sorted by arm (first appearance), seed, trial."""
    f, reader, column, width = open_csv(path, TRIALS_COLUMNS, optional_file=False)
    trials = []
    seen = set()
    with f:
        try:
            for row in reader:
                line = reader.line_num
                if not row:
                    continue
                if len(row) != width:
                    raise InputError(path, f"line {line}: expected {width} fields, got {len(row)}")
                fields = {name: row[column[name]].strip() for name in TRIALS_COLUMNS}
                trial = parse_trial_row(path, line, fields)
                key = (trial.arm, trial.seed, trial.trial)
                if key in seen:
                    raise InputError(path, f"line {line}: arm {trial.arm} seed {trial.seed} "
                                           f"trial {trial.trial} appears twice")
                seen.add(key)
                trials.append(trial)
        except (csv.Error, UnicodeDecodeError) as error:
            raise InputError(path, f"line {reader.line_num}: unreadable ({error})")
    if not trials:
        raise InputError(path, "has a header but no trial rows")
    arm_order = {}
    for trial in trials:
        arm_order.setdefault(trial.arm, len(arm_order))
    return sorted(trials, key=lambda t: (arm_order[t.arm], t.seed, t.trial))


def read_pitch(path, wanted):
    """{(arm, seed, trial): (t, theta_b)} as numpy arrays for the wanted trials of steps.csv.

    Returns None when steps.csv is absent (logging off). Streams the file and parses only
    the rows of the wanted trials, so a log of tens of MB costs one pass of the csv reader.
    """
    opened = open_csv(path, STEPS_KEY_COLUMNS + STEPS_PITCH_COLUMNS, optional_file=True)
    if opened is None:
        return None
    f, reader, column, width = opened
    i_arm, i_seed, i_trial = (column[name] for name in STEPS_KEY_COLUMNS)
    i_t, i_theta = (column[name] for name in STEPS_PITCH_COLUMNS)
    samples = {key: ([], []) for key in wanted}
    key_of_raw = {}  # the raw key fields of a row -> its wanted key, or None
    with f:
        try:
            for row in reader:
                if len(row) != width:
                    if not row:
                        continue
                    raise InputError(path, f"line {reader.line_num}: expected {width} fields, "
                                           f"got {len(row)}")
                raw = (row[i_arm], row[i_seed], row[i_trial])
                key = key_of_raw.get(raw, False)
                if key is False:
                    try:
                        key = (raw[0].strip(), int(raw[1]), int(raw[2]))
                    except ValueError:
                        raise InputError(path, f"line {reader.line_num}: seed '{raw[1]}' or "
                                               f"trial '{raw[2]}' is not an integer")
                    key = key if key in samples else None
                    key_of_raw[raw] = key
                if key is None:
                    continue
                try:
                    t, theta = float(row[i_t]), float(row[i_theta])
                except ValueError:
                    raise InputError(path, f"line {reader.line_num}: t '{row[i_t]}' or "
                                           f"theta_b '{row[i_theta]}' is not a number")
                samples[key][0].append(t)
                samples[key][1].append(theta)
        except (csv.Error, UnicodeDecodeError) as error:
            raise InputError(path, f"line {reader.line_num}: unreadable ({error})")
    return {key: (np.asarray(t), np.asarray(theta))
            for key, (t, theta) in samples.items() if t}


# ------------------------------------------------------------------ what to plot

def arms_in_order(summary, trials):
    """Arms in the order of summary.json, then any that only trials.csv names."""
    arms = list(summary.get("arms", {}))
    for trial in trials:
        if trial.arm not in arms:
            arms.append(trial.arm)
    return arms


def trials_of(trials, arm, seed):
    return [t for t in trials if t.arm == arm and t.seed == seed]


def first_seed(summary, trials, arm):
    """The run's first seed (summary.json's order) that has trials of this arm."""
    seeds = sorted({t.seed for t in trials if t.arm == arm})
    for seed in summary.get("seeds") or []:
        if seed in seeds:
            return seed
    return seeds[0] if seeds else None


@dataclass
class PitchSelection:
    """The exp1 trials of one arm and seed to draw: first, the failures between, the end."""
    first: Trial
    between: list
    last: Trial  # the first successful trial, or the last trial when none succeeded
    succeeded: bool


def exp1_pitch_selection(seed_trials):
    """First trial, the failed trials between, and the first success (or the last trial)."""
    first_success = next((t for t in seed_trials if t.succeeded), None)
    last = first_success or seed_trials[-1]
    between = [t for t in seed_trials if seed_trials[0].trial < t.trial < last.trial]
    return PitchSelection(first=seed_trials[0], between=between, last=last,
                          succeeded=first_success is not None)


def early_late_trials(trial_numbers):
    """(early, late) exp2 trials: the first two after the CB-coordinated trial 1, the last two."""
    numbers = sorted(trial_numbers)
    operant = numbers[1:] if len(numbers) > 1 else numbers
    early = operant[:2]
    late = [n for n in operant[-2:] if n not in early]
    return early, late


@dataclass
class SeedFailures:
    seed: int
    failures: int
    succeeded: bool


def failures_per_seed(summary, trials, arm):
    """Failures before the first success per seed: summary.json's, else counted in trials.csv.

    A seed that never succeeded counts every trial it ran (a lower bound).
    """
    result = summary.get("arms", {}).get(arm, {})
    failures = result.get("failures_before_success")
    succeeded = result.get("succeeded")
    seeds = summary.get("seeds")
    if failures is not None and succeeded is not None:
        if seeds is None:  # summary.json without "seeds": the seeds trials.csv names
            seeds = sorted({t.seed for t in trials if t.arm == arm})
            if len(seeds) != len(failures):
                seeds = list(range(1, len(failures) + 1))
        return [SeedFailures(s, n, ok) for s, n, ok in zip(seeds, failures, succeeded)]
    counted = []
    for seed in sorted({t.seed for t in trials if t.arm == arm}):
        seed_trials = trials_of(trials, arm, seed)
        first_success = next((t for t in seed_trials if t.succeeded), None)
        if first_success is None:
            counted.append(SeedFailures(seed, len(seed_trials), False))
        else:
            before = sum(1 for t in seed_trials if t.trial < first_success.trial)
            counted.append(SeedFailures(seed, before, True))
    return counted


def median_failures(summary, arm, per_seed):
    median = summary.get("arms", {}).get(arm, {}).get("median")
    if median is not None:
        return float(median)
    return float(np.median([s.failures for s in per_seed])) if per_seed else None


def spread_offsets(values, width):
    """Horizontal offsets that spread equal values side by side (a small beeswarm)."""
    offsets = [0.0] * len(values)
    groups = {}
    for i, value in enumerate(values):
        groups.setdefault(value, []).append(i)
    for members in groups.values():
        n = len(members)
        step = min(0.1, width / max(n - 1, 1))
        for rank, i in enumerate(members):
            offsets[i] = (rank - (n - 1) / 2) * step
    return offsets


def file_name_part(arm):
    return re.sub(r"[^A-Za-z0-9_.-]", "_", arm)


# ----------------------------------------------------------------------- figures

def new_figure(ncols=1, sharey=False):
    fig, axes = plt.subplots(1, ncols, figsize=FIGURE_SIZE, dpi=FIGURE_DPI, sharey=sharey,
                             layout="constrained")
    return fig, axes


def ending(trial, t):
    """How a trial ended, for a legend: "20.0 s" or "failed at 1.62 s"."""
    if not len(t):
        return trial.status
    if trial.status == "success":
        return f"{t[-1]:.1f} s"
    return f"{trial.status} at {t[-1]:.2f} s"


def draw_failure_band(ax, failure_angle):
    """The failure angle as dashed lines; the pitch axis spans a little beyond it, so that a
    diverged trial's last samples do not squash the others."""
    if failure_angle is None:
        return
    for sign in (1, -1):
        ax.axhline(sign * failure_angle, color="0.55", linestyle="--", linewidth=0.9,
                   label=f"failure angle ±{failure_angle:.3f} rad" if sign > 0 else None)
    ax.set_ylim(-1.25 * failure_angle, 1.25 * failure_angle)


def plot_exp1_pitch(arm, seed, selection, pitch, failure_angle, plant):
    fig, ax = new_figure()
    drawn_between = False
    for trial in selection.between:
        key = (arm, seed, trial.trial)
        if key in pitch:
            t, theta = pitch[key]
            first_between = selection.between[0].trial
            last_between = selection.between[-1].trial
            span = (f"trial {first_between}" if first_between == last_between
                    else f"trials {first_between}-{last_between}")
            ax.plot(t, theta, color="0.7", linewidth=0.8,
                    label=None if drawn_between else f"{span} (failed)")
            drawn_between = True
    ends = [selection.first] if selection.first is selection.last else [selection.first,
                                                                        selection.last]
    colours = ["tab:red", "tab:blue"] if len(ends) == 2 else ["tab:blue"]
    for trial, colour in zip(ends, colours):
        key = (arm, seed, trial.trial)
        if key not in pitch:
            continue
        t, theta = pitch[key]
        role = "first trial"
        if trial is selection.last:
            role = "first success" if selection.succeeded else "last trial, no success"
            if trial is selection.first:
                role = "first trial, first success"
        ax.plot(t, theta, color=colour, linewidth=1.4,
                label=f"trial {trial.trial}: {role} ({ending(trial, t)})")
    draw_failure_band(ax, failure_angle)
    ax.axhline(0.0, color="black", linewidth=0.5)
    ax.set_xlabel("time t [s]")
    ax.set_ylabel(r"pitch $\theta_b$ [rad]")
    ax.set_title(f"Pitch angle, arm {arm} ({plant} plant), seed {seed}")
    ax.grid(True, alpha=0.3)
    ax.legend(loc="upper right", fontsize="small")
    return fig


def plot_failures(arms, per_arm, medians, paper, max_trials, experiment, plant):
    fig, ax = new_figure()
    labelled = set()

    def label_once(text):
        if text in labelled:
            return None
        labelled.add(text)
        return text

    never_succeeded = (f"seed that never succeeded in {max_trials} trials" if max_trials
                       else "seed that never succeeded (at its trial count)")
    tick_labels = []
    for x, arm in enumerate(arms):
        seeds = per_arm[arm]
        values = [s.failures for s in seeds]
        offsets = spread_offsets(values, 0.6)
        for s, dx in zip(seeds, offsets):
            if s.succeeded:
                ax.plot(x + dx, s.failures, "o", color="tab:blue", markersize=6, alpha=0.8,
                        zorder=3, label=label_once("one seed"))
            else:
                ax.plot(x + dx, s.failures, "X", color="tab:red", markersize=8, zorder=3,
                        label=label_once(never_succeeded))
        if medians[arm] is not None:
            ax.hlines(medians[arm], x - 0.3, x + 0.3, color="black", linewidth=2.0, zorder=2,
                      label=label_once("median over seeds"))
        if arm in paper:
            ax.plot(x + 0.4, paper[arm], "D", markersize=9, markerfacecolor="none",
                    markeredgecolor="tab:orange", markeredgewidth=2, zorder=3,
                    label=label_once("paper (one run)"))
            ax.annotate(f"{paper[arm]:g}", (x + 0.4, paper[arm]), xytext=(8, 0),
                        textcoords="offset points", va="center", color="tab:orange")
        succeeded = sum(1 for s in seeds if s.succeeded)
        tick_labels.append(f"{arm}\n{succeeded}/{len(seeds)} seeds succeeded")
    ax.set_xticks(range(len(arms)), tick_labels)
    ax.set_xlim(-0.6, len(arms) - 0.3)
    top = max([s.failures for a in arms for s in per_arm[a]]
              + [paper[a] for a in arms if a in paper] + [1])
    ax.set_ylim(-0.05 * top - 0.5, top * 1.08 + 0.5)
    ax.set_ylabel("failures before first success [trials]")
    ax.set_title(f"Failures before the first successful trial ({experiment}, {plant} plant)")
    ax.grid(True, axis="y", alpha=0.3)
    ax.legend(loc="best", fontsize="small")
    return fig


def plot_temperature_entropy(arms, trials, summary, stages, experiment, plant):
    fig, (ax_t, ax_e) = new_figure(ncols=2)
    colours = plt.rcParams["axes.prop_cycle"].by_key()["color"]
    for index, arm in enumerate(arms):
        colour = colours[index % len(colours)]
        seed = first_seed(summary, trials, arm)
        arm_trials = [t for t in trials if t.arm == arm]
        seeds = sorted({t.seed for t in arm_trials})
        prefix = f"{arm}, " if len(arms) > 1 else ""
        for ax, field in ((ax_t, "mean_temperature"), (ax_e, "mean_entropy")):
            if len(seeds) > 1:
                by_trial = {}
                for t in arm_trials:
                    value = getattr(t, field)
                    if math.isfinite(value):
                        by_trial.setdefault(t.trial, []).append(value)
                numbers = sorted(n for n, v in by_trial.items() if len(v) > 1)
                if numbers:
                    low = [min(by_trial[n]) for n in numbers]
                    high = [max(by_trial[n]) for n in numbers]
                    middle = [float(np.median(by_trial[n])) for n in numbers]
                    ax.fill_between(numbers, low, high, color=colour, alpha=0.18, linewidth=0,
                                    label=f"{prefix}range over {len(seeds)} seeds")
                    ax.plot(numbers, middle, color=colour, linestyle="--", linewidth=1.1,
                            label=f"{prefix}median over {len(seeds)} seeds")
            first = trials_of(trials, arm, seed)
            ax.plot([t.trial for t in first], [getattr(t, field) for t in first], "o-",
                    color=colour, markersize=3.5, linewidth=1.4, label=f"{prefix}seed {seed}")
    for ax in (ax_t, ax_e):
        for from_trial, k1 in stages:
            if from_trial > 1:
                ax.axvline(from_trial - 0.5, color="0.6", linestyle=":", linewidth=1.0)
        ax.set_xlabel("trial")
        ax.grid(True, alpha=0.3)
        ax.xaxis.get_major_locator().set_params(integer=True)
        if stages:
            # The annealing stages on a top axis: k1 from each stage's first trial on.
            top = ax.secondary_xaxis("top")
            top.set_xticks([from_trial for from_trial, _ in stages],
                           [f"{k1:g}" for _, k1 in stages], fontsize=8)
            top.set_xlabel("annealing factor k1 from this trial", fontsize=8)
    ax_t.set_ylabel("mean temperature T [dimensionless]")
    ax_t.set_title("Mean temperature per trial")
    ax_e.set_ylabel("mean entropy E [bits]")
    ax_e.set_title("Mean entropy per trial")
    ax_e.legend(loc="best", fontsize="small")
    fig.suptitle(f"Annealing schedule and exploration ({experiment}, {plant} plant)")
    return fig


def plot_pitch_early_late(arm, seed, early, late, by_number, pitch, failure_angle,
                          stages, plant):
    fig, (ax_early, ax_late) = new_figure(ncols=2, sharey=True)

    def k1_of(number):
        k1 = None
        for from_trial, value in stages:
            if from_trial <= number:
                k1 = value
        return k1

    for ax, numbers, name, colours in ((ax_early, early, "Early", ["tab:red", "tab:orange"]),
                                       (ax_late, late, "Late", ["tab:blue", "tab:green"])):
        for number, colour in zip(numbers, colours):
            key = (arm, seed, number)
            if key not in pitch:
                continue
            t, theta = pitch[key]
            k1 = k1_of(number)
            stage = f", k1={k1:g}" if k1 is not None else ""
            ax.plot(t, theta, color=colour, linewidth=1.2,
                    label=f"trial {number}{stage} ({ending(by_number[number], t)})")
        draw_failure_band(ax, failure_angle)
        ax.axhline(0.0, color="black", linewidth=0.5)
        shown = ", ".join(str(n) for n in numbers) if numbers else "none"
        ax.set_title(f"{name} trials ({shown})")
        ax.set_xlabel("time t [s]")
        ax.grid(True, alpha=0.3)
        if ax.get_legend_handles_labels()[0]:
            ax.legend(loc="upper right", fontsize="small")
    ax_early.set_ylabel(r"pitch $\theta_b$ [rad]")
    fig.suptitle(f"Pitch of early and late trials, arm {arm} ({plant} plant), seed {seed}")
    return fig


# -------------------------------------------------------------------------- main

def draw_pitch(save, summary, trials, pitch_path, failure_angle, plant):
    """Per arm, the pitch of its first seed's first, failed and last trials."""
    selections = {}
    for arm in arms_in_order(summary, trials):
        seed = first_seed(summary, trials, arm)
        if seed is not None:
            selections[arm] = (seed, exp1_pitch_selection(trials_of(trials, arm, seed)))
    wanted = set()
    for arm, (seed, sel) in selections.items():
        wanted.update((arm, seed, t.trial) for t in [sel.first, *sel.between, sel.last])
    pitch = read_pitch(pitch_path, wanted)
    if pitch is None:
        note(f"{pitch_path} absent (tick logging off): pitch figures skipped")
        return
    for arm, (seed, sel) in selections.items():
        ends = {sel.first.trial, sel.last.trial}
        missing = sorted(n for n in ends if (arm, seed, n) not in pitch)
        if len(missing) == len(ends):
            note(f"{pitch_path} has no rows for arm {arm} seed {seed}: "
                 f"pitch_{file_name_part(arm)}.png skipped")
            continue
        if missing:
            note(f"{pitch_path} has no rows for arm {arm} seed {seed} trial(s) "
                 f"{', '.join(map(str, missing))}")
        save(plot_exp1_pitch(arm, seed, sel, pitch, failure_angle, plant),
             f"pitch_{file_name_part(arm)}.png")


def draw_failures(save, summary, trials, experiment, plant):
    """Per arm, the failures before the first success of each seed."""
    arms = arms_in_order(summary, trials)
    per_arm = {arm: failures_per_seed(summary, trials, arm) for arm in arms}
    medians = {arm: median_failures(summary, arm, per_arm[arm]) for arm in arms}
    save(plot_failures(arms, per_arm, medians, summary.get("paper", {}),
                       summary.get("max_trials"), experiment, plant), "failures.png")


DRAWINGS = ("pitch", "failures", "skill", "annealing", "evaluation", "figures")


def read_schema(path):
    """DIR/schema.json (what the protocol's results hold), or None for results written
    before cbbg wrote one."""
    try:
        with open(path, encoding="utf-8") as f:
            schema = json.load(f)
    except FileNotFoundError:
        return None
    except (OSError, ValueError) as error:
        raise InputError(path, f"unreadable ({error})")
    plots = schema.get("plots") if isinstance(schema, dict) else None
    if not isinstance(plots, list) or not all(isinstance(p, str) for p in plots):
        raise InputError(path, '"plots" must be a list of drawing names')
    unknown = [p for p in plots if p not in DRAWINGS]
    if unknown:
        raise InputError(path, f"names no drawing '{unknown[0]}' ({', '.join(DRAWINGS)})")
    return schema


def drawings_of(results_dir, summary, trials_path, figures_path):
    """The drawings the results' schema names; for results without schema.json, those their
    files call for."""
    schema = read_schema(os.path.join(results_dir, "schema.json"))
    if schema is not None:
        return schema["plots"]
    if has_oscillation(trials_path):
        drawings = ["annealing"]
    else:
        drawings = ["pitch", "failures"] + (["skill"] if has_skill(summary) else [])
    return drawings + (["figures"] if os.path.isfile(figures_path) else [])


def plot_evaluation(summary, experiment, plant):
    """Per arm and initial angle, the evaluation runs that balanced (summary.json's
    "evaluation": the learnt actor alone, or an arm's closed loop as it is)."""
    fig, ax = new_figure()
    arms = [arm for arm, entry in summary.get("arms", {}).items()
            if isinstance(entry, dict) and isinstance(entry.get("evaluation"), dict)]
    width = 0.8 / max(len(arms), 1)
    for a, arm in enumerate(arms):
        evaluation = summary["arms"][arm]["evaluation"]
        angles, balanced, runs = evaluation["theta0"], evaluation["balanced"], evaluation["of"]
        rates = [b / runs if runs else float("nan") for b in balanced]
        ax.bar([i + (a - (len(arms) - 1) / 2) * width for i in range(len(angles))], rates,
               width, label=f"{arm} (of {runs} seeds)")
        ax.set_xticks(range(len(angles)), [f"{theta:g}" for theta in angles])
    ax.set_xlabel("initial pitch theta0 (rad)")
    ax.set_ylabel("runs that balanced (share of seeds)")
    ax.set_ylim(0, 1.05)
    ax.set_title(f"Evaluation per initial angle ({experiment}, {plant} plant)")
    ax.grid(True, axis="y", alpha=0.3)
    if arms:
        ax.legend(loc="best", fontsize="small")
    fig.tight_layout()
    return fig


def has_skill(summary):
    """Whether summary.json lists trials_to_skill (results without schema.json)."""
    arms = summary.get("arms")
    return isinstance(arms, dict) and any(
        isinstance(arm, dict) and "trials_to_skill" in arm for arm in arms.values())


def has_oscillation(trials_path):
    """Whether trials.csv has the oscillation columns (results without schema.json whose
    protocol annealed k1 trial by trial)."""
    with open(trials_path, encoding="utf-8") as f:
        return "pitch_rms" in [name.strip() for name in f.readline().split(",")]


def plot_skill(arms, summary, experiment, plant):
    """exp3: per arm, four strips of one point per seed: failures and trials to the first
    success, then to the skill (the actor alone balances); seeds without it are marked."""
    fig, ax = new_figure()
    max_trials = summary.get("max_trials") or 0
    columns = ("failures to\nfirst success", "trials to\nfirst success",
               "failures to\nskill", "trials to\nskill")
    colours = ("tab:blue", "tab:blue", "tab:green", "tab:green")
    ticks, labels = [], []
    for a, arm in enumerate(arms):
        entry = summary["arms"][arm]
        failures = entry.get("failures_before_success", [])
        strips = (failures, [f + 1 for f in failures], entry.get("failures_to_skill", []),
                  entry.get("trials_to_skill", []))
        for c, (values, colour) in enumerate(zip(strips, colours)):
            x = a * (len(columns) + 1) + c
            reached = [v for v in values if v is not None]
            offsets = spread_offsets(reached, 0.6)
            ax.plot([x + dx for dx in offsets], reached, "o", color=colour, alpha=0.7)
            missing = len(values) - len(reached)
            if missing:
                ax.plot([x], [max_trials + 1], "X", color="tab:red", markersize=9)
                ax.annotate(f"{missing} seed(s) never", (x, max_trials + 1), xytext=(6, 0),
                            textcoords="offset points", va="center", color="tab:red",
                            fontsize="small")
            if reached:
                middle = float(np.median(reached))
                ax.hlines(middle, x - 0.3, x + 0.3, color="black", linewidth=2.0)
            ticks.append(x)
            labels.append(columns[c])
        ax.annotate(arm, (a * (len(columns) + 1) + 1.5, 1.02), xycoords=("data", "axes fraction"),
                    ha="center", fontweight="bold")
    ax.set_xticks(ticks, labels, fontsize="small")
    ax.set_ylabel("trials (one point per seed; bar: median)")
    ax.set_title(f"First success and skill: the actor alone balances ({experiment}, {plant} plant)",
                 pad=18)
    ax.grid(True, axis="y", alpha=0.3)
    fig.tight_layout()
    return fig


OSCILLATION_COLUMNS = ("pitch_rms", "pitch_peak_to_peak", "mean_forward_speed")


def read_oscillation(path):
    """exp2's oscillation columns of trials.csv: {trial: {column: [finite values over
    seeds]}} for the trials that lasted past the settle time; None without the columns."""
    with open(path, newline="") as file:
        reader = csv.DictReader(file)
        if not set(OSCILLATION_COLUMNS) <= set(reader.fieldnames or []):
            return None
        by_trial = {}
        for line, row in enumerate(reader, start=2):
            trial = parse_integer(path, line, "trial", row["trial"], 1)
            for name in OSCILLATION_COLUMNS:
                value = parse_number(path, line, name, row[name])
                if math.isfinite(value):
                    by_trial.setdefault(trial, {}).setdefault(name, []).append(value)
    return by_trial


def plot_oscillation(by_trial, stages, seeds, experiment, plant):
    """Per trial, the median over seeds (and range) of the pitch's RMS and peak-to-peak after
    the transient, and of the mean forward speed: does the vibration fade, does it drift."""
    fig, (ax_p, ax_v) = new_figure(ncols=2)
    numbers = sorted(by_trial)
    for ax, names, scale, unit in ((ax_p, ("pitch_rms", "pitch_peak_to_peak"), 1000.0, "mrad"),
                                   (ax_v, ("mean_forward_speed",), 1.0, "m/s")):
        for name in names:
            present = [n for n in numbers if by_trial[n].get(name)]
            values = [[v * scale for v in by_trial[n][name]] for n in present]
            (line,) = ax.plot(present, [float(np.median(v)) for v in values], "o-",
                              markersize=3.5, label=name.replace("_", " ") + " (median)")
            ax.fill_between(present, [min(v) for v in values], [max(v) for v in values],
                            color=line.get_color(), alpha=0.18, linewidth=0)
        ax.set_ylabel(unit)
        ax.set_xlabel("trial")
        ax.grid(True, alpha=0.3)
        for from_trial, _ in stages:
            if from_trial > 1:
                ax.axvline(from_trial - 0.5, color="0.6", linestyle=":", linewidth=1.0)
        if stages:
            top = ax.secondary_xaxis("top")
            top.set_xticks([f for f, _ in stages], [f"{k1:g}" for _, k1 in stages], fontsize=8)
            top.set_xlabel("annealing factor k1 from this trial", fontsize=8)
        ax.legend(loc="best", fontsize="small")
    ax_v.axhline(0.0, color="0.4", linewidth=0.8)
    ax_p.set_title("Pitch oscillation after the transient")
    ax_v.set_title("Mean forward speed after the transient")
    fig.suptitle(f"Does the oscillation fade? ({experiment}, {plant} plant, range over {seeds} "
                 "seeds shaded)")
    return fig


def draw_exp2(save, summary, trials, pitch_path, failure_angle, stages, experiment,
              plant, trials_path=None):
    arms = [arm for arm in arms_in_order(summary, trials) if any(t.arm == arm for t in trials)]
    save(plot_temperature_entropy(arms, trials, summary, stages, experiment, plant),
         "temperature_entropy.png")
    oscillation = read_oscillation(trials_path) if trials_path else None
    if oscillation:
        seeds = len({t.seed for t in trials})
        save(plot_oscillation(oscillation, stages, seeds, experiment, plant), "oscillation.png")
    choices = {}
    for arm in arms:
        seed = first_seed(summary, trials, arm)
        by_number = {t.trial: t for t in trials_of(trials, arm, seed)}
        choices[arm] = (seed, by_number, *early_late_trials(by_number))
    wanted = {(arm, seed, n) for arm, (seed, _, early, late) in choices.items()
              for n in early + late}
    pitch = read_pitch(pitch_path, wanted)
    if pitch is None:
        note(f"{pitch_path} absent (tick logging off): pitch figures skipped")
        return
    for arm, (seed, by_number, early, late) in choices.items():
        name = ("pitch_early_late.png" if len(arms) == 1
                else f"pitch_early_late_{file_name_part(arm)}.png")
        missing = [n for n in early + late if (arm, seed, n) not in pitch]
        if len(missing) == len(early + late):
            note(f"{pitch_path} has no rows for arm {arm} seed {seed}: {name} skipped")
            continue
        if missing:
            note(f"{pitch_path} has no rows for arm {arm} seed {seed} trial(s) "
                 f"{', '.join(map(str, missing))}")
        save(plot_pitch_early_late(arm, seed, early, late, by_number, pitch,
                                   failure_angle, stages, plant), name)


# What cbbg's temporaries and manifests are called (the C++ store's output discipline).
TEMPORARY_TAG = ".cbbg-tmp-"
MANIFEST = ".cbbg-written"
MANIFEST_HEADER = "cbbg-written 1"


def temporary_name(folder, name):
    """A hidden name beside `name` that marks it as cbbg's temporary (removed on resume)."""
    identity = f"{os.getpid()}.{process_start(os.getpid())}"
    return os.path.join(folder, f".{name}{TEMPORARY_TAG}{socket.gethostname()}-{identity}-0")


def write_atomically(path, write):
    """write(temporary path), then the rename: a reader never sees half a file. The temporary
    has cbbg's temporary name, so a run after a kill removes what the kill left."""
    temporary = temporary_name(os.path.dirname(path), os.path.basename(path))
    try:
        write(temporary)
        os.chmod(temporary, 0o644)
        os.replace(temporary, path)
    except BaseException:
        if os.path.exists(temporary):
            os.unlink(temporary)
        raise


def study_report_main(argv, program, marker, script, name, read_study, report, figure):
    """A study report's command line: `program DIR` reads the study (read_study(DIR)), and
    publishes report(study) and figure(study) as NAME.md and NAME.png (publish_study_report).
    Returns the exit status: 2 for a wrong call or a study it cannot read (one line)."""
    if len(argv) != 2:
        print(f"usage: {program} DIR", file=sys.stderr)
        return 2
    directory = argv[1]
    try:
        study = read_study(directory)
        table = report(study)
    except InputError as error:
        print(f"{program}: {error}", file=sys.stderr)
        return 2
    return publish_study_report(program, directory, marker, script, name, table,
                                lambda: figure(study))


def publish_study_report(program, directory, marker, script, name, table, make_figure):
    """A study report's NAME.md (`table`) and NAME.png (make_figure()) in `directory`, each
    atomically, replacing them only in a folder `script` marked with `marker`; the table on
    stdout. Returns the exit status: 0, 2 (outputs not the study's), 1 (not written)."""
    outputs = [os.path.join(directory, f"{name}.{kind}") for kind in ("md", "png")]
    made_here = os.path.isfile(os.path.join(directory, marker))
    for path in outputs:
        if os.path.exists(path) and not made_here:
            print(f"{program}: {path} exists and this is not a study of {script}: move it away "
                  "first", file=sys.stderr)
            return 2
    remove_stale_temporaries(directory, [os.path.basename(path) for path in outputs])

    def write_table(path):
        with open(path, "w", encoding="utf-8") as file:
            file.write(table)

    try:
        write_atomically(outputs[0], write_table)
        fig = make_figure()
        write_atomically(outputs[1], lambda path: fig.savefig(path, format="png"))
    except OSError as error:
        print(f"{program}: {directory}: cannot write the report ({error.strerror})",
              file=sys.stderr)
        return 1
    sys.stdout.write(table)
    return 0


def remove_stale_temporaries(folder, names):
    """Remove the temporaries of `names` in `folder` that a killed process of this host left."""
    for entry in os.listdir(folder):
        for name in names:
            prefix = f".{name}{TEMPORARY_TAG}{socket.gethostname()}-"
            if entry.startswith(prefix) and writer_gone(entry[len(prefix):].rsplit("-", 1)[0]):
                path = os.path.join(folder, entry)
                shutil.rmtree(path) if os.path.isdir(path) else os.unlink(path)


def process_stat(pid):
    """(state, start in clock ticks after boot) of process `pid` from /proc, or None."""
    try:
        with open(f"/proc/{pid}/stat", encoding="utf-8", errors="replace") as stat:
            fields = stat.read().rsplit(")", 1)[1].split()
    except (OSError, IndexError):
        return None
    return fields[0], fields[19]


def process_start(pid):
    stat = process_stat(pid)
    return stat[1] if stat else "0"


def writer_gone(identity):
    """Whether the writer "PID.START" (or "PID", as older names hold) of a temporary is gone:
    no such process, a zombie, or a later process that took its pid (another start)."""
    pid, _, start = identity.partition(".")
    if not pid.isdigit():
        return False
    stat = process_stat(int(pid))
    if stat is None:
        return True
    state, started = stat
    return state in ("Z", "X") or (start != "" and start != started)


def read_manifest(folder):
    """The names cbbg wrote into `folder`, as its manifest lists them (none: empty)."""
    try:
        with open(os.path.join(folder, MANIFEST), encoding="utf-8") as f:
            lines = f.read().splitlines()
    except FileNotFoundError:
        return []
    return lines[1:] if lines and lines[0] == MANIFEST_HEADER else []


def write_manifest(folder, names):
    path = os.path.join(folder, MANIFEST)
    temporary = temporary_name(folder, MANIFEST)
    with open(temporary, "w", encoding="utf-8") as f:
        f.write("".join(line + "\n" for line in [MANIFEST_HEADER] + names))
    os.replace(temporary, path)


def publish_figures(staging, final, names):
    """Move the staged figures into `final`, never over a file that cbbg did not write."""
    if os.path.lexists(final) and (not os.path.isdir(final) or os.path.islink(final)):
        raise InputError(final, "exists and is not a folder; move it away")
    os.makedirs(final, exist_ok=True)
    listed = read_manifest(final)
    for name in names:
        target = os.path.join(final, name)
        if os.path.lexists(target) and name not in listed:
            raise InputError(target, "exists and cbbg did not write it; cbbg never replaces a "
                             "file of yours: move it away")
    # Listed before they arrive, so a kill never leaves a figure of cbbg's unlisted.
    write_manifest(final, listed + [name for name in names if name not in listed])
    for name in names:
        os.replace(os.path.join(staging, name), os.path.join(final, name))


def read_sweep(path):
    """sweep.csv: (the swept keys, the headline's name, its rows as dicts)."""
    with open(path, newline="") as file:
        reader = csv.DictReader(file)
        header = reader.fieldnames or []
        rows = list(reader)
    if "arm" not in header or not header or header[0] != "point":
        raise InputError(path, "is not a sweep.csv (its header starts point,<keys>,arm,...)")
    keys = header[1:header.index("arm")]
    medians = [name for name in header if name.endswith("_median")]
    if not medians:
        raise InputError(path, "has no <figure>_median column")
    headline = medians[0][:-len("_median")]
    for line, row in enumerate(rows, start=2):
        for suffix in ("_median", "_min", "_max"):
            parse_number(path, line, headline + suffix, row[headline + suffix])
        if row.get("balance_rate"):
            parse_number(path, line, "balance_rate", row["balance_rate"])
    return keys, headline, rows


def read_figures(path):
    """figures.csv (a protocol's own per-seed figures): (the figures' names, the rows as
    dicts of numbers, None where a seed has none, with their arm and seed)."""
    f, reader, column, width = open_csv(path, ["arm", "seed"], optional_file=False)
    names = [name for name in column if name not in ("arm", "seed")]
    rows = []
    with f:
        try:
            for row in reader:
                line = reader.line_num
                if len(row) != width:
                    raise InputError(path, f"line {line}: expected {width} fields, got {len(row)}")
                parsed = {"arm": row[column["arm"]], "seed": row[column["seed"]]}
                for name in names:
                    text = row[column[name]]
                    parsed[name] = parse_number(path, line, name, text) if text else None
                rows.append(parsed)
        except (csv.Error, UnicodeDecodeError) as error:
            raise InputError(path, f"line {reader.line_num}: unreadable ({error})")
    return names, rows


def seed_figure_bars(names, rows):
    """(bar labels, {arm: values}) of figures.csv: a rate balanced@C / evaluated@C for each
    condition C of the pairs, and the mean over the seeds of every other figure."""
    arms = list(dict.fromkeys(row["arm"] for row in rows))
    labels, values = [], {arm: [] for arm in arms}
    for name in names:
        if name.startswith("evaluated@") and "balanced@" + name[len("evaluated@"):] in names:
            continue
        rate_of = "evaluated@" + name[len("balanced@"):] if name.startswith("balanced@") else None
        labels.append(name[len("balanced@"):] if rate_of in names else name)
        for arm in arms:
            picked = [row for row in rows if row["arm"] == arm and row[name] is not None]
            total = sum(row[name] for row in picked)
            if rate_of in names:
                runs = sum(row[rate_of] for row in picked)
                values[arm].append(total / runs if runs else float("nan"))
            else:  # the mean of the seeds that have one
                values[arm].append(total / len(picked) if picked else float("nan"))
    return labels, values


def plot_seed_figures(names, rows, experiment, plant):
    """figures.png: each of the protocol's own figures per arm, side by side."""
    labels, values = seed_figure_bars(names, rows)
    fig, ax = new_figure()
    fig.set_size_inches(max(FIGURE_SIZE[0], 0.45 * len(labels) * max(len(values), 1)),
                        FIGURE_SIZE[1] * 1.3)
    width = 0.8 / max(len(values), 1)
    for i, (arm, heights) in enumerate(values.items()):
        ax.bar([x + i * width for x in range(len(labels))], heights, width, label=arm)
    ax.set_xticks([x + 0.4 - width / 2 for x in range(len(labels))], labels, rotation=60,
                  ha="right", fontsize="small")
    rates = any(name.startswith("balanced@") for name in names)
    ax.set_ylabel("balanced runs / runs" if rates else "mean over seeds")
    ax.grid(True, axis="y", alpha=0.3)
    ax.legend(fontsize="small")
    ax.set_title(f"{experiment}: per-seed figures, {plant} plant")
    return fig


def has_balance_rates(rows):
    """Whether sweep.csv's rows carry the evaluation's balance rate (exp1, exp3)."""
    return any(row.get("balance_rate") for row in rows)


def axis_positions(values):
    """x positions of a key's values in grid order: the numbers themselves when all are
    numbers, else 0, 1, 2, ... with the values as labels."""
    try:
        return [float(v) for v in values], None
    except ValueError:
        return list(range(len(values))), values


def sweep_lines(key, keys, rows):
    """The rows of each line of a key's figure: one per arm and values of the other keys,
    each {value of key: row}."""
    others = [k for k in keys if k != key]
    lines = {}
    for row in rows:
        label = row["arm"] + "".join(f", {k}={row[k]}" for k in others)
        lines.setdefault(label, {})[row[key]] = row
    return lines


def draw_sweep_headline(ax, values, positions, lines, headline):
    for label, by_value in lines.items():
        xs = [positions[values.index(v)] for v in values if v in by_value]
        picked = [by_value[v] for v in values if v in by_value]
        median = [float(r[headline + "_median"]) for r in picked]
        low = [float(r[headline + "_min"]) for r in picked]
        high = [float(r[headline + "_max"]) for r in picked]
        (line,) = ax.plot(xs, median, marker="o", label=label)
        ax.fill_between(xs, low, high, color=line.get_color(), alpha=0.15, linewidth=0)


def draw_sweep_balance(ax, values, positions, lines):
    for label, by_value in lines.items():
        picked = [(positions[values.index(v)], by_value[v]) for v in values
                  if v in by_value and by_value[v].get("balance_rate")]
        ax.plot([x for x, _ in picked], [float(r["balance_rate"]) for _, r in picked],
                marker="o", label=label)
    ax.set_ylim(-0.05, 1.05)


def plot_sweep_key(key, keys, headline, rows, plant):
    values = list(dict.fromkeys(row[key] for row in rows))
    positions, labels = axis_positions(values)
    lines = sweep_lines(key, keys, rows)
    balance = has_balance_rates(rows)
    fig, axes = new_figure(ncols=2 if balance else 1)
    axes = list(axes) if balance else [axes]
    draw_sweep_headline(axes[0], values, positions, lines, headline)
    seeds = rows[0]["seeds"] if rows else "?"
    axes[0].set_ylabel(headline.replace("_", " ") + f" (median, range over {seeds} seeds)")
    axes[0].set_title("learning")
    if balance:
        fig.set_size_inches(FIGURE_SIZE[0] * 1.5, FIGURE_SIZE[1])
        draw_sweep_balance(axes[1], values, positions, lines)
        axes[1].set_ylabel("balanced runs / runs (seeds x angles)")
        axes[1].set_title("evaluation")
    for ax in axes:
        if labels is not None:
            ax.set_xticks(positions)
            ax.set_xticklabels(labels)
        ax.set_xlabel(key)
        ax.grid(True, alpha=0.3)
        ax.legend(fontsize="small")
    fig.suptitle(f"sweep of {key}, {plant} plant")
    return fig


def run_sweep(results_dir, save):
    sweep_path = os.path.join(results_dir, "sweep.csv")
    keys, headline, rows = read_sweep(sweep_path)
    config = read_config(os.path.join(results_dir, "config.yaml"))
    plant = (config or {}).get("plant.kind") or "unknown"
    for key in keys:
        save(plot_sweep_key(key, keys, headline, rows, plant),
             "sweep_" + re.sub(r"[^A-Za-z0-9_.-]", "_", key) + ".png")


def run(results_dir):
    if os.path.isfile(os.path.join(results_dir, "sweep.csv")):
        return draw_into(results_dir, lambda save: run_sweep(results_dir, save))
    summary_path = os.path.join(results_dir, "summary.json")
    trials_path = os.path.join(results_dir, "trials.csv")
    config_path = os.path.join(results_dir, "config.yaml")
    steps_path = os.path.join(results_dir, "steps.csv")
    if not os.path.isdir(results_dir):
        raise InputError(results_dir, "not a results directory (missing or not a folder)")

    summary = read_summary(summary_path)
    figures_path = os.path.join(results_dir, "figures.csv")
    drawings = drawings_of(results_dir, summary, trials_path, figures_path)
    if not drawings:
        note("the results' schema names no drawing: nothing to draw")
        return None
    trials = read_trials(trials_path) if set(drawings) - {"evaluation", "figures"} else []
    config = read_config(config_path)
    experiment = summary.get("experiment") or (config or {}).get("experiment")
    if not experiment:
        raise InputError(summary_path, 'has no "experiment" (and config.yaml names none)')
    plant = summary.get("plant") or (config or {}).get("plant.kind") or "unknown"
    failure_angle = config_number(config, "trial.failure_angle", config_path)
    stages = annealing_stages(config, config_path)

    def draw(save):
        if "annealing" in drawings:
            draw_exp2(save, summary, trials, steps_path, failure_angle, stages, experiment,
                      plant, trials_path)
        if "pitch" in drawings:
            draw_pitch(save, summary, trials, steps_path, failure_angle, plant)
        if "failures" in drawings:
            draw_failures(save, summary, trials, experiment, plant)
        if "skill" in drawings:
            save(plot_skill(arms_in_order(summary, trials), summary, experiment, plant),
                 "skill.png")
        if "evaluation" in drawings:
            save(plot_evaluation(summary, experiment, plant), "evaluation.png")
        if "figures" in drawings and os.path.isfile(figures_path):
            names, rows = read_figures(figures_path)
            if names:
                save(plot_seed_figures(names, rows, experiment, plant), "figures.png")

    draw_into(results_dir, draw)


def draw_into(results_dir, draw):
    """Runs draw(save) into a staging folder that then replaces DIR/figures."""
    remove_stale_temporaries(results_dir, ["figures"])  # a killed plot's staging folder
    staging = temporary_name(results_dir, "figures")
    os.makedirs(staging, exist_ok=True)
    written = []

    def save(fig, name):
        fig.savefig(os.path.join(staging, name), dpi=FIGURE_DPI)
        plt.close(fig)
        written.append(name)

    final = os.path.join(results_dir, "figures")
    try:
        draw(save)
        publish_figures(staging, final, written)
    finally:
        shutil.rmtree(staging, ignore_errors=True)
    for name in written:
        print(f"wrote {os.path.join(final, name)}")


def main(argv):
    if len(argv) != 2:
        print(f"usage: {os.path.basename(argv[0])} RESULTS_DIR", file=sys.stderr)
        return 2
    if MISSING_MODULE:
        print(f"plot_results.py: {MISSING_MODULE} is not installed for {sys.executable}: "
              "run with /usr/bin/python3 (Debian's python3-numpy, python3-matplotlib)",
              file=sys.stderr)
        return 1
    try:
        run(argv[1])
    except InputError as error:
        print(f"plot_results.py: error: {error}", file=sys.stderr)
        return 2
    except OSError as error:
        # matplotlib writes through a file object: the error may not name the file.
        where = error.filename or os.path.join(argv[1], "figures")
        print(f"plot_results.py: error: cannot write '{where}': {error.strerror or error}",
              file=sys.stderr)
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
