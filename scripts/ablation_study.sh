#!/usr/bin/env bash
# What do the paper's choices buy? The paper's learner and each built-in alternative of one of
# its blocks (each a config of configs/, one change: Gaussian exploration with a fixed or an
# annealed spread, Ornstein-Uhlenbeck exploration, a quadratic reward, a TD(0) critic, a fixed
# temperature), trained alike over the same seeds, for cbbg and bg_only:
#   - exp1: failures before the first success;
#   - exp3: trials until the actor alone balances (the skill).
# Then ablation_report.py's table, each variant paired with the paper's learner seed by seed.
#
#   scripts/ablation_study.sh --out DIR [--plant analytic|simbody|mujoco] [--seeds N] [--jobs J]
#                             [--variants paper,gaussian_exploration,...,path/to/mine.yaml]
#
# A variant is a config of configs/ by name, or a user's own YAML config by path (named
# after its file).
# DIR/VARIANT/exp1 and DIR/VARIANT/exp3 are cbbg results directories, DIR/ablation.md the
# table and DIR/ablation.png its figure. Run again after a kill, it resumes each run from its
# finished tasks (the bytes of an uninterrupted study) and skips the finished ones; run again
# when done, it runs nothing and writes the same report; run with more --variants, it adds
# them. It refuses a DIR it did not make, of another plant or seed count, or that another
# invocation is using (two at once on one DIR: the second is refused); every variant's runs
# are checked by cbbg before anything is made, and a refusal (exit 2, one line naming the
# variant and what cbbg refused) leaves nothing behind.
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
study=ablation_study.sh
# The variants by name: paper, and the configs of configs/ (installed beside this script).
all_variants="paper,gaussian_exploration,annealed_gaussian_exploration,ou_exploration"
all_variants+=",quadratic_reward,td0_critic,fixed_temperature"
usage() { echo "$study: $1 (usage: --out DIR [--plant analytic|simbody|mujoco] [--seeds N] [--jobs J] [--variants A,B,...])" >&2; exit 2; }
# shellcheck source=study_kit.sh
source "$here/study_kit.sh"
study_variant_options "$@"

# runs_of VARIANT: the commands of its two runs (`cbbg run` with them and --out), in
# exp1_args and exp3_args, run into DIR/VARIANT/exp1 and DIR/VARIANT/exp3; the arms are
# exp1's and exp3's default, cbbg and bg_only.
study_runs=(exp1 exp3)
# shellcheck disable=SC2034  # NAME_args are read by name (study_kit.sh)
runs_of() {
  local config=()
  [[ "$1" == paper ]] || config=(--config "$(study_config_of "$1")")
  local common=("${config[@]}" --seeds "$seeds" --jobs "$jobs" --set plant.kind="$plant"
    --no-figures)
  exp1_args=(--experiment exp1 "${common[@]}")
  exp3_args=(--experiment exp3 "${common[@]}")
}

study_variants_run .cbbg-ablation-study ablation_report.py
