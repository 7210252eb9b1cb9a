# Sourced by the study scripts (robustness_study.sh, teacher_study.sh, ablation_study.sh,
# baseline_study.sh): what they share. The caller sets
#   study     its own name, for messages ("robustness_study.sh")
#   here      its folder
#   usage     a function that prints "$study: MESSAGE (usage: ...)" and exits 2
# and the options: out (--out), plant, seeds, jobs, which study_options parses (or the study).
# study_check_options checks the options every study has, before anything is made, and finds
# cbbg; study_folder_open (with settings, one line of what the study was started with, and
# marker_name, the file that marks the folder as the study's) refuses (exit 2) a folder it
# did not make, one that holds another study, or one another invocation is using, else makes
# it so that no kill leaves one the next run would refuse, takes its lock, and sets `made` to
# what it created (empty when it resumes); study_remove_leftovers and study_refuse_temporaries
# keep a killed invocation's temporaries out of a finished study; study_folder_take_back
# removes a folder this invocation made while it holds only its marker (cbbg refused the
# study's first command).
# The studies of variants (teacher_study.sh, ablation_study.sh) set all_variants (their own,
# by name, paper first), source this before they parse, and define runs_of VARIANT, which sets
# the `cbbg run` arguments of each of the variant's runs (without --out) in NAME_args, NAME
# one of study_runs (the runs' folders in DIR/VARIANT/, in the order they run):
# study_variant_options parses and checks their options (--variants too) before anything is
# made and sets `chosen`, the variants; study_variants_run MARKER REPORT has cbbg check every
# run of every variant, opens the study's folder (marked MARKER), runs each run into
# DIR/VARIANT/NAME (resuming one a kill interrupted, skipping one done) and then REPORT, a
# Python script beside the study's, on DIR.

study_check_options() {
  [[ -n "$out" ]] || usage "--out DIR is required"
  [[ "$plant" == analytic || "$plant" == simbody || "$plant" == mujoco ]] ||
    usage "--plant must be analytic, simbody or mujoco; got '$plant'"
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
  command -v flock >/dev/null ||
    { echo "$study: no flock found (it locks the study; Debian's util-linux has it)" >&2; exit 1; }
  while [[ "$out" == */ && "$out" != / ]]; do out="${out%/}"; done  # DIR.new-study is beside DIR
}

# study_probe WHAT ARGS...: cbbg checks `cbbg run ARGS... --check` as it would start it (every
# key and value, the arms, the protocol, the weights) and writes nothing. A refusal exits here
# with cbbg's own words, naming WHAT (the run or the variant), and nothing made.
study_probe() {
  local what="$1" status=0 said line
  shift
  said="$("$cbbg" run "$@" --check 2>&1 >/dev/null)" || status=$?
  [[ $status == 0 ]] && return 0
  line="$(grep -m1 ': error: ' <<<"$said" || true)"
  [[ -n "$line" ]] || line="$(tail -n 1 <<<"$said")"
  [[ -n "$line" ]] || line="exited $status, saying nothing"
  line="${line#*: error: }"
  if [[ $status == 2 ]]; then
    echo "$study: $what: $line" >&2
    exit 2
  fi
  echo "$study: $what: cbbg could not check it: $line" >&2
  exit 1
}

# study_options ARGS...: every study's options, parsed and checked: --out, --plant (analytic),
# --seeds (20), --jobs (nproc); any other is handed to study_extra_option NAME VALUE, which a
# study with options of its own defines (its status 1: an unknown option).
study_options() {
  plant=analytic seeds=20 jobs="$(nproc)" out=""
  while [[ $# -gt 0 ]]; do
    [[ $# -ge 2 ]] || usage "$1 needs a value"
    case "$1" in
      --out) out="$2" ;;
      --plant) plant="$2" ;;
      --seeds) seeds="$2" ;;
      --jobs) jobs="$2" ;;
      *) study_extra_option "$1" "$2" || usage "unknown option '$1'" ;;
    esac
    shift 2
  done
  study_check_options
}
study_extra_option() { return 1; }

# study_variant_options ARGS...: a study of variants' options, parsed and checked: those of
# study_options and --variants (all_variants).
study_variant_options() {
  variants="$all_variants"
  study_extra_option() { [[ "$1" == --variants ]] && variants="$2"; }
  study_options "$@"
  study_check_variants
}

# A variant is a config of the study's configs/ by name (the tree's configs/, or the installed
# ones beside the script), or a user's own YAML config by path, named after its file; paper
# is the paper's learner (no config). study_config_of VARIANT: its config ("" for paper);
# study_name_of VARIANT: its folder's name in DIR.
study_config_of() {
  case "$1" in
    paper) echo "" ;;
    *.yaml) realpath -- "$1" ;;
    *) echo "$configs/$1.yaml" ;;
  esac
}
study_name_of() { basename -- "$1" .yaml; }

# --variants checked (exit 2, one line, nothing made): paper first (the others are paired
# with it), each variant known or an existing config named as a lowercase word, no two with
# one folder. Sets `chosen`, the variants in order, and `configs`.
study_check_variants() {
  configs="$here/../configs"
  [[ -d "$configs" ]] || configs="$here/configs"
  IFS=, read -r -a chosen <<<"$variants"
  [[ "${chosen[0]:-}" == paper ]] || usage "--variants must begin with paper (the others are paired with it); got '$variants'"
  local names=" " variant name
  for variant in "${chosen[@]}"; do
    name="$(study_name_of "$variant")"
    [[ "$names" != *" $name "* ]] ||
      usage "--variants: two variants named $name (each has its folder DIR/NAME)"
    names+="$name "
    if [[ "$variant" == *.yaml ]]; then
      [[ -f "$variant" ]] || usage "--variants: no config file '$variant'"
      [[ "$name" =~ ^[a-z][a-z0-9_]*$ && "$name" != paper ]] ||
        usage "--variants: a config's file name must be a lowercase word other than paper; got '$variant'"
    else
      [[ "$variant" == paper || -f "$configs/$variant.yaml" ]] ||
        usage "--variants: no variant '$variant' (there are ${all_variants//,/, }, or a config's path.yaml)"
    fi
  done
}

# Every variant's runs checked by cbbg before anything is made: a key it refuses in the last
# variant refuses the study, not the study after the paper's runs.
study_probe_variants() {
  local variant what run
  for variant in "${chosen[@]}"; do
    runs_of "$variant"
    what="--variants $variant"
    [[ "$variant" != paper ]] || what="the paper's runs"
    for run in "${study_runs[@]}"; do
      local -n study_args="${run}_args"
      study_probe "$what" "${study_args[@]}"
    done
  done
}

# study_run_or_resume DIR ARGS...: cbbg run ARGS... --out DIR, or --resume DIR after a kill,
# or nothing when DIR is done. Exits with cbbg's status when it fails.
study_run_or_resume() {
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

# Every variant's runs, in order, each into DIR/VARIANT/NAME.
study_run_variants() {
  local variant run
  for variant in "${chosen[@]}"; do
    runs_of "$variant"
    for run in "${study_runs[@]}"; do
      local -n study_args="${run}_args"
      study_run_or_resume "$out/$(study_name_of "$variant")/$run" "${study_args[@]}"
    done
  done
}

# study_variants_run MARKER REPORT: the study of variants, from its checks to its report.
study_variants_run() {
  study_probe_variants
  marker_name="$1"
  # The variants are not part of it: a study grows by variants, each paired with the same
  # seeds.
  settings="plant=$plant seeds=$seeds"
  study_folder_open
  study_remove_leftovers "$out" "$out"/*/
  study_run_variants
  study_refuse_temporaries
  /usr/bin/python3 "$here/$2" "$out"
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

# Waits for the lock of DIR's parent (fd 8), which only making and taking back a study's
# folder hold, a moment each. Returns 1 when the parent was removed while it waited (a
# take-back of a new parent): the caller looks again.
study_parent_lock() {
  local parent
  parent="$(dirname "$out")"
  exec 8<"$parent" || { echo "$study: cannot open $parent to make $out in it" >&2; exit 1; }
  flock 8
  [[ "$parent" -ef /dev/fd/8 ]] && return 0
  exec 8<&-
  return 1
}

study_in_use() {
  echo "$study: $out is in use by another $study (or the cbbg it started); wait for it to end" >&2
  exit 2
}

study_folder_open() {
  marker="$out/$marker_name"
  # The folder is made under this name beside it, marked, locked, then renamed into place.
  staging="$out.new-study"
  made=""
  while true; do
    if [[ -e "$out" || -L "$out" ]]; then
      if [[ ! -f "$marker" ]]; then
        echo "$study: $out exists and was not made by this script; choose a new --out" >&2
        exit 2
      fi
      if ! { exec 9<"$marker"; } 2>/dev/null; then
        [[ -e "$marker" ]] || continue  # taken back meanwhile
        echo "$study: cannot open $marker to lock $out" >&2
        exit 1
      fi
      local recorded
      recorded="$(cat <&9)"
      if [[ "$recorded" != "$settings" ]]; then
        echo "$study: $out holds a study with $recorded; this one has $settings" >&2
        exit 2
      fi
      flock -n 9 || study_in_use
      # Taken back by the invocation that made it while this one opened it: look again.
      [[ "$marker" -ef /dev/fd/9 ]] && return 0
      exec 9<&-
      continue
    fi
    made="$(study_folder_first_missing "$out")"
    mkdir -p "$(dirname "$out")"
    study_parent_lock || continue
    if [[ -e "$out" || -L "$out" ]]; then  # another invocation made it meanwhile
      exec 8<&-
      made=""
      continue
    fi
    # Under the parent's lock a staging folder is one whose maker was killed.
    [[ ! -e "$staging" && ! -L "$staging" ]] || study_folder_remove_unstarted "$staging"
    mkdir "$staging"
    echo "$settings" >"$staging/$marker_name"
    exec 9<"$staging/$marker_name"
    flock -n 9 || study_in_use  # cannot be: no one else knows of it yet
    mv -T "$staging" "$out"
    exec 8<&-
    return 0
  done
}

# study_remove_leftovers FOLDER...: the temporaries a killed invocation left in FOLDERs (the
# study's own folders, beside its runs: a cbbg run's staging folder .RUN.partial.cbbg-tmp-*,
# a report's .NAME.cbbg-tmp-*), removed. Under the study's lock no process of a killed
# invocation runs (it would hold the lock), so they are stale whatever their pid says (a pid
# may have been reused since; cbbg and the report judge them by it, and keep them). A
# staging folder whose lock (.cbbg-lock) a live cbbg holds is someone else's: refused. What
# a run's own folder holds (RUN.partial) is cbbg's: its --resume removes it.
study_remove_leftovers() {
  local folder leftover
  for folder in "$@"; do
    [[ -d "$folder" && ! -L "$folder" ]] || continue
    while IFS= read -r -d '' leftover; do
      if [[ -f "$leftover/.cbbg-lock" ]] && ! (exec 7<"$leftover/.cbbg-lock" && flock -n 7)
      then
        echo "$study: $leftover is in use by another cbbg run; wait for it to end" >&2
        exit 2
      fi
      rm -rf -- "$leftover"
    done < <(find "$folder" -mindepth 1 -maxdepth 1 -name '*.cbbg-tmp-*' -print0)
  done
}

# The last check before the report: no temporary, and no unfinished run, anywhere in the
# study (exit 1 naming the first), so a finished study never holds a half-written file.
study_refuse_temporaries() {
  local found
  found="$(find "$out" \( -name '*.cbbg-tmp-*' -o -name '*.partial' -o -name .cbbg-run \) \
             -print -quit)"
  [[ -z "$found" ]] && return 0
  echo "$study: not publishing $out: it holds $found, a half-written file; run the study again" >&2
  exit 1
}

# cbbg refused the command of a study this invocation began (exit 2: it wrote nothing), so
# that the corrected command is not refused: the folder goes back to its temporary name in
# one step and is removed there, with the parents made above (rmdir removes only empty ones),
# under the parent's lock.
study_folder_take_back() {
  [[ -n "$made" ]] || return 0
  [[ -z "$(find "$out" -mindepth 1 -maxdepth 1 ! -name "$marker_name")" ]] || return 0
  study_parent_lock || return 0
  mv -T "$out" "$staging"
  study_folder_remove_unstarted "$staging"
  local dir
  dir="$(dirname "$out")"
  while [[ "$out" != "$made" ]] && rmdir "$dir" 2>/dev/null && [[ "$dir" != "$made" ]]; do
    dir="$(dirname "$dir")"
  done
  exec 8<&- 9<&-
}
