#!/usr/bin/env bash
# Builds and runs every benchmark; each prints its ratios to a baseline measured in the same
# run. Arguments go to every benchmark (e.g. --benchmark_min_time=2).
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
"$root/scripts/build.sh"
for bench in framework/bench_framework plant/bench_plant diagrams/bench_diagrams; do
  echo "== $bench"
  "$root/build/bench/$bench" "$@"
done
