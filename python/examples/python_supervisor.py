"""docs/python.md's example: the CB-BG controller with a supervisor written in
Python, experiment 1 over 5 seeds beside the preset with the C++ PD, and each arm's failures
before the first success plotted with matplotlib.

usage: /usr/bin/python3 python_supervisor.py [--plant simbody|analytic] [--out failures.png]
"""

import argparse
import os
import sys

import matplotlib

matplotlib.use("Agg")  # a file, no window
import matplotlib.pyplot as plt  # noqa: E402

import cbbg  # noqa: E402


# [docs lean-supervisor]
class LeanSupervisor(cbbg.LeafBlock):
    """A supervisor of the user's: the PD law on pitch and pitch rate alone (no wheel terms)."""

    def __init__(self, name, parameters):
        super().__init__(name)
        self.k_theta = parameters["supervisor.k_theta"]
        self.k_dtheta = parameters["supervisor.k_dtheta"]
        self.measured = self.declare_input_port("measured", 6, "the sensors' six signals")
        self.declare_output_port("action", 1, self.calc_action, reads=[self.measured])

    def calc_action(self, context, action):
        pitch, pitch_rate = context.input(self.measured)[:2]
        action[0] = self.k_theta * pitch + self.k_dtheta * pitch_rate
# [docs lean-supervisor end]


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--plant", default="simbody", choices=cbbg.plant_kinds())
    parser.add_argument("--out", default="failures.png")
    args = parser.parse_args()
    if os.path.exists(args.out):
        print(f"python_supervisor.py: '{args.out}' exists; give another --out (it is not replaced)",
              file=sys.stderr)
        sys.exit(2)

    # [docs python-exp1]
    options = cbbg.preset("cbbg").options
    options.slots.supervisor = LeanSupervisor  # called as LeanSupervisor(name, parameters)
    arms = [cbbg.make_arm("cbbg_lean", options), cbbg.preset_arm("cbbg")]
    parameters = cbbg.parameters({"plant.kind": args.plant, "seeds": 5})
    results = cbbg.run_exp1(parameters, arms, jobs=2)

    figure, axes = plt.subplots(figsize=(5, 3))
    for index, arm in enumerate(results.arms):
        failures = [results.run(index, s).failures_before_success for s in range(len(results.seeds))]
        print(f"{arm:10s} failures before the first success, seeds {results.seeds}: {failures}")
        axes.plot(results.seeds, failures, "o-", label=arm)
    # [docs python-exp1 end]
    axes.set_xticks(results.seeds)
    axes.yaxis.get_major_locator().set_params(integer=True)
    axes.set_xlabel("seed")
    axes.set_ylabel("failures before success")
    axes.set_title(f"exp1, {args.plant} plant")
    axes.legend()
    figure.tight_layout()
    figure.savefig(args.out, dpi=100)
    print(f"plot in {args.out}")


if __name__ == "__main__":
    main()
