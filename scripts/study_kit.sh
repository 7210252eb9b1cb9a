# Sourced by the study scripts (robustness_study.sh, teacher_study.sh), after they parse their
# options: what they share. The caller sets
#   study     its own name, for messages ("robustness_study.sh")
#   here      its folder
#   usage     a function that prints "$study: MESSAGE (usage: ...)" and exits 2
# and the options: out (--out), plant, seeds, jobs.
# study_check_options checks the options every study has, before anything is made, and finds
# cbbg; study_folder_open (with settings, one line of what the study was started with, and
# marker_name, the file that marks the folder as the study's) refuses (exit 2) a folder it
# did not make or that holds another study, else makes it so that no kill leaves one the
# next run would refuse, and sets `made` to what it created (empty when it resumes);
# study_folder_take_back removes a folder this invocation made while it holds only its
# marker (cbbg refused the study's first command).

study_check_options() {
  [[ -n "$out" ]] || usage "--out DIR is required"
  [[ "$plant" == analytic || "$plant" == simbody ]] ||
    usage "--plant must be analytic or simbody; got '$plant'"
  # cbbg's own limits (config `seeds`, --jobs), checked here so that a refusal leaves nothing.
  in_range() { [[ "$1" =~ ^[1-9][0-9]{0,5}$ ]] && (( $1 <= $2 )); }
  in_range "$seeds" 10000 || usage "--seeds must be a whole number from 1 to 10000; got '$seeds'"
  in_range "$jobs" 1024 || usage "--jobs must be a whole number from 1 to 1024; got '$jobs'"
  # cbbg: $CBBG, else the tree's build (scripts/build.sh), else the installed one beside the
  # script (PREFIX/share/cbbg/ and PREFIX/bin/), else the one on PATH.
  cbbg="${CBBG:-$here/../build/apps/cbbg}"
  [[ -x "$cbbg" ]] || cbbg="$here/../../bin/cbbg"
  [[ -x "$cbbg" ]] || cbbg="$(command -v cbbg || true)"
  [[ -n "$cbbg" && -x "$cbbg" ]] ||
    { echo "$study: no cbbg found (build it: scripts/build.sh, or set CBBG)" >&2; exit 1; }
  while [[ "$out" == */ && "$out" != / ]]; do out="${out%/}"; done  # DIR.new-study is beside DIR
}

# Removes `folder` if it holds at most the marker (a study's start or take-back, killed);
# refuses anything else.
study_folder_remove_unstarted() {
  local folder="$1"
  if [[ -L "$folder" || ! -d "$folder" ||
        -n "$(find "$folder" -mindepth 1 -maxdepth 1 ! -name "$marker_name")" ]]; then
    echo "$study: $folder is in the way and not this script's; move it away" >&2
    exit 2
  fi
  rm -f "$folder/$marker_name"
  rmdir "$folder"
}

# The first of the folder and its parents that does not exist yet: all this invocation
# makes, and so all it may take back.
study_folder_first_missing() {
  local path="$1" missing=""
  while [[ ! -e "$path" && ! -L "$path" ]]; do
    missing="$path"
    [[ "$(dirname "$path")" != "$path" ]] || break
    path="$(dirname "$path")"
  done
  echo "$missing"
}

study_folder_open() {
  marker="$out/$marker_name"
  # The folder is made under this name beside it, marked, then renamed into place.
  staging="$out.new-study"
  if [[ -e "$out" && ! -f "$marker" ]]; then
    echo "$study: $out exists and was not made by this script; choose a new --out" >&2
    exit 2
  fi
  if [[ -f "$marker" && "$(cat "$marker")" != "$settings" ]]; then
    echo "$study: $out holds a study with $(cat "$marker"); this one has $settings" >&2
    exit 2
  fi
  made=""
  if [[ ! -e "$out" ]]; then
    [[ ! -e "$staging" ]] || study_folder_remove_unstarted "$staging"
    made="$(study_folder_first_missing "$out")"
    mkdir -p "$(dirname "$out")"
    mkdir "$staging"
    echo "$settings" > "$staging/$marker_name"
    mv -T "$staging" "$out"
  fi
}

# cbbg refused the command of a study this invocation began (exit 2: it wrote nothing), so
# that the corrected command is not refused: the folder goes back to its temporary name in
# one step and is removed there, with the parents made above (rmdir removes only empty ones).
study_folder_take_back() {
  [[ -n "$made" ]] || return 0
  [[ -z "$(find "$out" -mindepth 1 -maxdepth 1 ! -name "$marker_name")" ]] || return 0
  mv -T "$out" "$staging"
  study_folder_remove_unstarted "$staging"
  local dir
  dir="$(dirname "$out")"
  while [[ "$out" != "$made" ]] && rmdir "$dir" 2>/dev/null && [[ "$dir" != "$made" ]]; do
    dir="$(dirname "$dir")"
  done
}
