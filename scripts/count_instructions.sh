#!/usr/bin/env bash
# Instructions per tick of the framework, counted by callgrind: unlike timings they repeat
# from run to run, whatever else the machine does. Prints a table for this tree's build:
#  - the cbbg diagram's trial (analytic plant) on each schedule, and the hand-written loop;
#  - a chain of one block closed by a hold (the fixed cost of a tick) on each schedule.
#
#   scripts/count_instructions.sh [BUILD_DIR]     # default: build/; an earlier commit's
#                                                  # build (bench.sh --against) works too
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${1:-$root/build}"
command -v valgrind >/dev/null || { echo "count_instructions.sh: needs valgrind" >&2; exit 1; }
out="$(mktemp -d "${TMPDIR:-/tmp}/cbbg-count.XXXXXX")"
trap 'rm -rf "$out"' EXIT

# per_call <binary> <benchmark filter> <function>: inclusive instructions per call of the
# function (its calls summed over the whole run, so setup outside it does not count); nan
# where the binary has no such benchmark (an earlier build, before the interpreted one was
# kept beside the compiled schedule).
per_call() {
  valgrind --tool=callgrind --callgrind-out-file="$out/callgrind.out" --toggle-collect="$3*" \
    "$1" --benchmark_filter="$2" --benchmark_min_time=0.3 >/dev/null 2>&1
  /usr/bin/python3 - "$out/callgrind.out" "$3" <<'EOF'
import re, sys
text = open(sys.argv[1]).read()
names = dict(re.findall(r"^c?fn=\((\d+)\) (.*)$", text, re.M))
calls = sum(int(n) for fn, n in re.findall(r"^cfn=\((\d+)\).*\ncalls=(\d+)", text, re.M)
            if names.get(fn, "").startswith(sys.argv[2]))
total = int(re.search(r"^summary: (\d+)", text, re.M).group(1))
print(total / calls if calls else float("nan"))
EOF
}

diagrams="$build/bench/diagrams/bench_diagrams"
framework="$build/bench/framework/bench_framework"
"$diagrams" --benchmark_filter='BM_PlainLoopTrial' --benchmark_min_time=0.01 \
  --benchmark_out="$out/ticks.json" --benchmark_out_format=json >/dev/null 2>&1
ticks="$(/usr/bin/python3 -c 'import json,sys; print(int(json.load(open(sys.argv[1]))["benchmarks"][0]["ticks"]))' \
  "$out/ticks.json")"

trial=cbbg::experiments::TrialRunner::run_trial
compiled="$(per_call "$diagrams" 'BM_DiagramTrial$' "$trial")"
interpreted="$(per_call "$diagrams" 'BM_DiagramTrialInterpreted' "$trial")"
plain="$(per_call "$diagrams" 'BM_PlainLoopTrial' cbbg::tests::PlainLoop::run_trial)"
chain_compiled="$(per_call "$framework" 'BM_Diagram/1$' cbbg::Simulator::advance_to)"
chain_interpreted="$(per_call "$framework" 'BM_DiagramInterpreted/1$' cbbg::Simulator::advance_to)"

/usr/bin/python3 - "$ticks" "$compiled" "$interpreted" "$plain" "$chain_compiled" \
  "$chain_interpreted" <<'EOF'
import sys
ticks, compiled, interpreted, plain, chain_c, chain_i = map(float, sys.argv[1:])
print(f"\n| instructions per tick (callgrind) | interpreted | compiled | hand-written loop |")
print("|---|---|---|---|")
print(f"| `cbbg` diagram, analytic plant ({ticks:.0f}-tick trial) | {interpreted / ticks / 1e3:.2f} k"
      f" | {compiled / ticks / 1e3:.2f} k | {plain / ticks / 1e3:.2f} k |")
print(f"| chain of 1 block and a hold (`Simulator::advance_to`) | {chain_i:.0f} | {chain_c:.0f} | |")
EOF
