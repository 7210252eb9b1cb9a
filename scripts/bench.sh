#!/usr/bin/env bash
# Builds and runs the benchmarks, then prints the table of ratios that docs/performance.md
# shows. Every ratio is measured in this one run, against a baseline run
# in it too.
#
#   scripts/bench.sh                      # this tree: every ratio it can measure alone
#   scripts/bench.sh --against <commit>   # also builds <commit> (a git archive of it, in
#                                         # build/bench-baseline/) and compares the framework's
#                                         # fixed tick cost and the main job with it
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
against=""
if [[ "${1:-}" == "--against" ]]; then
  [[ $# -ge 2 ]] || { echo "bench.sh: --against needs a commit" >&2; exit 2; }
  against="$(git -C "$root" rev-parse --verify --quiet "$2^{commit}")" ||
    { echo "bench.sh: --against: '$2' is not a commit of this repository" >&2; exit 2; }
fi

"$root/scripts/build.sh" >/dev/null
out="$(mktemp -d "${TMPDIR:-/tmp}/cbbg-bench.XXXXXX")"
trap 'rm -rf "$out"' EXIT

# The baseline tree: extracted and built once per commit (baseline_tree.sh).
baseline=""
if [[ -n "$against" ]]; then
  baseline="$("$root/scripts/baseline_tree.sh" "$against" bench_framework bench_diagrams cbbg)"
fi

bench() {  # bench <name> <binary> <args...>: the binary's results as JSON in $out/<name>.json
  local name="$1" binary="$2"
  shift 2
  echo "== $name" >&2
  "$binary" --benchmark_out="$out/$name.json" --benchmark_out_format=json "$@" >&2
}
# wall <name> <command...>: the command's wall time in seconds, in $out/times
wall() {
  local name="$1" start end
  shift
  echo "== $name: $*" >&2
  start="$(date +%s.%N)"
  "$@" >/dev/null
  end="$(date +%s.%N)"
  echo "$name $start $end" >> "$out/times"
}

b="$root/build/bench"
bench framework "$b/framework/bench_framework" --benchmark_repetitions=5
bench diagrams "$b/diagrams/bench_diagrams" --benchmark_repetitions=5
bench plant "$b/plant/bench_plant" --benchmark_repetitions=3 \
  --benchmark_filter='Configurations|DiagramOverPlainLoop|AnalyticPlantStep'
bench policy_export "$b/codegen/bench_policy_export" --benchmark_repetitions=3
if [[ -n "$baseline" ]]; then
  bench baseline_framework "$baseline/build/bench/framework/bench_framework" \
    --benchmark_repetitions=5 --benchmark_filter='/1$'
  bench baseline_diagrams "$baseline/build/bench/diagrams/bench_diagrams" \
    --benchmark_repetitions=5
fi

# The main job (exp1 on Simbody, 20 seeds, the defaults) on 1 and 2 threads, and its
# baseline: the commit given, or else this tree with the constrained Simbody model.
cbbg="$root/build/apps/cbbg"
wall jobs1 "$cbbg" run --jobs 1 --no-figures --out "$out/exp1-jobs1"
wall jobs2 "$cbbg" run --jobs 2 --no-figures --out "$out/exp1-jobs2"
if [[ -n "$baseline" ]]; then
  wall baseline_main "$baseline/build/apps/cbbg" run --jobs 2 --no-figures --out "$out/exp1-base"
  # exp1 on the analytic plant, where the framework's share of the time is largest.
  wall analytic "$cbbg" run --jobs 2 --no-figures --set plant.kind=analytic --out "$out/analytic"
  wall baseline_analytic "$baseline/build/apps/cbbg" run --jobs 2 --no-figures \
    --set plant.kind=analytic --out "$out/analytic-base"
else
  wall baseline_main "$cbbg" run --jobs 2 --no-figures --set plant.simbody_model=constrained \
    --out "$out/exp1-base"
fi
# same_results <dir> <dir>: yes when the two runs wrote the same result bytes.
same_results() {
  local file
  for file in trials.csv evaluation.csv steps.csv summary.json; do
    cmp -s "$1/$file" "$2/$file" || { echo no; return; }
  done
  echo yes
}
identical="$(same_results "$out/exp1-jobs1" "$out/exp1-jobs2")"
: > "$out/same_as_baseline"
if [[ -n "$baseline" ]]; then
  echo "main $(same_results "$out/exp1-jobs2" "$out/exp1-base")" >> "$out/same_as_baseline"
  echo "analytic $(same_results "$out/analytic" "$out/analytic-base")" >> "$out/same_as_baseline"
fi

python3 "$root/scripts/bench_table.py" "$out" "$identical" "${against:-constrained}"
# Instructions per tick, which repeat where timings do not.
"$root/scripts/count_instructions.sh" "$root/build"
if [[ -n "$baseline" ]]; then
  echo "The same at ${against:0:7}:"
  "$root/scripts/count_instructions.sh" "$baseline/build"
fi
