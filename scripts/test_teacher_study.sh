#!/usr/bin/env bash
# The teacher study end to end, small (analytic plant, 2 seeds, two variants): a refused
# command (a key cbbg refuses in the last variant among them) leaves nothing; it writes the
# report's four tables and its figure, each variant paired with the paper's learner; stopped
# by cbbg's fault hook while training and run again, also beside leftovers named after a live
# pid, it ends with the bytes of an uninterrupted study; of two at once on one new folder,
# one runs and the other is refused, leaving nothing; a further variant, a user's own
# config, joins a finished study; a folder it did not make, or of other settings, is refused.
#   test_teacher_study.sh BUILD_DIR
set -euo pipefail
export CBBG="$(cd "$1" && pwd)/apps/cbbg"
study="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)/teacher_study.sh"
scratch="$(mktemp -d /tmp/cbbg-teacher.XXXXXX)"
trap 'rm -rf "$scratch"' EXIT
fail() { echo "test_teacher_study: $1" >&2; exit 1; }
small=(--plant analytic --seeds 2 --jobs 2 --variants paper,wheel_rate_reward)

# refused MESSAGE OPTION...: exit 2, MESSAGE as the one line, nothing left of the folder.
refused() {
  local message="$1" status=0
  shift
  "$study" "$@" --out "$scratch/new/study" 2>"$scratch/err" || status=$?
  [[ "$status" == 2 && "$(wc -l <"$scratch/err")" == 1 && ! -e "$scratch/new" ]] &&
    grep -qF -- "$message" "$scratch/err" ||
    fail "$* exited $status and said: $(cat "$scratch/err")"
}
refused "teacher_study.sh: --variants: no variant 'no_such'" --seeds 2 --variants paper,no_such
refused "teacher_study.sh: --variants must begin with paper" --seeds 2 --variants wide_pitch
refused "teacher_study.sh: --variants: two variants named wide_pitch" --seeds 2 \
  --variants "paper,wide_pitch,$scratch/wide_pitch.yaml"
# A key cbbg refuses in the user's own variant, the last: refused before the paper's runs.
printf 'critic:\n  no_such: 1\n' >"$scratch/bad.yaml"
refused "teacher_study.sh: --variants $scratch/bad.yaml: $scratch/bad.yaml: unknown key 'critic.no_such'" \
  --plant analytic --seeds 2 --jobs 2 --variants "paper,wheel_rate_reward,$scratch/bad.yaml"
printf '#!/bin/sh\nexec "%s" "$@" --set no_such_key=1\n' "$CBBG" >"$scratch/refusing-cbbg"
chmod +x "$scratch/refusing-cbbg"
CBBG="$scratch/refusing-cbbg" refused "unknown key 'no_such_key'" "${small[@]}"

whole="$scratch/whole"
"$study" "${small[@]}" --out "$whole" >/dev/null 2>&1 || fail "the small study failed"
for section in "## Trials to skill" "## Balanced runs under each condition" \
               "## exp2, trials 23-30" "## The moonshot"; do
  grep -qF "$section" "$whole/teacher.md" || fail "teacher.md has no '$section'"
done
[[ "$(head -c 8 "$whole/teacher.png" | od -An -tx1 | tr -d ' \n')" == 89504e470d0a1a0a ]] ||
  fail "teacher.png is not a PNG"
grep -q '^| wheel_rate_reward | cbbg | .* | .*/2 | .*, p = ' "$whole/teacher.md" ||
  fail "the variant's trials to skill are not paired with the paper's"
grep -q '^| PD supervisor | pd_only | 10/10 |' "$whole/teacher.md" ||
  fail "the PD supervisor's row is missing"

# Stopped by cbbg's fault hook while the first run trains, then run again.
status=0
CBBG_FAULT_AT=task:record@3 "$study" "${small[@]}" --out "$scratch/faulted" >/dev/null 2>&1 ||
  status=$?
[[ "$status" == 86 && -d "$scratch/faulted/paper/transfer.partial" ]] ||
  fail "the fault hook did not stop the study while it trained (exit $status)"
"$study" "${small[@]}" --out "$scratch/faulted" >/dev/null 2>&1
diff -r "$whole" "$scratch/faulted" || fail "the study stopped while training differs"

# Killed again and left, beside a run, the staging folder of a cbbg it started, and a
# half-written report, both named after a pid that runs (as a reused pid would): the study,
# under its lock, removes them before it runs on and publishes.
status=0
CBBG_FAULT_AT=task:record@3 "$study" "${small[@]}" --out "$scratch/leftover" >/dev/null 2>&1 ||
  status=$?
[[ "$status" == 86 ]] || fail "the fault hook did not stop the study (exit $status)"
leftover="$scratch/leftover/paper/.exp2.partial.cbbg-tmp-$(hostname)-$$-0"
mkdir -p "$leftover/tasks"
: >"$leftover/.cbbg-lock"
echo "half a table" >"$scratch/leftover/.teacher.md.cbbg-tmp-$(hostname)-$$-0"
"$study" "${small[@]}" --out "$scratch/leftover" >/dev/null 2>&1 || fail "the study with leftovers failed"
diff -r "$whole" "$scratch/leftover" || fail "the study run on beside its leftovers differs"

# Two at once on one new --out: one makes the study, the other is refused with one line
# naming it and leaves nothing; the study is the whole one's.
for k in 1 2; do
  { status=0
    "$study" "${small[@]}" --out "$scratch/twice/study" >/dev/null 2>"$scratch/err.$k" || status=$?
    echo "$status"; } >"$scratch/status.$k" &
done
wait
statuses="$(cat "$scratch/status.1" "$scratch/status.2" | sort | tr '\n' ' ')"
[[ "$statuses" == "0 2 " ]] || fail "two studies at once exited $statuses"
refusal="$(grep -h "teacher_study.sh: " "$scratch/err.1" "$scratch/err.2")"
[[ "$refusal" == "teacher_study.sh: $scratch/twice/study is in use by another teacher_study.sh (or the cbbg it started); wait for it to end" ]] ||
  fail "the second study at once said: $(cat "$scratch/err.1" "$scratch/err.2")"
for k in 1 2; do
  [[ "$(cat "$scratch/status.$k")" != 2 || "$(wc -l <"$scratch/err.$k")" == 1 ]] ||
    fail "the refused study said more than one line: $(cat "$scratch/err.$k")"
done
[[ "$(ls -A "$scratch/twice")" == study ]] || fail "two studies at once left $(ls -A "$scratch/twice")"
diff -r "$whole" "$scratch/twice/study" || fail "the study run beside a refused one differs"

# A further variant joins, a user's own config: the earlier runs are kept as they are.
cp -a "$whole" "$scratch/grown"
printf 'critic:\n  gamma: 0.9\n' >"$scratch/my_gamma.yaml"
"$study" --plant analytic --seeds 2 --jobs 2 \
  --variants "paper,wheel_rate_reward,$scratch/my_gamma.yaml" --out "$scratch/grown" \
  >/dev/null 2>&1 || fail "adding a variant failed"
diff -r "$whole/paper" "$scratch/grown/paper" || fail "adding a variant changed the paper's runs"
grep -q '^| my_gamma | bg_only |' "$scratch/grown/teacher.md" || fail "my_gamma is not reported"

mkdir "$scratch/mine"
status=0
"$study" --seeds 2 --out "$scratch/mine" 2>"$scratch/err" || status=$?
[[ "$status" == 2 ]] && grep -q "exists and was not made by this script" "$scratch/err" ||
  fail "a foreign folder was not refused: $(cat "$scratch/err")"
status=0
"$study" --plant analytic --seeds 3 --out "$whole" 2>"$scratch/err" || status=$?
[[ "$status" == 2 ]] && grep -q "holds a study with plant=analytic seeds=2" "$scratch/err" ||
  fail "a study of other settings was not refused: $(cat "$scratch/err")"
echo "test_teacher_study: refusals leave nothing; four tables and the figure, variants paired with the paper;" \
  "stopped while training and run again, beside leftovers too, to the same bytes; two at once: one refused;" \
  "a user's own config joins; foreign folders refused"
