"""What Python costs: a block written in Python against the same block in C++, per tick, and
the environment's steps per second against a NumPy-only step of the same robot. Everything in
one run on one machine; the table is what docs/python.md shows (scripts/bench_python.sh).

usage: bench_python.py [--repeats N]
"""

import argparse
import os
import sys
import time

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(__file__), os.pardir, os.pardir, "python",
                                "examples"))
import cbbg  # noqa: E402
import two_wheeler  # noqa: E402
from pd_supervisor import PdSupervisor as PdInPython  # noqa: E402


def best_interleaved(repeats, runs):
    """The fastest of `repeats` runs of each of `runs`, s each. The runs take turns, round by
    round, so a slow spell of this shared machine slows each of them alike."""
    best = [float("inf")] * len(runs)
    for _ in range(repeats):
        for index, run in enumerate(runs):
            start = time.perf_counter()
            run()
            best[index] = min(best[index], time.perf_counter() - start)
    return best


def block_run(make_block, ticks):
    """A run of `ticks` ticks of a diagram: a 6-signal sine source, the block, a 10 ms hold."""
    builder = cbbg.DiagramBuilder("bench")
    source = builder.add(cbbg.SineSource("source", [0.1] * 6, [1.0] * 6, [0.0] * 6, [0.0] * 6))
    block = builder.add(make_block())
    hold = builder.add(cbbg.ZeroOrderHold("hold", 1, 0.01))
    builder.connect(source.output_port("y"), block.input_port("measured"))
    builder.connect(block.output_port("action"), hold.input_port("u"))
    builder.export_output(hold.output_port("y"), "held")
    diagram = builder.build()

    return lambda: cbbg.Simulator(diagram).advance_to(ticks * 0.01)


def closed_loop_run(supervisor_slot, ticks):
    """A pd_only trial of `ticks` ticks on the analytic plant, the supervisor from the slot."""
    parameters = cbbg.parameters({"plant.kind": "analytic", "trial.duration": ticks * 0.01})
    options = cbbg.preset("pd_only").options
    options.slots.supervisor = supervisor_slot
    arm = cbbg.make_arm("pd", options)

    def run():
        loop = arm.learner(parameters)
        context = loop.diagram.create_context(1)
        loop.start_trial(context, 0.1)
        cbbg.Simulator(loop.diagram, context).advance_to(ticks * 0.01)

    return run


def environment_run(plant_kind, steps):
    """An episode of `steps` steps, the actions the supervisor's."""
    env = cbbg.BalanceEnv({"plant.kind": plant_kind, "trial.duration": steps * 0.01})

    def run():
        observation, info = env.reset(seed=1)
        for _ in range(steps):
            observation, reward, terminated, truncated, info = env.step(info["supervisor_action"])

    return run


def pd_action(y, gains=(50.0, 10.0, 1.0, 1.0)):
    return (gains[0] * y[0] + gains[1] * y[1] + gains[2] * (y[2] + y[3]) / 2.0
            + gains[3] * (y[4] + y[5]) / 2.0)


def numpy_rollout(steps, substeps):
    """The same robot under the same law, stepped by NumPy alone (RK4): its pitch per tick."""
    params = two_wheeler.RobotParams()
    x = np.zeros(9)
    x[0] = 0.1744
    pitch = [x[0]]
    for _ in range(steps - 1):
        action = pd_action(two_wheeler.signals_of(params, x))
        x = two_wheeler.step(params, x, np.array([action, action]), substeps=substeps)
        pitch.append(x[0])
    return np.array(pitch)


def environment_pitch(steps):
    env = cbbg.BalanceEnv({"plant.kind": "analytic"})
    observation, info = env.reset(seed=1)
    pitch = [info["state"][0]]
    for _ in range(steps - 1):
        observation, reward, terminated, truncated, info = env.step(info["supervisor_action"])
        pitch.append(info["state"][0])
    return np.array(pitch)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--repeats", type=int, default=3)
    args = parser.parse_args()
    r = args.repeats

    ticks = 20000
    cpp_block, py_block = [t / ticks for t in best_interleaved(r, [
        block_run(lambda: cbbg.PdSupervisor("pd", cbbg.PdSupervisorParams()), ticks),
        block_run(lambda: PdInPython("pd"), ticks)])]
    ticks = 2000
    cpp_loop, py_loop = [t / ticks for t in best_interleaved(r, [
        closed_loop_run(None, ticks), closed_loop_run(PdInPython, ticks)])]
    # The NumPy baseline at its cheapest: one RK4 step per 10 ms, as accurate as the C++
    # plant's integrator is asked to be (its deviation from the environment's pitch is shown).
    analytic, simbody, numpy_only = [steps / t for steps, t in zip((2000, 500, 2000), best_interleaved(r, [
        environment_run("analytic", 2000), environment_run("simbody", 500),
        lambda: numpy_rollout(2000, substeps=1)]))]
    deviation = np.max(np.abs(numpy_rollout(2000, 1) - environment_pitch(2000)))

    print("| what | C++ | Python | Python / C++ |")
    print("|---|---|---|---|")
    print(f"| a PD block's diagram (source, block, hold), per tick | {cpp_block * 1e6:.2f} us "
          f"| {py_block * 1e6:.2f} us | {py_block / cpp_block:.1f} |")
    print(f"| the pd_only trial on the analytic plant, per tick | {cpp_loop * 1e6:.2f} us "
          f"| {py_loop * 1e6:.2f} us | {py_loop / cpp_loop:.2f} |")
    print(f"| the Python block's own cost per tick | | {(py_block - cpp_block) * 1e6:.2f} us | |")
    print()
    print("| environment, PD actions from info | steps/s | / NumPy-only |")
    print("|---|---|---|")
    print(f"| cbbg.BalanceEnv, analytic plant | {analytic:,.0f} | {analytic / numpy_only:.1f} |")
    print(f"| cbbg.BalanceEnv, Simbody plant | {simbody:,.0f} | {simbody / numpy_only:.2f} |")
    print(f"| NumPy-only analytic step (one RK4 step of 10 ms) | {numpy_only:,.0f} | 1.0 |")
    print()
    print(f"The NumPy rollout's pitch is within {deviation:.1e} rad of the environment's over the "
          "20 s trial.")


if __name__ == "__main__":
    main()
