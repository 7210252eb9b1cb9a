#!/usr/bin/env bash
# The robustness study: what exp3 teaches each arm (trained on the nominal robot), and the
# supervisor alone (pd_only), evaluated on robots they were not trained on. One `cbbg run` of
# the transfer protocol: each arm and seed trains once, then is evaluated under every
# perturbation's values (transfer.conditions); then the table and the figure of
# robustness_report.py.
#
#   scripts/robustness_study.sh --out DIR [--plant analytic|simbody] [--seeds N] [--jobs J]
#
# DIR/transfer/ is the run's results directory, DIR/robustness.md the table and
# DIR/robustness.png the figure. Run again after a kill, it resumes: an interrupted run
# (DIR/transfer.partial) carries on from its finished tasks, so the bytes are those of an
# uninterrupted run. It refuses a DIR it did not make. A refusal (exit 2, one line) leaves
# nothing behind: the options are checked before DIR is made, and a DIR this run made is
# removed again when cbbg refuses the study's command.
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
# cbbg's own limits (config `seeds`, --jobs), checked here so that a refusal leaves nothing.
in_range() { [[ "$1" =~ ^[1-9][0-9]{0,5}$ ]] && (( $1 <= $2 )); }
in_range "$seeds" 10000 || usage "--seeds must be a whole number from 1 to 10000; got '$seeds'"
in_range "$jobs" 1024 || usage "--jobs must be a whole number from 1 to 1024; got '$jobs'"
[[ -n "$cbbg" && -x "$cbbg" ]] || { echo "robustness_study.sh: no cbbg found (build it: scripts/build.sh, or set CBBG)" >&2; exit 1; }
while [[ "$out" == */ && "$out" != / ]]; do out="${out%/}"; done  # DIR.new-study is beside DIR

marker_name=.cbbg-robustness-study
marker="$out/$marker_name"
if [[ -e "$out" && ! -f "$marker" ]]; then
  echo "robustness_study.sh: $out exists and was not made by this script; choose a new --out" >&2
  exit 2
fi
settings="plant=$plant seeds=$seeds"
if [[ -f "$marker" && "$(cat "$marker")" != "$settings" ]]; then
  echo "robustness_study.sh: $out holds a study with $(cat "$marker"); this one has $settings" >&2
  exit 2
fi

# DIR is made under this name beside it, marked, then renamed into place, so that no kill
# leaves a DIR without its marker (which the next run would refuse).
staging="$out.new-study"
# Removes `folder` if it holds at most the marker (a study's start or take-back, killed);
# refuses anything else.
remove_unstarted() {
  local folder="$1"
  if [[ -L "$folder" || ! -d "$folder" ||
        -n "$(find "$folder" -mindepth 1 -maxdepth 1 ! -name "$marker_name")" ]]; then
    echo "robustness_study.sh: $folder is in the way and not this script's; move it away" >&2
    exit 2
  fi
  rm -f "$folder/$marker_name"
  rmdir "$folder"
}
# The first of DIR and its parents that does not exist yet: all this invocation makes, and
# so all it may take back.
first_missing() {
  local path="$1" missing=""
  while [[ ! -e "$path" && ! -L "$path" ]]; do
    missing="$path"
    [[ "$(dirname "$path")" != "$path" ]] || break
    path="$(dirname "$path")"
  done
  echo "$missing"
}
made=""
if [[ ! -e "$out" ]]; then
  [[ ! -e "$staging" ]] || remove_unstarted "$staging"
  made="$(first_missing "$out")"
  mkdir -p "$(dirname "$out")"
  mkdir "$staging"
  echo "$settings" > "$staging/$marker_name"
  mv -T "$staging" "$out"
fi

# cbbg refused the command of a study this invocation began (exit 2: it wrote nothing), so
# that the corrected command is not refused: DIR goes back to its temporary
# name in one step and is removed there, with the parents made above (rmdir removes only
# empty folders).
take_back() {
  [[ -z "$(find "$out" -mindepth 1 -maxdepth 1 ! -name "$marker_name")" ]] || return 0
  mv -T "$out" "$staging"
  remove_unstarted "$staging"
  local dir
  dir="$(dirname "$out")"
  while [[ "$out" != "$made" ]] && rmdir "$dir" 2>/dev/null && [[ "$dir" != "$made" ]]; do
    dir="$(dirname "$dir")"
  done
}

# The perturbations: each key's values, the nominal robot (1 or 0) among them; each value is
# one of transfer.conditions.
grids=(
  "evaluation.body_mass_scale=0.7,0.85,1,1.15,1.3"
  "evaluation.com_height_scale=0.7,0.85,1,1.15,1.3"
  "evaluation.noise_std=0,0.01,0.02,0.05,0.1"
  "evaluation.push_torque=0,1,2,5,10,20"
)
conditions=""
for grid in "${grids[@]}"; do
  key="${grid%%=*}"
  IFS=, read -r -a values <<<"${grid#*=}"
  for value in "${values[@]}"; do conditions+="${conditions:+, }$key=$value"; done
done
# A push lasts 0.5 s, long enough for the motors' limit (5 N m) not to hide the larger ones.
push_duration=0.5
run="$out/transfer"
status=0
if [[ -e "$run.partial" || -e "$run/.cbbg-run" ]]; then
  # Killed while training or publishing: --resume carries on from the finished tasks.
  "$cbbg" run --resume "$run" --jobs "$jobs" || status=$?
elif [[ -d "$run" ]]; then
  echo "robustness_study.sh: the transfer run is done ($run)" >&2
else
  "$cbbg" run --experiment transfer --set transfer.training=exp3 --set plant.kind="$plant" \
    --set "arms=[cbbg, bg_only, pd_only]" --seeds "$seeds" --jobs "$jobs" \
    --set evaluation.push_duration=$push_duration --set "transfer.conditions=[$conditions]" \
    --no-figures --out "$run" || status=$?
  if [[ $status == 2 && -n "$made" ]]; then take_back; fi
fi
[[ $status == 0 ]] || exit "$status"
/usr/bin/python3 "$here/robustness_report.py" "$out"
