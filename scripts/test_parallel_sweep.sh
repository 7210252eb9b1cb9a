#!/usr/bin/env bash
# A sweep through GNU parallel: its 4 shards run 2 at a time on this machine, then the merge;
# the merged directory must be byte for byte a single-process run's.
#   test_parallel_sweep.sh BUILD_DIR
set -euo pipefail
cbbg="$(cd "$1" && pwd)/apps/cbbg"
command -v parallel >/dev/null || { echo "test_parallel_sweep: GNU parallel is missing (scripts/setup.sh installs it)" >&2; exit 1; }
scratch="$(mktemp -d /tmp/cbbg-parallel.XXXXXX)"
trap 'rm -rf "$scratch"' EXIT
sweep=(--set plant.kind=analytic --seeds 3 --no-figures --grid actor.alpha=0.1,0.2
       --grid critic.beta=0.05,0.1)
"$cbbg" run "${sweep[@]}" --out "$scratch/single" >/dev/null 2>&1
parallel --will-cite -j 2 "$cbbg" run "${sweep[@]}" --shard {}/4 --out "$scratch/parallel" \
  ::: 1 2 3 4 2>/dev/null
"$cbbg" merge "$scratch/parallel" >/dev/null 2>&1
diff -r "$scratch/single" "$scratch/parallel"
echo "test_parallel_sweep: 4 shards through GNU parallel merged to the bytes of a single-process run"
