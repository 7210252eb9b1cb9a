#!/usr/bin/python3
"""The states the teacher's pushed runs visit: the PD supervisor balancing the robot from each
evaluation angle while a push from outside acts, as the teacher study's push condition does,
and the largest |value| each measured signal reaches, beside what the paper's feature grid
covers (3 units of normaliser.scale_* each side).

  PYTHONPATH=build/python /usr/bin/python3 scripts/push_envelope.py --plant simbody

Prints a Markdown table (docs/model.md quotes it). Exit status 2 for a bad option.
"""

import argparse
import sys

import numpy as np

import cbbg


def envelope(plant, force, duration, start):
    """Per signal (theta_b, theta_b', phi, phi'), the largest |value| over every evaluation
    angle's run, and the runs that balanced."""
    settings = {"plant.kind": plant, "push.force": force, "push.duration": duration,
                "push.start": start}
    env = cbbg.BalanceEnv(settings)
    angles = list(cbbg.parameters(settings)["evaluation.angles"])
    largest = np.zeros(4)
    balanced = 0
    for angle in angles:
        observation, info = env.reset(seed=1, options={"initial_pitch": angle})
        while True:
            phi = (observation[2] + observation[3]) / 2
            phi_rate = (observation[4] + observation[5]) / 2
            signals = np.abs([observation[0], observation[1], phi, phi_rate])
            largest = np.maximum(largest, signals)
            observation, _, terminated, truncated, info = env.step(info["supervisor_action"])
            if terminated or truncated:
                balanced += int(truncated and not terminated)
                break
    return largest, balanced, len(angles)


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--plant", default="simbody")
    parser.add_argument("--force", type=float, default=74.0, help="N at the centre of mass")
    parser.add_argument("--duration", type=float, default=0.5, help="s")
    parser.add_argument("--start", type=float, default=5.0, help="s")
    args = parser.parse_args(argv)
    try:
        largest, balanced, runs = envelope(args.plant, args.force, args.duration, args.start)
    except (cbbg.ConfigError, ValueError) as error:
        parser.error(str(error))
    defaults = cbbg.parameters({"plant.kind": args.plant})
    grid = 3 * np.array([defaults["normaliser.scale_theta"], defaults["normaliser.scale_dtheta"],
                         defaults["normaliser.scale_phi"], defaults["normaliser.scale_dphi"]])
    print(f"The PD supervisor, {args.force:g} N for {args.duration:g} s from {args.start:g} s, "
          f"plant {args.plant}: {balanced} of {runs} runs balanced.\n")
    print("| signal | largest |value| | the default grid reaches | the grid's scale to cover it |")
    print("|---|---|---|---|")
    names = ("theta_b, rad", "theta_b', rad/s", "phi (mean wheel angle), rad",
             "phi' (mean wheel rate), rad/s")
    for name, value, reach in zip(names, largest, grid):
        print(f"| {name} | {value:.3g} | ±{reach:.3g} | {value / 3:.3g} per unit |")
    return 0


if __name__ == "__main__":
    sys.exit(main())
