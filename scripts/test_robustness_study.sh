#!/usr/bin/env bash
# The robustness study end to end, small (analytic plant, 2 seeds): a refused command leaves
# nothing that would refuse the corrected one; it writes a table of every perturbation's
# values; killed part-way (a SIGKILL while training, cbbg's fault hook while training and
# after publishing) and run again, also beside leftovers named after a live pid, it ends with
# the bytes of an uninterrupted study; of two at once on one new folder, one runs and the
# other is refused, leaving nothing; and it refuses a folder it did not make.
#   test_robustness_study.sh BUILD_DIR
set -euo pipefail
export CBBG="$(cd "$1" && pwd)/apps/cbbg"
study="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)/robustness_study.sh"
scratch="$(mktemp -d /tmp/cbbg-robustness.XXXXXX)"
trap 'rm -rf "$scratch"' EXIT
fail() { echo "test_robustness_study: $1" >&2; exit 1; }
whole="$scratch/new/whole"  # its parent is new too: a refusal removes both

# refused MESSAGE OPTION...: the study exits 2 with MESSAGE as its one line and leaves no
# trace of $whole (nor of its new parent).
refused() {
  local message="$1" status=0 left
  shift
  "$study" "$@" --out "$whole" 2>"$scratch/err" || status=$?
  left="$(find "$scratch/new" 2>/dev/null | tr '\n' ' ')" || true  # none: find fails
  [[ "$status" == 2 && "$(wc -l <"$scratch/err")" == 1 && -z "$left" ]] &&
    grep -qF -- "$message" "$scratch/err" ||
    fail "$* exited $status, left '$left' and said: $(cat "$scratch/err")"
}
# cbbg's limits, which the script checks before it makes anything.
refused "robustness_study.sh: --seeds must be a whole number from 1 to 10000; got '99999'" \
  --plant analytic --seeds 99999
refused "robustness_study.sh: --jobs must be a whole number from 1 to 1024; got '2000'" \
  --plant analytic --seeds 2 --jobs 2000
# cbbg refusing the study's first command for a reason of its own (an unknown key here).
printf '#!/bin/sh\nexec "%s" "$@" --set no_such_key=1\n' "$CBBG" >"$scratch/refusing-cbbg"
chmod +x "$scratch/refusing-cbbg"
CBBG="$scratch/refusing-cbbg" refused \
  "robustness_study.sh: the transfer run: --set no_such_key=1: unknown key 'no_such_key'" \
  --plant analytic --seeds 2

# The corrected command.
"$study" --plant analytic --seeds 2 --jobs 2 --out "$whole" >/dev/null 2>&1
rows="$(grep -c '^| [a-z]' "$whole/robustness.md")"
[[ "$rows" == 22 ]] || fail "robustness.md has $rows rows; expected 1 header + 21 values"
grep -q '^| body mass and inertias x | 1 | .*/10 | .*/10 | 10/10 |$' "$whole/robustness.md" ||
  fail "the nominal robot's row is not 2 seeds x 5 angles per arm with pd_only balancing all"

# Killed while the transfer run trains (one job, so that it lasts), then run again.
setsid "$study" --seeds 2 --jobs 1 --out "$scratch/killed" >/dev/null 2>&1 &
pid=$!
for _ in $(seq 1 400); do
  compgen -G "$scratch/killed/transfer.partial/tasks/*.run" >/dev/null && break
  sleep 0.02
done
kill -KILL -- "-$pid" 2>/dev/null || true
wait "$pid" 2>/dev/null || true
# A SIGKILL is delivered, not done: the group's cbbg may hold its lock a moment longer.
for _ in $(seq 1 250); do pgrep -g "$pid" >/dev/null || break; sleep 0.02; done
[[ -d "$scratch/killed/transfer.partial" && ! -f "$scratch/killed/robustness.md" ]] ||
  fail "the kill came too late to test a resume"
"$study" --seeds 2 --jobs 2 --out "$scratch/killed" >/dev/null 2>&1
diff -r "$whole" "$scratch/killed" || fail "the resumed study differs from the whole one"

# Stopped by cbbg's fault hook after some tasks were kept, then run again.
status=0
CBBG_FAULT_AT=task:record@3 "$study" --seeds 2 --jobs 1 --out "$scratch/faulted" \
  >/dev/null 2>&1 || status=$?
[[ "$status" == 86 && -d "$scratch/faulted/transfer.partial" ]] ||
  fail "the fault hook did not stop the study while it trained (exit $status)"
"$study" --seeds 2 --jobs 2 --out "$scratch/faulted" >/dev/null 2>&1
diff -r "$whole" "$scratch/faulted" || fail "the study stopped while training differs"

# Stopped after the results were published and before cbbg had cleaned up (cbbg's fault
# hook), then run again: the resume must finish the commit.
status=0
CBBG_FAULT_AT=commit:clean "$study" --seeds 2 --jobs 2 --out "$scratch/published" \
  >/dev/null 2>&1 || status=$?
[[ "$status" == 86 && -e "$scratch/published/transfer/.cbbg-run" ]] ||
  fail "the fault hook did not stop the study after its publish (exit $status)"
"$study" --seeds 2 --jobs 2 --out "$scratch/published" >/dev/null 2>&1
diff -r "$whole" "$scratch/published" ||
  fail "the study stopped after a publish and run again differs from the whole one"

# Stopped while training, then beside the run the staging folder of a killed cbbg and a
# half-written table, named after a pid that runs (as a reused pid would): run again, the
# study removes them under its lock and ends with the whole one's bytes. A staging folder
# whose lock a live process holds is another cbbg's: refused, and left as it was.
status=0
CBBG_FAULT_AT=task:record@3 "$study" --seeds 2 --jobs 1 --out "$scratch/leftover" \
  >/dev/null 2>&1 || status=$?
[[ "$status" == 86 ]] || fail "the fault hook did not stop the study (exit $status)"
leftover="$scratch/leftover/.transfer.partial.cbbg-tmp-$(hostname)-$$-0"
mkdir -p "$leftover/tasks"
: >"$leftover/.cbbg-lock"
echo "half a table" >"$scratch/leftover/.robustness.md.cbbg-tmp-$(hostname)-$$-0"
exec 7<"$leftover/.cbbg-lock"
flock 7
status=0
"$study" --seeds 2 --jobs 2 --out "$scratch/leftover" 2>"$scratch/err" || status=$?
[[ "$status" == 2 && "$(cat "$scratch/err")" == "robustness_study.sh: $leftover is in use by another cbbg run; wait for it to end" &&
   -d "$leftover" ]] ||
  fail "a staging folder a live cbbg holds was not refused (exit $status): $(cat "$scratch/err")"
exec 7<&-
"$study" --seeds 2 --jobs 2 --out "$scratch/leftover" >/dev/null 2>&1 ||
  fail "the study beside its leftovers failed"
diff -r "$whole" "$scratch/leftover" || fail "the study run on beside its leftovers differs"

# Two at once on one new --out: one makes the study, the other is refused with one line
# naming it and leaves nothing; the study is the whole one's.
for k in 1 2; do
  { status=0
    "$study" --seeds 2 --jobs 2 --out "$scratch/twice/study" >/dev/null 2>"$scratch/err.$k" ||
      status=$?
    echo "$status"; } >"$scratch/status.$k" &
done
wait
statuses="$(cat "$scratch/status.1" "$scratch/status.2" | sort | tr '\n' ' ')"
[[ "$statuses" == "0 2 " ]] || fail "two studies at once exited $statuses"
for k in 1 2; do
  [[ "$(cat "$scratch/status.$k")" != 2 ||
     "$(cat "$scratch/err.$k")" == "robustness_study.sh: $scratch/twice/study is in use by another robustness_study.sh (or the cbbg it started); wait for it to end" ]] ||
    fail "the second study at once said: $(cat "$scratch/err.$k")"
done
[[ "$(ls -A "$scratch/twice")" == study ]] || fail "two studies at once left $(ls -A "$scratch/twice")"
diff -r "$whole" "$scratch/twice/study" || fail "the study run beside a refused one differs"

# A folder it did not make, and another study's settings.
mkdir "$scratch/mine"
status=0
"$study" --seeds 2 --out "$scratch/mine" 2>"$scratch/err" || status=$?
[[ "$status" == 2 ]] && grep -q "exists and was not made by this script" "$scratch/err" ||
  fail "a foreign folder was not refused with exit 2: $(cat "$scratch/err")"
status=0
"$study" --seeds 3 --out "$whole" 2>"$scratch/err" || status=$?
[[ "$status" == 2 ]] && grep -q "holds a study with plant=analytic seeds=2" "$scratch/err" ||
  fail "a study of other settings was not refused with exit 2: $(cat "$scratch/err")"
status=0
"$study" --seeds 0 --out "$scratch/zero" 2>"$scratch/err" || status=$?
[[ "$status" == 2 && ! -e "$scratch/zero" ]] &&
  grep -q "^robustness_study.sh: --seeds must be a whole number from 1 to 10000; got '0'" \
    "$scratch/err" ||
  fail "--seeds 0 was not refused with exit 2 before any folder was made: $(cat "$scratch/err")"
echo "test_robustness_study: refusals leave nothing; 21 rows; killed while training, or" \
  "stopped after a publish, and run again to the same bytes, beside leftovers too; two at once:" \
  "one refused; foreign folders refused"
