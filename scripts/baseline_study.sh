#!/usr/bin/env bash
# The paper's learner against a deep-RL baseline on the same robot and the same conditions:
#   - cbbg (the paper's learner) and bg_only (its actor-critic without the teacher), each
#     alone: exp1, for the simulated seconds of experience until the first 20 s trial;
#     transfer trained as exp3, for the learnt actor's robustness (the nominal robot, +30 %
#     mass, +30 % CoM height, 0.05 rad noise, the teacher's 74 N push);
#   - PPO (python/examples/ppo_balance.py) per seed, for --steps steps from the same initial
#     pitch: the experience until its first 20 s episode, then its final policy under the
#     same conditions from the same angles.
# Then baseline_report.py's table, DIR/baseline.md, and the CPU time each took.
#
#   scripts/baseline_study.sh --out DIR [--plant analytic|simbody|mujoco] [--seeds N]
#                             [--jobs J] [--steps S]
#
# DIR/paper/{exp1,transfer}_{cbbg,bg_only} are cbbg results directories, DIR/ppo/seed_N.json the
# baseline's reports. Run again after a kill, it resumes the cbbg runs from their finished
# tasks and skips every finished run and seed. It refuses a DIR it did not make, of another
# plant, seed count or step budget, or that another invocation is using. Needs PyTorch
# (python3-torch; scripts/setup.sh installs it) and Debian's /usr/bin/python3.
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
study=baseline_study.sh
all_variants=paper
usage() { echo "$study: $1 (usage: --out DIR [--plant analytic|simbody|mujoco] [--seeds N] [--jobs J] [--steps S])" >&2; exit 2; }
# shellcheck source=study_kit.sh
source "$here/study_kit.sh"

steps=300000
study_extra_option() { [[ "$1" == --steps ]] && steps="$2"; }
study_options "$@"
[[ "$steps" =~ ^[1-9][0-9]{0,8}$ ]] || usage "--steps must be a whole number from 1 to 999999999; got '$steps'"
# The baseline: the tree's python/examples, or installed among the documentation's examples
# (PREFIX/share/doc/cbbg/examples/python, beside PREFIX/share/cbbg).
ppo="$here/../python/examples/ppo_balance.py"
[[ -f "$ppo" ]] || ppo="$here/../doc/cbbg/examples/python/ppo_balance.py"
[[ -f "$ppo" ]] || { echo "$study: no ppo_balance.py beside it (python/examples/)" >&2; exit 1; }
# The cbbg Python package of the cbbg found (a build tree's build/python), else the installed one.
python_package="$(dirname "$cbbg")/../python"
[[ ! -d "$python_package/cbbg" ]] || export PYTHONPATH="$python_package${PYTHONPATH:+:$PYTHONPATH}"
/usr/bin/python3 -c "import torch" 2>/dev/null ||
  { echo "$study: PyTorch is not installed for /usr/bin/python3 (scripts/setup.sh installs python3-torch)" >&2; exit 1; }
/usr/bin/python3 -c "import cbbg" 2>/dev/null ||
  { echo "$study: the cbbg Python package is not importable by /usr/bin/python3 (build it: scripts/build.sh)" >&2; exit 1; }

# The conditions of the teacher study (teacher_study.sh), the push lasting 0.5 s.
conditions="evaluation.noise_std=0, evaluation.body_mass_scale=1.3, evaluation.com_height_scale=1.3"
conditions+=", evaluation.noise_std=0.05, evaluation.push_force=74"
# Each arm in runs of its own, so that each has its CPU time.
study_runs=(exp1_cbbg transfer_cbbg exp1_bg_only transfer_bg_only)
# shellcheck disable=SC2034  # NAME_args are read by name (study_kit.sh)
runs_of() {
  local arm common
  for arm in cbbg bg_only; do
    common=(--seeds "$seeds" --jobs "$jobs" --set plant.kind="$plant" --set "arms=[$arm]"
      --no-figures)
    declare -n exp1="exp1_${arm}_args" transfer="transfer_${arm}_args"
    exp1=(--experiment exp1 "${common[@]}")
    transfer=(--experiment transfer --set transfer.training=exp3
      --set evaluation.push_duration=0.5 --set "transfer.conditions=[$conditions]" "${common[@]}")
    unset -n exp1 transfer
  done
}
chosen=(paper)
study_probe_variants
marker_name=.cbbg-baseline-study
settings="plant=$plant seeds=$seeds steps=$steps"
study_folder_open
study_remove_leftovers "$out" "$out/paper"
[[ ! -d "$out/ppo" ]] || find "$out/ppo" -maxdepth 1 -name '.ppo-*' -delete

# The CPU seconds (user + system) of this shell's finished children so far: its cutime and
# cstime, fields 16 and 17 of /proc/PID/stat ($$ is this shell's pid in a subshell too).
children_cpu() {
  awk -v tick="$(getconf CLK_TCK)" '{ sub(/^.*\) /, ""); printf "%.2f\n", ($14 + $15) / tick }' \
    "/proc/$$/stat"
}

# Each cbbg run; its CPU time is recorded when it ran in one go (a resumed run's is not known).
runs_of paper
for run in "${study_runs[@]}"; do
  dir="$out/paper/$run"
  [[ ! -d "$dir" || -e "$dir/.cbbg-run" ]] || continue
  fresh=yes
  [[ ! -e "$dir.partial" && ! -e "$dir/.cbbg-run" ]] || fresh=no
  before="$(children_cpu)"
  declare -n run_args="${run}_args"
  study_run_or_resume "$dir" "${run_args[@]}"
  unset -n run_args
  [[ $fresh == no ]] || awk -v a="$before" -v b="$(children_cpu)" 'BEGIN { printf "%.2f\n", b - a }' \
    >"$out/paper/$run.cpu_s"
done

# The baseline, one process per seed, --jobs at once (each single-threaded).
mkdir -p "$out/ppo"
for ((seed = 1; seed <= seeds; seed++)); do
  [[ -e "$out/ppo/seed_$seed.json" ]] || echo "$seed"
done | xargs -r -P "$jobs" -I{} /usr/bin/python3 "$ppo" --plant "$plant" --seed {} \
  --steps "$steps" --out "$out/ppo/seed_{}.json" >/dev/null

study_refuse_temporaries
/usr/bin/python3 "$here/baseline_report.py" "$out"
