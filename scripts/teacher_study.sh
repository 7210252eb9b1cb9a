#!/usr/bin/env bash
# Can the learner outgrow its teacher? The paper's learner and each variant of configs/ (each
# one change: features that see the wheels, a wider pitch view, a reward that minds the
# drift; and the three together), trained and measured alike over the same seeds:
#   - transfer (exp3's training, then evaluated under the robustness conditions): trials to
#     skill and runs balanced, for cbbg and bg_only (and the PD supervisor alone, once);
#   - exp2: the late trials' drift speed and pitch RMS.
# Then teacher_report.py's table, each variant paired with the paper's learner seed by seed.
#
#   scripts/teacher_study.sh --out DIR [--plant analytic|simbody|mujoco] [--seeds N] [--jobs J]
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
# The variants by name: paper, and the configs of configs/ (installed beside this script).
all_variants="paper,wheel_rate_features,wheel_features,wide_pitch,wheel_rate_reward,outgrow"
usage() { echo "$study: $1 (usage: --out DIR [--plant analytic|simbody|mujoco] [--seeds N] [--jobs J] [--variants A,B,...])" >&2; exit 2; }
# shellcheck source=study_kit.sh
source "$here/study_kit.sh"
study_variant_options "$@"

# The robustness conditions: the nominal robot, the heaviest and highest of the robustness
# study, its noise that the learnt actors failed, and the largest push from outside that the
# PD supervisor survives (74 N at the centre of mass for 0.5 s; 80 N fells it).
conditions="evaluation.noise_std=0, evaluation.body_mass_scale=1.3, evaluation.com_height_scale=1.3"
conditions+=", evaluation.noise_std=0.05, evaluation.push_force=74"

# runs_of VARIANT: the commands of its two runs (`cbbg run` with them and --out), in
# transfer_args and exp2_args, run into DIR/VARIANT/transfer and DIR/VARIANT/exp2.
study_runs=(transfer exp2)
# shellcheck disable=SC2034  # NAME_args are read by name (study_kit.sh)
runs_of() {
  local config=() arms="[cbbg, bg_only]"
  [[ "$1" == paper ]] || config=(--config "$(study_config_of "$1")")
  # The PD supervisor learns nothing: the paper's run evaluates it once for every variant.
  [[ "$1" != paper ]] || arms="[cbbg, bg_only, pd_only]"
  local common=(--seeds "$seeds" --jobs "$jobs" --set plant.kind="$plant" --no-figures)
  transfer_args=(--experiment transfer "${config[@]}" --set transfer.training=exp3
    --set "arms=$arms" --set evaluation.push_duration=0.5 --set "transfer.conditions=[$conditions]"
    "${common[@]}")
  exp2_args=(--experiment exp2 "${config[@]}" "${common[@]}")
}

study_variants_run .cbbg-teacher-study teacher_report.py
