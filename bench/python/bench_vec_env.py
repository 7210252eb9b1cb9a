"""The vectorised environment's steps per second: cbbg.VecBalanceEnv stepping N robots in
C++ threads per call, against the same N robots as N cbbg.BalanceEnv stepped one by one from
Python, for N = 1, 16, 64, 256 and each plant kind built (analytic, Simbody, MuJoCo). The
actions are the supervisor's (info["supervisor_action"]), so every robot balances and no
episode ends. The runs of each comparison take turns, best of --repeats each.

usage: bench_vec_env.py [--repeats N] [--kinds analytic,simbody,mujoco] [--sizes 1,16,64,256]
"""

import argparse
import os

import cbbg
from bench_python import best_interleaved  # the runs take turns, best of each

# Steps of one measured run, per plant kind: about a second each on this machine.
STEPS = {"analytic": 400_000, "simbody": 30_000, "mujoco": 100_000}
LONG = 1e6  # trial.duration, s: no episode is truncated while measured


def settings(kind):
    return {"plant.kind": kind, "trial.duration": LONG}


def vector_run(kind, n, calls):
    envs = cbbg.VecBalanceEnv(n, settings(kind))
    _, infos = envs.reset(seed=1)

    def run():
        nonlocal infos
        for _ in range(calls):
            _, _, _, _, infos = envs.step(infos["supervisor_action"])

    return run


def singles_run(kind, n, calls):
    envs = [cbbg.BalanceEnv(settings(kind)) for _ in range(n)]
    infos = [env.reset(seed=1 + i)[1] for i, env in enumerate(envs)]

    def run():
        for _ in range(calls):
            for i, env in enumerate(envs):
                infos[i] = env.step(infos[i]["supervisor_action"])[4]

    return run


def built(kind):
    try:
        cbbg.parameters(settings(kind))
        return True
    except ValueError:
        return False


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--repeats", type=int, default=3)
    parser.add_argument("--kinds", default="analytic,simbody,mujoco")
    parser.add_argument("--sizes", default="1,16,64,256")
    args = parser.parse_args()
    print(f"cores: {os.cpu_count()}; threads: the machine's (at most N); best of {args.repeats}")
    print("| plant | N | VecBalanceEnv, steps/s | N BalanceEnv from Python, steps/s | ratio |")
    print("|---|---|---|---|---|")
    for kind in args.kinds.split(","):
        if not built(kind):
            print(f"| {kind} | not built | | | |")
            continue
        for n in (int(size) for size in args.sizes.split(",")):
            calls = max(1, STEPS[kind] // n)
            vector, singles = best_interleaved(
                args.repeats, [vector_run(kind, n, calls), singles_run(kind, n, calls)])
            steps = n * calls
            print(f"| {kind} | {n} | {steps / vector:,.0f} | {steps / singles:,.0f} | "
                  f"{singles / vector:.1f} |", flush=True)


if __name__ == "__main__":
    main()
