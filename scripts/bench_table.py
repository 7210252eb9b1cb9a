#!/usr/bin/env python3
"""Prints the table of scripts/bench.sh from the results it leaves in one folder.

Usage: bench_table.py <folder> <jobs-identical: yes|no> <baseline name>
Benchmarks give medians of their repetitions (CPU time); the main job gives wall times.
"""
import json
import sys
from pathlib import Path


def medians(path):
    """name -> the median aggregate (its CPU time in ns and its counters)."""
    runs = json.loads(path.read_text())["benchmarks"]
    result = {}
    for run in runs:
        if run.get("run_type") == "aggregate" and run.get("aggregate_name") == "median":
            scale = {"ns": 1.0, "us": 1e3, "ms": 1e6, "s": 1e9}[run["time_unit"]]
            name = run["run_name"].split("/min_time:")[0]  # MinTime() suffixes the name
            result[name] = dict(run, cpu_ns=run["cpu_time"] * scale)
    return result


def walls(path):
    times = {}
    for line in path.read_text().splitlines():
        name, start, end = line.split()
        times[name] = float(end) - float(start)
    return times


def fixed_tick_ns(framework):
    return framework["BM_Diagram/1"]["cpu_ns"] - framework["BM_PlainLoop/1"]["cpu_ns"]


def main():
    folder, identical, baseline = Path(sys.argv[1]), sys.argv[2], sys.argv[3]
    framework = medians(folder / "framework.json")
    diagrams = medians(folder / "diagrams.json")
    plant = medians(folder / "plant.json")["BM_SimbodyConfigurations"]
    times = walls(folder / "times")
    rows = []

    old_us = plant["constrained_merson_us_per_step"]
    new_us = plant["rolling_merson_us_per_step"]
    rows.append(("Simbody plant, 10 ms step: rolling ÷ constrained model (merson)",
                 f"{new_us:.0f} µs vs {old_us:.0f} µs", f"{old_us / new_us:.2f}× faster", "≥ 3×"))
    for trial, schedule, goal in (("BM_DiagramTrial", "compiled", "≤ 1.10"),
                                  ("BM_DiagramTrialInterpreted", "interpreted", "")):
        diagram = diagrams[trial]["cpu_ns"] / diagrams["BM_PlainLoopTrial"]["cpu_ns"]
        per_tick = diagrams[trial]["cpu_per_tick"] * 1e6
        rows.append((f"`cbbg` diagram ÷ hand-written loop (analytic plant), {schedule} schedule",
                     f"{per_tick:.2f} µs per tick", f"{diagram:.2f}", goal))
    for chain, schedule, goals in (("BM_Diagram", "compiled", "≤ 4 / 1.6 / 1.3"),
                                   ("BM_DiagramOfLambdas", "compiled, lambdas", ""),
                                   ("BM_DiagramInterpreted", "interpreted", "")):
        if f"{chain}/1" not in framework:
            continue
        ratios = [framework[f"{chain}/{n}"]["cpu_ns"] / framework[f"BM_PlainLoop/{n}"]["cpu_ns"]
                  for n in (1, 10, 100)]
        nanoseconds = [framework[f"{chain}/{n}"]["cpu_ns"] for n in (1, 10, 100)]
        rows.append((f"chain of 1 / 10 / 100 blocks ÷ plain loop, {schedule} schedule",
                     " / ".join(f"{ns:.0f} ns" for ns in nanoseconds),
                     " / ".join(f"{r:.2f}" for r in ratios), goals))
    fixed = fixed_tick_ns(framework)
    if (folder / "baseline_framework.json").exists():
        old_fixed = fixed_tick_ns(medians(folder / "baseline_framework.json"))
        rows.append((f"framework fixed cost per tick (chain of 1), vs {baseline[:7]}",
                     f"{fixed:.1f} ns vs {old_fixed:.1f} ns", f"{fixed / old_fixed:.2f}", ""))
        old = medians(folder / "baseline_diagrams.json")
        old_ratio = old["BM_DiagramTrial"]["cpu_ns"] / old["BM_PlainLoopTrial"]["cpu_ns"]
        rows.append((f"`cbbg` diagram ÷ hand-written loop at {baseline[:7]}", "", f"{old_ratio:.2f}",
                     ""))
    else:
        rows.append(("framework fixed cost per tick (chain of 1 ÷ its plain loop)", f"{fixed:.1f} ns",
                     f"{framework['BM_Diagram/1']['cpu_ns'] / framework['BM_PlainLoop/1']['cpu_ns']:.1f}",
                     ""))
    scaling = times["jobs1"] / times["jobs2"]
    rows.append(("main job (exp1, Simbody, 20 seeds): `--jobs 2` ÷ `--jobs 1`",
                 f"{times['jobs2']:.1f} s vs {times['jobs1']:.1f} s; same bytes: {identical}",
                 f"{scaling:.2f}× faster", "≥ 1.8×"))
    main_job = times["baseline_main"] / times["jobs2"]
    what = f"at {baseline[:7]}" if baseline != "constrained" else "with plant.simbody_model=constrained"
    same = dict(line.split() for line in (folder / "same_as_baseline").read_text().splitlines())
    rows.append((f"main job on 2 threads ÷ the same {what}",
                 f"{times['jobs2']:.1f} s vs {times['baseline_main']:.1f} s"
                 + (f"; same bytes: {same['main']}" if "main" in same else ""),
                 f"{main_job:.2f}× faster", ""))
    if "analytic" in times:
        analytic = times["baseline_analytic"] / times["analytic"]
        rows.append((f"exp1 on the analytic plant, 2 threads ÷ the same {what}",
                     f"{times['analytic']:.1f} s vs {times['baseline_analytic']:.1f} s; "
                     f"same bytes: {same['analytic']}", f"{analytic:.2f}× faster", ""))

    print("\n| ratio | measured | ratio | goal |\n|---|---|---|---|")
    for row in rows:
        print("| " + " | ".join(row) + " |")
    print("\nSimbody configurations, in alternating slices of one run (medians of 3):\n")
    print("| model, integrator | CPU per step | ÷ constrained, merson | heap allocations per step |"
          " pitch error after 3 s |\n|---|---|---|---|---|")
    for name in ("constrained_merson", "rolling_merson", "rolling_rk3", "rolling_verlet"):
        model, integrator = name.split("_")
        print(f"| {model}, {integrator} | {plant[name + '_us_per_step']:.0f} µs"
              f" | {plant[name + '_over_baseline']:.3f} | {plant[name + '_allocs_per_step']:.0f}"
              f" | {plant[name + '_pitch_error_rad']:.1e} rad |")


if __name__ == "__main__":
    main()
