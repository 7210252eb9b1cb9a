#!/usr/bin/python3
"""Small synthetic cbbg results directories, in the formats `cbbg run` writes.

Usage: /usr/bin/python3 tests/plot/make_fixtures.py exp1|exp2 DIR   (to look at the figures)

The pitch curves are made up: a failed trial is an oscillation growing until it crosses the
failure angle, a successful one decays over the 20 s; exp2's oscillation shrinks trial by trial
as the annealing factor k1 falls. They are shaped like the paper's, not simulated.
"""

import json
import math
import os
import sys

PERIOD = 0.01  # s, one tick
LOG_EVERY = 5  # ticks: the step log is decimated
DURATION = 20.0  # s, a successful trial
THETA0 = 0.1744  # rad
FAILURE_ANGLE = 0.5236  # rad
ANNEALING = [(1, 10.0), (11, 5.0), (16, 1.0), (21, 0.5), (23, 0.1)]

STEPS_HEADER = ("arm,seed,trial,t,theta_b,dtheta_b,phi_l,phi_r,a_S,a_A,a_E,a,omega,V,delta,"
                "T,reward")
TRIALS_HEADER = "arm,seed,trial,failed,steps,mean_temperature,mean_entropy,final_theta,status"

# exp1: failures before the first success per seed (None: never succeeded), and the trial cap.
EXP1_SEEDS = [1, 2, 3]
EXP1_FAILURES = {"cbbg": [0, 1, 0], "bg_only": [8, None, 5]}
EXP1_MAX_TRIALS = 12


def config_yaml(experiment, arms, seeds, max_trials):
    """A config.yaml shaped like the resolved config the run writes (block style)."""
    annealing = "".join(f"\n  - {{from_trial: {t}, k1: {k1:g}}}" for t, k1 in ANNEALING)
    return (f"experiment: {experiment}\n"
            f"arms: [{', '.join(arms)}]\n"
            f"seeds: {len(seeds)}\n"
            f"seed: {seeds[0]}\n"
            f"max_trials: {max_trials}\n"
            "plant:\n  kind: analytic\n  torque_limit: 5\n"
            f"trial:\n  theta0: {THETA0}\n  duration: {DURATION:g}\n"
            f"  failure_angle: {FAILURE_ANGLE}\n  period: {PERIOD}\n"
            "tropism:\n  k1: 10\n  k2: 0.1\n"
            f"annealing:{annealing}\n")


def pitch_curve(growth, frequency, succeeded):
    """(t, theta_b) samples of a trial: theta0 e^(growth t) cos(2 pi f t) until it fails."""
    samples = []
    tick = 0
    while True:
        t = tick * PERIOD
        theta = THETA0 * math.exp(growth * t) * math.cos(2 * math.pi * frequency * t)
        crossed = abs(theta) > FAILURE_ANGLE
        if tick % LOG_EVERY == 0 or crossed:
            samples.append((t, theta))
        if crossed and not succeeded:
            return samples
        if t >= DURATION - 1e-9:
            return samples
        tick += 1


def step_rows(arm, seed, trial, samples):
    rows = []
    for t, theta in samples:
        a_s = 50 * theta
        rows.append(f"{arm},{seed},{trial},{t:.2f},{theta:.6f},0,0,0,{a_s:.6f},0,0,{a_s:.6f},"
                    "0,0,0,5,0")
    return rows


def write(directory, name, text):
    with open(os.path.join(directory, name), "w", encoding="utf-8") as f:
        f.write(text)


def temperature(k1, trial):
    """T = k1 / (1 + exp(k2 V)) with a critic value V that rises as the robot learns."""
    value = -20.0 + 0.5 * trial
    return k1 / (1 + math.exp(0.1 * value))


def entropy_bits(temperature_value):
    return 0.5 * math.log2(math.pi * math.e * temperature_value)


def make_exp1(directory, with_steps=True):
    """exp1 with arms cbbg and bg_only over 3 seeds; bg_only seed 2 never succeeds."""
    os.makedirs(directory, exist_ok=True)
    arms = list(EXP1_FAILURES)
    trial_rows, steps = [], []
    summary_arms = {}
    for arm_index, arm in enumerate(arms):
        for seed, failures in zip(EXP1_SEEDS, EXP1_FAILURES[arm]):
            trial_count = EXP1_MAX_TRIALS if failures is None else failures + 1
            for trial in range(1, trial_count + 1):
                succeeded = trial == trial_count and failures is not None
                growth = -0.25 if succeeded else 0.6 + 0.1 * arm_index + 0.2 / trial
                samples = pitch_curve(growth, 0.8 + 0.05 * seed, succeeded)
                status = "success" if succeeded else "failed"
                trial_rows.append(f"{arm},{seed},{trial},{0 if succeeded else 1},"
                                  f"{round(samples[-1][0] / PERIOD)},4.5,1.2,"
                                  f"{samples[-1][1]:.6f},{status}")
                steps += step_rows(arm, seed, trial, samples)
        counted = [EXP1_MAX_TRIALS if n is None else n for n in EXP1_FAILURES[arm]]
        ordered = sorted(counted)
        summary_arms[arm] = {
            "failures_before_success": counted,
            "succeeded": [n is not None for n in EXP1_FAILURES[arm]],
            "num_succeeded": sum(n is not None for n in EXP1_FAILURES[arm]),
            "median": ordered[len(ordered) // 2],
            "min": ordered[0],
            "max": ordered[-1],
        }
    summary = {"experiment": "exp1", "plant": "analytic", "max_trials": EXP1_MAX_TRIALS,
               "seeds": EXP1_SEEDS,
               "arms": summary_arms, "paper": {"cbbg": 0, "bg_only": 8}}
    write(directory, "summary.json", json.dumps(summary, indent=2) + "\n")
    write(directory, "trials.csv", "\n".join([TRIALS_HEADER] + trial_rows) + "\n")
    write(directory, "config.yaml", config_yaml("exp1", arms, EXP1_SEEDS, EXP1_MAX_TRIALS))
    if with_steps:
        write(directory, "steps.csv", "\n".join([STEPS_HEADER] + steps) + "\n")


def k1_of_trial(trial):
    return [k1 for from_trial, k1 in ANNEALING if from_trial <= trial][-1]


def make_exp2(directory, seeds=(1, 2), trial_count=25):
    """exp2 of arm cbbg: 25 trials per seed, temperature and entropy falling with k1."""
    os.makedirs(directory, exist_ok=True)
    trial_rows, steps = [], []
    for seed in seeds:
        for trial in range(1, trial_count + 1):
            k1 = k1_of_trial(trial)
            temperature_value = temperature(k1, trial) * (1 + 0.05 * (seed - 1))
            # The oscillation dies out faster as k1, and with it the exploration, falls.
            samples = pitch_curve(-0.05 - 0.6 / (1 + k1), 0.9 + 0.02 * trial, True)
            tail = [theta for t, theta in samples if t >= 5.0] or [samples[-1][1]]
            rms = (sum(theta * theta for theta in tail) / len(tail)) ** 0.5
            trial_rows.append(f"cbbg,{seed},{trial},0,{round(DURATION / PERIOD)},"
                              f"{temperature_value:.6f},{entropy_bits(temperature_value):.6f},"
                              f"{samples[-1][1]:.6f},success,{rms:.6f},"
                              f"{max(tail) - min(tail):.6f},0.01")
            steps += step_rows("cbbg", seed, trial, samples)
    summary = {"experiment": "exp2", "plant": "analytic", "seeds": list(seeds),
               "arms": {"cbbg": {"num_succeeded": len(seeds)}}}
    write(directory, "summary.json", json.dumps(summary, indent=2) + "\n")
    # exp2's trials.csv has the oscillation columns (what the plot tells exp2's results by).
    header = TRIALS_HEADER + ",pitch_rms,pitch_peak_to_peak,mean_forward_speed"
    write(directory, "trials.csv", "\n".join([header] + trial_rows) + "\n")
    write(directory, "config.yaml", config_yaml("exp2", ["cbbg"], list(seeds), 100))
    write(directory, "steps.csv", "\n".join([STEPS_HEADER] + steps) + "\n")


if __name__ == "__main__":
    if len(sys.argv) != 3 or sys.argv[1] not in ("exp1", "exp2"):
        print("usage: make_fixtures.py exp1|exp2 DIR", file=sys.stderr)
        sys.exit(2)
    (make_exp1 if sys.argv[1] == "exp1" else make_exp2)(sys.argv[2])
