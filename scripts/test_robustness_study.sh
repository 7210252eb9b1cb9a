#!/usr/bin/env bash
# The robustness study end to end, small (analytic plant, 2 seeds): it writes a table of
# every perturbation's values; killed part-way and run again, it ends with the bytes of an
# uninterrupted study; and it refuses a folder it did not make.
#   test_robustness_study.sh BUILD_DIR
set -euo pipefail
export CBBG="$(cd "$1" && pwd)/apps/cbbg"
study="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)/robustness_study.sh"
scratch="$(mktemp -d /tmp/cbbg-robustness.XXXXXX)"
trap 'rm -rf "$scratch"' EXIT
fail() { echo "test_robustness_study: $1" >&2; exit 1; }

"$study" --seeds 2 --jobs 2 --out "$scratch/whole" >/dev/null 2>&1
rows="$(grep -c '^| [a-z]' "$scratch/whole/robustness.md")"
[[ "$rows" == 22 ]] || fail "robustness.md has $rows rows; expected 1 header + 21 values"
grep -q '^| body mass and inertias x | 1 | .*/10 | .*/10 | 10/10 |$' "$scratch/whole/robustness.md" ||
  fail "the nominal robot's row is not 2 seeds x 5 angles per arm with pd_only balancing all"

# Killed while its second sweep runs, then run again.
setsid "$study" --seeds 2 --jobs 2 --out "$scratch/killed" >/dev/null 2>&1 &
pid=$!
for _ in $(seq 1 300); do
  [[ -d "$scratch/killed/com_height_scale.partial" ]] && break
  sleep 0.05
done
kill -KILL -- "-$pid" 2>/dev/null || true
wait "$pid" 2>/dev/null || true
[[ ! -f "$scratch/killed/robustness.md" ]] || fail "the kill came too late to test a resume"
"$study" --seeds 2 --jobs 2 --out "$scratch/killed" >/dev/null 2>&1
diff -r "$scratch/whole" "$scratch/killed" || fail "the resumed study differs from the whole one"

# A folder it did not make, and another study's settings.
mkdir "$scratch/mine"
status=0
"$study" --seeds 2 --out "$scratch/mine" 2>"$scratch/err" || status=$?
[[ "$status" == 2 ]] && grep -q "exists and was not made by this script" "$scratch/err" ||
  fail "a foreign folder was not refused with exit 2: $(cat "$scratch/err")"
status=0
"$study" --seeds 3 --out "$scratch/whole" 2>"$scratch/err" || status=$?
[[ "$status" == 2 ]] && grep -q "holds a study with plant=analytic seeds=2" "$scratch/err" ||
  fail "a study of other settings was not refused with exit 2: $(cat "$scratch/err")"
status=0
"$study" --seeds 0 --out "$scratch/zero" 2>"$scratch/err" || status=$?
[[ "$status" == 2 && ! -e "$scratch/zero" ]] &&
  grep -q "^robustness_study.sh: --seeds must be a whole number >= 1; got '0'" "$scratch/err" ||
  fail "--seeds 0 was not refused with exit 2 before any folder was made: $(cat "$scratch/err")"
echo "test_robustness_study: 21 rows; killed and resumed to the same bytes; foreign folders refused"
