#!/usr/bin/env bash
# The robustness study: what exp3 teaches each arm (trained on the nominal robot), and the
# supervisor alone (pd_only), evaluated on robots they were not trained on. One sweep per
# perturbation, each a `cbbg run --grid` over an evaluation.* key, then the table and the
# figure of robustness_report.py.
#
#   scripts/robustness_study.sh --out DIR [--plant analytic|simbody] [--seeds N] [--jobs J]
#
# DIR/<key>/ is each sweep's results directory, DIR/robustness.md the table and
# DIR/robustness.png the figure. Run again after a kill, it resumes: a finished sweep is
# kept, an interrupted one (DIR/<key>.partial) resumes where it stopped, so the bytes are
# those of an uninterrupted run. It refuses a DIR it did not make.
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
# cbbg: $CBBG, else the tree's build (scripts/build.sh), else the installed one beside this
# script (PREFIX/share/cbbg/ and PREFIX/bin/), else the one on PATH.
cbbg="${CBBG:-$here/../build/apps/cbbg}"
[[ -x "$cbbg" ]] || cbbg="$here/../../bin/cbbg"
[[ -x "$cbbg" ]] || cbbg="$(command -v cbbg || true)"
plant=analytic seeds=20 jobs="$(nproc)" out=""
usage() { echo "robustness_study.sh: $1 (usage: --out DIR [--plant analytic|simbody] [--seeds N] [--jobs J])" >&2; exit 2; }
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
[[ -n "$out" ]] || usage "--out DIR is required"
[[ "$plant" == analytic || "$plant" == simbody ]] || usage "--plant must be analytic or simbody; got '$plant'"
[[ "$seeds" =~ ^[1-9][0-9]{0,5}$ ]] || usage "--seeds must be a whole number >= 1; got '$seeds'"
[[ "$jobs" =~ ^[1-9][0-9]{0,3}$ ]] || usage "--jobs must be a whole number >= 1; got '$jobs'"
[[ -n "$cbbg" && -x "$cbbg" ]] || { echo "robustness_study.sh: no cbbg found (build it: scripts/build.sh, or set CBBG)" >&2; exit 1; }

marker="$out/.cbbg-robustness-study"
if [[ -e "$out" && ! -f "$marker" ]]; then
  echo "robustness_study.sh: $out exists and was not made by this script; choose a new --out" >&2
  exit 2
fi
settings="plant=$plant seeds=$seeds"
if [[ -f "$marker" && "$(cat "$marker")" != "$settings" ]]; then
  echo "robustness_study.sh: $out holds a study with $(cat "$marker"); this one has $settings" >&2
  exit 2
fi
mkdir -p "$out"
echo "$settings" > "$marker"

# The perturbations: each key's values, the nominal robot (1 or 0) among them.
grids=(
  "evaluation.body_mass_scale=0.7,0.85,1,1.15,1.3"
  "evaluation.com_height_scale=0.7,0.85,1,1.15,1.3"
  "evaluation.noise_std=0,0.01,0.02,0.05,0.1"
  "evaluation.push_torque=0,1,2,5,10,20"
)
# A push lasts 0.5 s, long enough for the motors' limit (5 N m) not to hide the larger ones.
push_duration=0.5
for grid in "${grids[@]}"; do
  key="${grid%%=*}"
  sweep="$out/${key#evaluation.}"
  if [[ -d "$sweep" && ! -e "$sweep.partial" ]]; then
    echo "robustness_study.sh: $key done ($sweep)" >&2
  elif [[ -d "$sweep" ]]; then
    "$cbbg" merge "$sweep"  # killed while publishing: the merge finishes it
  else
    # New or interrupted: the same command again carries on from the finished tasks.
    "$cbbg" run --experiment exp3 --set plant.kind="$plant" --set "arms=[cbbg, bg_only, pd_only]" \
      --seeds "$seeds" --jobs "$jobs" --set evaluation.push_duration=$push_duration \
      --grid "$grid" --out "$sweep"
  fi
done
/usr/bin/python3 "$here/robustness_report.py" "$out"
