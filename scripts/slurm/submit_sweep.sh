#!/usr/bin/env bash
# Submits a cbbg sweep to Slurm: its shards as one job array, and the merge as a job that
# starts when every shard has succeeded.
#   submit_sweep.sh SHARDS DIR [cbbg run options...]
#   e.g. submit_sweep.sh 20 results/alpha-sweep --grid actor.alpha=0.05,0.1,0.2 --seeds 50
# Prints the two job ids. Extra sbatch options (partition, time, account) go in SBATCH_*
# environment variables (SBATCH_PARTITION=..., SBATCH_TIMELIMIT=...), which sbatch reads.
# The cbbg binary is $CBBG, or cbbg on the PATH of the jobs.
set -euo pipefail
if (($# < 2)) || ! [[ "$1" =~ ^[1-9][0-9]*$ ]]; then
  echo "usage: submit_sweep.sh SHARDS DIR [cbbg run options...] (SHARDS a positive integer)" >&2
  exit 2
fi
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
shards="$1"
out="$2"
shift 2
array="$(sbatch --parsable --export=ALL --array="1-${shards}" "$here/sweep.sbatch" \
  --out "$out" "$@")"
array="${array%%;*}"  # "id;cluster" on multi-cluster setups
merge="$(sbatch --parsable --export=ALL --dependency="afterok:${array}" "$here/merge.sbatch" \
  "$out")"
echo "shards: job array ${array} (${shards} tasks); merge: job ${merge%%;*}"
