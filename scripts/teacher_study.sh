#!/usr/bin/env bash
# Can the learner outgrow its teacher? The paper's learner and each variant of configs/ (each
# one change: features that see the wheels, a wider pitch view, a reward that minds the
# drift; and the three together), trained and measured alike over the same seeds:
#   - transfer (exp3's training, then evaluated under the robustness conditions): trials to
#     skill and runs balanced, for cbbg and bg_only (and the PD supervisor alone, once);
#   - exp2: the late trials' drift speed and pitch RMS.
# Then teacher_report.py's table, each variant paired with the paper's learner seed by seed.
#
#   scripts/teacher_study.sh --out DIR [--plant analytic|simbody] [--seeds N] [--jobs J]
#                            [--variants paper,wheel_rate_features,...,path/to/mine.yaml]
#
# A variant is a config of configs/ by name, or a user's own YAML config by path (named
# after its file).
# DIR/VARIANT/transfer and DIR/VARIANT/exp2 are cbbg results directories, DIR/teacher.md the
# table. Run again after a kill, it resumes each run from its finished tasks (the bytes of an
# uninterrupted study) and skips the finished ones; run with more --variants, it adds them.
# It refuses a DIR it did not make, of another plant or seed count, or that another
# invocation is using (two at once on one DIR: the second is refused); every variant's runs
# are checked by cbbg before anything is made, and a refusal (exit 2, one line naming the
# variant and what cbbg refused) leaves nothing behind.
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
study=teacher_study.sh
# The variants' configs: the tree's configs/, or the installed ones beside this script.
configs="$here/../configs"
[[ -d "$configs" ]] || configs="$here/configs"
all_variants="paper,wheel_rate_features,wheel_features,wide_pitch,wheel_rate_reward,outgrow"
plant=analytic seeds=20 jobs="$(nproc)" out="" variants="$all_variants"
usage() { echo "$study: $1 (usage: --out DIR [--plant analytic|simbody] [--seeds N] [--jobs J] [--variants A,B,...])" >&2; exit 2; }
while [[ $# -gt 0 ]]; do
  [[ $# -ge 2 ]] || usage "$1 needs a value"
  case "$1" in
    --out) out="$2" ;;
    --plant) plant="$2" ;;
    --seeds) seeds="$2" ;;
    --jobs) jobs="$2" ;;
    --variants) variants="$2" ;;
    *) usage "unknown option '$1'" ;;
  esac
  shift 2
done
# shellcheck source=study_kit.sh
source "$here/study_kit.sh"
study_check_options
IFS=, read -r -a chosen <<<"$variants"
[[ "${chosen[0]:-}" == paper ]] || usage "--variants must begin with paper (the others are paired with it); got '$variants'"
# config_of VARIANT: its YAML file ("" for paper); name_of VARIANT: its folder's name.
config_of() {
  case "$1" in
    paper) echo "" ;;
    *.yaml) realpath -- "$1" ;;
    *) echo "$configs/$1.yaml" ;;
  esac
}
name_of() { basename -- "$1" .yaml; }
names=" "
for variant in "${chosen[@]}"; do
  [[ "$names" != *" $(name_of "$variant") "* ]] ||
    usage "--variants: two variants named $(name_of "$variant") (each has its folder DIR/NAME)"
  names+="$(name_of "$variant") "
  if [[ "$variant" == *.yaml ]]; then
    [[ -f "$variant" ]] || usage "--variants: no config file '$variant'"
    [[ "$(name_of "$variant")" =~ ^[a-z][a-z0-9_]*$ && "$(name_of "$variant")" != paper ]] ||
      usage "--variants: a config's file name must be a lowercase word other than paper; got '$variant'"
  else
    [[ "$variant" == paper || -f "$configs/$variant.yaml" ]] ||
      usage "--variants: no variant '$variant' (there are ${all_variants//,/, }, or a config's path.yaml)"
  fi
done

# The robustness conditions: the nominal robot, the heaviest and highest of the robustness
# study, its noise that the learnt actors failed, and the largest push from outside that the
# PD supervisor survives (74 N at the centre of mass for 0.5 s; 80 N fells it).
conditions="evaluation.noise_std=0, evaluation.body_mass_scale=1.3, evaluation.com_height_scale=1.3"
conditions+=", evaluation.noise_std=0.05, evaluation.push_force=74"

# runs_of VARIANT: the commands of its two runs (`cbbg run` with them and --out), in
# transfer_args and exp2_args.
runs_of() {
  local config=() arms="[cbbg, bg_only]"
  [[ "$1" == paper ]] || config=(--config "$(config_of "$1")")
  # The PD supervisor learns nothing: the paper's run evaluates it once for every variant.
  [[ "$1" != paper ]] || arms="[cbbg, bg_only, pd_only]"
  local common=(--seeds "$seeds" --jobs "$jobs" --set plant.kind="$plant" --no-figures)
  transfer_args=(--experiment transfer "${config[@]}" --set transfer.training=exp3
    --set "arms=$arms" --set evaluation.push_duration=0.5 --set "transfer.conditions=[$conditions]"
    "${common[@]}")
  exp2_args=(--experiment exp2 "${config[@]}" "${common[@]}")
}

# Every variant's runs checked by cbbg before anything is made: a key it refuses in the last
# variant refuses the study, not the study after the paper's runs.
for variant in "${chosen[@]}"; do
  runs_of "$variant"
  what="--variants $variant"
  [[ "$variant" != paper ]] || what="the paper's runs"
  study_probe "$what" "${transfer_args[@]}"
  study_probe "$what" "${exp2_args[@]}"
done

marker_name=.cbbg-teacher-study
# The variants are not part of it: a study grows by variants, each paired with the same seeds.
settings="plant=$plant seeds=$seeds"
study_folder_open
study_remove_leftovers "$out" "$out"/*/

# run_or_resume DIR ARGS...: cbbg run ARGS... --out DIR, or --resume DIR after a kill, or
# nothing when DIR is done. Exits with cbbg's status when it fails.
run_or_resume() {
  local run="$1" status=0
  shift
  if [[ -e "$run.partial" || -e "$run/.cbbg-run" ]]; then
    "$cbbg" run --resume "$run" --jobs "$jobs" || status=$?
  elif [[ ! -d "$run" ]]; then
    mkdir -p "$(dirname "$run")"
    "$cbbg" run "$@" --out "$run" || status=$?
    if [[ $status == 2 ]]; then
      rmdir "$(dirname "$run")" 2>/dev/null || true
      study_folder_take_back
    fi
  fi
  [[ $status == 0 ]] || exit "$status"
}

for variant in "${chosen[@]}"; do
  runs_of "$variant"
  name="$(name_of "$variant")"
  run_or_resume "$out/$name/transfer" "${transfer_args[@]}"
  run_or_resume "$out/$name/exp2" "${exp2_args[@]}"
done
study_refuse_temporaries
/usr/bin/python3 "$here/teacher_report.py" "$out"
