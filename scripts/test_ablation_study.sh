#!/usr/bin/env bash
# The ablation study end to end, small (analytic plant, 2 seeds, the paper and one variant):
# a bad --variants entry, and a user's config that cbbg refuses, are refused with exit 2 and
# one line, leaving nothing; the study writes ablation.md, a row per variant and arm with
# exp1's failures and exp3's trials to skill, the variant paired with the paper's learner
# (mean difference, sign test), and prints it; stopped by cbbg's fault hook while training
# and run again, it ends with the bytes of an uninterrupted study; run again once done, it
# runs nothing (cbbg only checks the commands) and leaves the same bytes.
#   test_ablation_study.sh BUILD_DIR
set -euo pipefail
CBBG="$(cd "$1" && pwd)/apps/cbbg"
export CBBG
study="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)/ablation_study.sh"
scratch="$(mktemp -d /tmp/cbbg-ablation.XXXXXX)"
trap 'rm -rf "$scratch"' EXIT
fail() { echo "test_ablation_study: $1" >&2; exit 1; }
variant=fixed_temperature
options=(--plant analytic --seeds 2 --jobs 1)
small=("${options[@]}" --variants "paper,$variant")

# expect_refusal TEXT OPTION...: the study exits 2 saying one line that holds TEXT, nothing on
# stdout, and no trace of its --out (nor of the folder above it).
expect_refusal() {
  local text="$1" status=0
  shift
  "$study" "$@" --out "$scratch/refused/study" >"$scratch/said" 2>"$scratch/complained" ||
    status=$?
  [[ ! -e "$scratch/refused" ]] || fail "$* left $scratch/refused behind"
  if [[ $status != 2 || -s "$scratch/said" || "$(wc -l <"$scratch/complained")" != 1 ]] ||
     ! grep -qF -- "$text" "$scratch/complained"; then
    fail "$* exited $status and said: $(cat "$scratch/said" "$scratch/complained")"
  fi
}
expect_refusal "ablation_study.sh: --variants: no variant 'no_such' (there are paper, gaussian_exploration," \
  --seeds 2 --variants paper,no_such
expect_refusal "ablation_study.sh: --variants must begin with paper" --seeds 2 --variants "$variant"
expect_refusal "ablation_study.sh: --variants: no config file '$scratch/none.yaml'" \
  --seeds 2 --variants "paper,$scratch/none.yaml"
# A user's config that cbbg refuses, the last variant: refused before the paper's runs.
printf 'exploration:\n  kind: uniform\n' >"$scratch/bad_kind.yaml"
expect_refusal "ablation_study.sh: --variants $scratch/bad_kind.yaml: " \
  "${options[@]}" --variants "paper,$variant,$scratch/bad_kind.yaml"
grep -qF "exploration.kind" "$scratch/complained" ||
  fail "the refusal does not name exploration.kind: $(cat "$scratch/complained")"

whole="$scratch/whole"
"$study" "${small[@]}" --out "$whole" >"$scratch/printed" 2>"$scratch/log" ||
  fail "the small study failed: $(tail -n 5 "$scratch/log")"
table="$whole/ablation.md"
grep -q '| variant | arm | failures before the first success (exp1).* sign test p ' "$table" ||
  fail "ablation.md has no sign test column: $(head -n 3 "$table")"
for arm in cbbg bg_only; do
  grep -q "^| paper | $arm | [0-9.]* \[[0-9]*, [0-9]*\], [0-2]/2 | " "$table" ||
    fail "ablation.md has no row of the paper's $arm"
  # Both figures paired: the mean difference [interval], then p (more/fewer/tied).
  pairing='[-+][0-9.]* \[[-+][0-9.]*, [-+][0-9.]*\] | [0-9.e-]* ([0-2]/[0-2]/[0-2])'
  grep -q "^| $variant | $arm | .* | $pairing | .* | $pairing |$" "$table" ||
    fail "the $variant row of $arm is not paired with the paper's: $(grep "^| $variant | $arm " "$table")"
done
grep -q '^## The cerebellum' "$table" || fail "ablation.md has no bg_only - cbbg table"
[[ "$(tail -c "$(wc -c <"$table")" "$scratch/printed")" == "$(cat "$table")" ]] ||
  fail "the study did not print the table it wrote"
[[ "$(head -c 8 "$whole/ablation.png" | od -An -tx1 | tr -d ' \n')" == 89504e470d0a1a0a ]] ||
  fail "ablation.png is not a PNG"

# Stopped by cbbg's fault hook while the first run trains, then run again.
status=0
CBBG_FAULT_AT=task:record@2 "$study" "${small[@]}" --out "$scratch/faulted" >/dev/null 2>&1 ||
  status=$?
[[ "$status" == 86 && -d "$scratch/faulted/paper/exp1.partial" ]] ||
  fail "the fault hook did not stop the study while it trained (exit $status)"
"$study" "${small[@]}" --out "$scratch/faulted" >/dev/null 2>&1 || fail "the resumed study failed"
diff -r "$whole" "$scratch/faulted" || fail "the study stopped while training differs"

# Once done, run again through a cbbg that logs its commands: every one is a check.
cp -a "$whole" "$scratch/done"
printf '#!/bin/sh\necho "$*" >>"%s"\nexec "%s" "$@"\n' "$scratch/commands" "$CBBG" \
  >"$scratch/logging-cbbg"
chmod +x "$scratch/logging-cbbg"
CBBG="$scratch/logging-cbbg" "$study" "${small[@]}" --out "$whole" >/dev/null 2>&1 ||
  fail "the study run again once done failed"
[[ -s "$scratch/commands" ]] || fail "the study run again did not even check its commands"
ran="$(grep -v -- ' --check$' "$scratch/commands" || true)"
[[ -z "$ran" ]] || fail "the study run again once done ran: $ran"
diff -r "$scratch/done" "$whole" || fail "the study run again once done changed its folder"
echo "test_ablation_study: bad variants refused in one line leaving nothing; ablation.md's rows" \
  "paired with the paper's (sign test), printed; stopped and run again to the same bytes;" \
  "run again once done: nothing run, the same bytes"
