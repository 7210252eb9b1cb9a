#!/usr/bin/env bash
# The design-space search of learning under disturbance: two cbbg sweeps over one grid of
# what the learner sees (normaliser.*, rbf.*) and what it learns under (training.*),
# `--seeds` seeds per point, each sharded through GNU parallel and merged: the transfer
# protocol (exp3's training, then the teacher study's conditions) and exp2 (whether the
# learner holds its ground); then disturbance_front.py's Pareto front of the two.
#
#   scripts/disturbance_search.sh --out DIR [--plant analytic|simbody|mujoco] [--seeds N]
#                                 [--jobs J] [--shards S] [--round 1|2]
#
# Round 1 sweeps the view (pitch, or the wheels' rate too), the pitch scales and the training
# disturbances (noise, push, initial pitch, curriculum); round 2 the view (the wheels' angle
# too), where the units sit (rbf.units grid or per_axis) and their width, the scales, and the
# spreads of initial pitch and body mass.
# DIR is the transfer sweep (cbbg's layout: sweep.csv, points/NNN/), DIR-holding the exp2
# sweep, DIR-costs.txt what they cost (wall time of the shards and of the merges, bytes),
# DIR/front.md and DIR/front.png the front. Killed, run it again: each shard redoes only its
# unfinished tasks (cbbg run --shard), and the merges and the front follow.
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
study=disturbance_search.sh
usage() { echo "$study: $1 (usage: --out DIR [--plant analytic|simbody|mujoco] [--seeds N] [--jobs J] [--shards S] [--round 1|2])" >&2; exit 2; }
# shellcheck source=study_kit.sh
source "$here/study_kit.sh"
shards=4 round=1
study_extra_option() {
  case "$1" in
    --shards) shards="$2" ;;
    --round) round="$2" ;;
    *) return 1 ;;
  esac
}
study_options "$@"
[[ "$shards" =~ ^[1-9][0-9]{0,3}$ ]] || usage "--shards must be a whole number from 1 to 9999; got '$shards'"
[[ "$round" == 1 || "$round" == 2 ]] || usage "--round must be 1 or 2; got '$round'"
# The cbbg Python package of the cbbg found (a build tree's build/python), else the installed one.
python_package="$(dirname "$cbbg")/../python"
[[ ! -d "$python_package/cbbg" ]] || export PYTHONPATH="$python_package${PYTHONPATH:+:$PYTHONPATH}"
command -v parallel >/dev/null ||
  { echo "$study: GNU parallel is not installed (scripts/setup.sh installs it)" >&2; exit 1; }

if [[ "$round" == 1 ]]; then
  grid=(--grid training.noise_std=0,0.05 --grid training.push_force=0,37,74
    --grid training.pitch_spread=0,0.1 --grid training.curriculum_trials=0,10
    --grid normaliser.inputs=pitch,pitch_wheel_rate
    --grid normaliser.scale_theta=0.0581776,0.1164,0.1745
    --grid normaliser.scale_dtheta=0.0581776,0.1745)
else
  # The wheels' scales cover where the teacher's pushed runs take them (docs/model.md §5.5).
  grid=(--set normaliser.scale_phi=4.65 --set normaliser.scale_dphi=7.84
    --grid normaliser.inputs=pitch,pitch_wheel_rate,pitch_wheels
    --grid rbf.units=grid,per_axis --grid rbf.width=0.5,0.75,1
    --grid normaliser.scale_theta=0.1164,0.1745 --grid normaliser.scale_dtheta=0.1745,0.41
    --grid training.pitch_spread=0,0.1 --grid training.body_mass_spread=0,0.3)
fi
conditions="evaluation.noise_std=0, evaluation.body_mass_scale=1.3, evaluation.com_height_scale=1.3"
conditions+=", evaluation.noise_std=0.05, evaluation.push_force=74"
# Per-tick logs off (log.decimation=0): a sweep of thousands of tasks keeps its figures only.
common=(--set plant.kind="$plant" --seeds "$seeds" --set log.decimation=0 --no-figures "${grid[@]}")
transfer=(--experiment transfer --set "arms=[cbbg]" --set transfer.training=exp3
  --set evaluation.push_duration=0.5 --set "transfer.conditions=[$conditions]" "${common[@]}")
holding=(--experiment exp2 "${common[@]}")
study_probe "the search" "${transfer[@]}"
study_probe "the search's exp2" "${holding[@]}"
costs="$out-costs.txt"

# sweep NAME DIR ARGS...: the sweep of ARGS into DIR, its shards through GNU parallel, then
# merged; its costs appended to the costs file. Nothing when DIR is a finished sweep.
sweep() {
  local name="$1" dir="$2" started sharded merged
  shift 2
  [[ -d "$dir" && ! -e "$dir.partial" ]] && return 0
  started=$(date +%s.%N)
  parallel -q --halt now,fail=1 -j "$jobs" "$cbbg" run "$@" --jobs 1 --shard "{}/$shards" \
    --out "$dir" ::: $(seq "$shards") >/dev/null
  sharded=$(date +%s.%N)
  "$cbbg" merge "$dir" >/dev/null
  merged=$(date +%s.%N)
  {
    echo "$name shards: $shards through GNU parallel, $jobs at once; wall $(awk -v a="$started" -v b="$sharded" 'BEGIN { printf "%.1f", b - a }') s"
    echo "$name merge: wall $(awk -v a="$sharded" -v b="$merged" 'BEGIN { printf "%.2f", b - a }') s"
    echo "$name bytes: $(du -sb "$dir" | cut -f1); files: $(find "$dir" -type f | wc -l)"
  } >>"$costs"
}

# The costs are written once a sweep is merged, the transfer sweep's first: a costs file
# beside no finished transfer sweep is not this search's to replace.
if [[ -e "$costs" && ! (-d "$out" && ! -e "$out.partial") ]]; then
  echo "$study: $costs exists, but $out is no finished search: move it away first" >&2
  exit 2
fi
sweep transfer "$out" "${transfer[@]}"
sweep exp2 "$out-holding" "${holding[@]}"
cat "$costs"
/usr/bin/python3 "$here/disturbance_front.py" "$out" "$out-holding"
