#!/usr/bin/env bash
# Peak memory of one trial of 100,000 and of 1,000,000 ticks (cbbg arm, analytic plant):
# the two should match, steps.csv being streamed to disk (log.decimation 1, the default).
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
scratch="$(mktemp -d)"
trap 'rm -rf "$scratch"' EXIT
command -v /usr/bin/time >/dev/null || { echo "needs /usr/bin/time (Debian package 'time')"; exit 2; }
for seconds in 1000 10000; do
  /usr/bin/time -f "$((seconds * 100)) ticks: peak RSS %M KB, %e s wall" \
    "$root/build/apps/cbbg" run --experiment cbbg --seeds 1 --no-figures \
    --set plant.kind=analytic --set trial.duration=$seconds --set 'evaluation.angles=[0.05]' \
    --out "$scratch/run$seconds" 2>&1 >/dev/null | grep ticks
  echo "  steps.csv: $(du -h "$scratch/run$seconds/steps.csv" | cut -f1)"
done
