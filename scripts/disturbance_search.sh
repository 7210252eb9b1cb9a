#!/usr/bin/env bash
# The design-space search of learning under disturbance: a cbbg sweep of the transfer
# protocol (exp3's training, then the teacher study's conditions) over what the learner sees
# (normaliser.inputs and scales) and what it learns under (training.*), `--seeds` seeds per
# point, sharded through GNU parallel and merged; then disturbance_front.py's Pareto front.
#
#   scripts/disturbance_search.sh --out DIR [--plant analytic|simbody|mujoco] [--seeds N]
#                                 [--jobs J] [--shards S]
#
# DIR is the sweep (cbbg's layout: sweep.csv, points/NNN/), DIR/../NAME-costs.txt what it
# cost (wall time of the shards and of the merge, bytes), DIR/front.md and DIR/front.png the
# front. Killed, run it again: each shard redoes only its unfinished tasks (cbbg run --shard),
# and the merge and the front follow.
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
study=disturbance_search.sh
usage() { echo "$study: $1 (usage: --out DIR [--plant analytic|simbody|mujoco] [--seeds N] [--jobs J] [--shards S])" >&2; exit 2; }
# shellcheck source=study_kit.sh
source "$here/study_kit.sh"
shards=4
study_extra_option() { [[ "$1" == --shards ]] && shards="$2"; }
study_options "$@"
[[ "$shards" =~ ^[1-9][0-9]{0,3}$ ]] || usage "--shards must be a whole number from 1 to 9999; got '$shards'"
# The cbbg Python package of the cbbg found (a build tree's build/python), else the installed one.
python_package="$(dirname "$cbbg")/../python"
[[ ! -d "$python_package/cbbg" ]] || export PYTHONPATH="$python_package${PYTHONPATH:+:$PYTHONPATH}"
command -v parallel >/dev/null ||
  { echo "$study: GNU parallel is not installed (scripts/setup.sh installs it)" >&2; exit 1; }

conditions="evaluation.noise_std=0, evaluation.body_mass_scale=1.3, evaluation.com_height_scale=1.3"
conditions+=", evaluation.noise_std=0.05, evaluation.push_force=74"
# Per-tick logs off (log.decimation=0): a sweep of thousands of tasks keeps its figures only.
run=(--experiment transfer --set plant.kind="$plant" --set "arms=[cbbg]" --seeds "$seeds"
  --set transfer.training=exp3 --set evaluation.push_duration=0.5
  --set "transfer.conditions=[$conditions]" --set log.decimation=0 --no-figures
  --grid training.noise_std=0,0.05 --grid training.push_force=0,37,74
  --grid training.pitch_spread=0,0.1 --grid training.curriculum_trials=0,10
  --grid normaliser.inputs=pitch,pitch_wheel_rate
  --grid normaliser.scale_theta=0.0581776,0.1164,0.1745
  --grid normaliser.scale_dtheta=0.0581776,0.1745)
study_probe "the search" "${run[@]}"
costs="$out-costs.txt"
if [[ ! -d "$out" || -e "$out.partial" ]]; then
  started=$(date +%s.%N)
  parallel -q --halt now,fail=1 -j "$jobs" "$cbbg" run "${run[@]}" --jobs 1 --shard "{}/$shards" \
    --out "$out" ::: $(seq "$shards") >/dev/null
  sharded=$(date +%s.%N)
  "$cbbg" merge "$out" >/dev/null
  merged=$(date +%s.%N)
  {
    echo "shards: $shards through GNU parallel, $jobs at once; wall $(awk -v a="$started" -v b="$sharded" 'BEGIN { printf "%.1f", b - a }') s"
    echo "merge: wall $(awk -v a="$sharded" -v b="$merged" 'BEGIN { printf "%.2f", b - a }') s"
    echo "bytes: $(du -sb "$out" | cut -f1); files: $(find "$out" -type f | wc -l)"
  } >"$costs"
fi
cat "$costs"
/usr/bin/python3 "$here/disturbance_front.py" "$out"
