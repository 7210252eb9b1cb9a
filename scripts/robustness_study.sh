#!/usr/bin/env bash
# The robustness study: what exp3 teaches each arm (trained on the nominal robot), and the
# supervisor alone (pd_only), evaluated on robots they were not trained on. One `cbbg run` of
# the transfer protocol: each arm and seed trains once, then is evaluated under every
# perturbation's values (transfer.conditions); then the table and the figure of
# robustness_report.py.
#
#   scripts/robustness_study.sh --out DIR [--plant analytic|simbody|mujoco] [--seeds N] [--jobs J]
#
# DIR/transfer/ is the run's results directory, DIR/robustness.md the table and
# DIR/robustness.png the figure. Run again after a kill, it resumes: an interrupted run
# (DIR/transfer.partial) carries on from its finished tasks, so the bytes are those of an
# uninterrupted run. It refuses a DIR it did not make, and one another invocation is using
# (two at once on one DIR: the second is refused). A refusal (exit 2, one line) leaves
# nothing behind: the options, and the run's command by cbbg, are checked before DIR is made,
# and a DIR this run made is removed again should cbbg refuse the command all the same.
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
study=robustness_study.sh
plant=analytic seeds=20 jobs="$(nproc)" out=""
usage() { echo "$study: $1 (usage: --out DIR [--plant analytic|simbody|mujoco] [--seeds N] [--jobs J])" >&2; exit 2; }
while [[ $# -gt 0 ]]; do
  [[ $# -ge 2 ]] || usage "$1 needs a value"
  case "$1" in
    --out) out="$2" ;;
    --plant) plant="$2" ;;
    --seeds) seeds="$2" ;;
    --jobs) jobs="$2" ;;
    *) usage "unknown option '$1'" ;;
  esac
  shift 2
done
# shellcheck source=study_kit.sh
source "$here/study_kit.sh"
study_check_options
# The perturbations: each key's values, the nominal robot (1 or 0) among them; each value is
# one of transfer.conditions.
grids=(
  "evaluation.body_mass_scale=0.7,0.85,1,1.15,1.3"
  "evaluation.com_height_scale=0.7,0.85,1,1.15,1.3"
  "evaluation.noise_std=0,0.01,0.02,0.05,0.1"
  "evaluation.push_force=0,20,40,60,74,80"
)
conditions=""
for grid in "${grids[@]}"; do
  key="${grid%%=*}"
  IFS=, read -r -a values <<<"${grid#*=}"
  for value in "${values[@]}"; do conditions+="${conditions:+, }$key=$value"; done
done
# The push comes from outside: a force at the body's centre of mass for 0.5 s. 74 N is the
# largest the PD supervisor survives from every angle on both plants, 80 N fells it (measured,
# docs/studies.md). A push through the motors (evaluation.push_torque) is bounded by their 5 N m limit.
push_duration=0.5
transfer_args=(--experiment transfer --set transfer.training=exp3 --set plant.kind="$plant"
  --set "arms=[cbbg, bg_only, pd_only]" --seeds "$seeds" --jobs "$jobs"
  --set evaluation.push_duration=$push_duration --set "transfer.conditions=[$conditions]"
  --no-figures)
# The run checked by cbbg before anything is made.
study_probe "the transfer run" "${transfer_args[@]}"

marker_name=.cbbg-robustness-study
settings="plant=$plant seeds=$seeds"
study_folder_open
study_remove_leftovers "$out"

run="$out/transfer"
status=0
if [[ -e "$run.partial" || -e "$run/.cbbg-run" ]]; then
  # Killed while training or publishing: --resume carries on from the finished tasks.
  "$cbbg" run --resume "$run" --jobs "$jobs" || status=$?
elif [[ -d "$run" ]]; then
  echo "robustness_study.sh: the transfer run is done ($run)" >&2
else
  "$cbbg" run "${transfer_args[@]}" --out "$run" || status=$?
  if [[ $status == 2 ]]; then study_folder_take_back; fi
fi
[[ $status == 0 ]] || exit "$status"
study_refuse_temporaries
/usr/bin/python3 "$here/robustness_report.py" "$out"
