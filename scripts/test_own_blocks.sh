#!/usr/bin/env bash
# The own-blocks example (examples/own_blocks/), built against the installed package: a
# critic, an exploration and a reward of the user's, each in its slot, through exp1 and exp3,
# a resume after a kill (the same bytes as a run never killed) and `eval` of the weights its
# two-part critic learnt (a version-2 weights file).
#   test_own_blocks.sh OWN_BLOCKS_PROGRAM SCRATCH_DIR
set -euo pipefail
program="$1"
scratch="$2"
mkdir -p "$scratch"
cd "$scratch"
fail() { echo "own blocks: $*" >&2; exit 1; }
quick=(--set plant.kind=analytic --set seeds=2 --set log.decimation=10 --jobs 2 --no-figures)
arms='arms=[cbbg,own_critic,own_exploration,own_reward]'

# exp1: every arm runs; the two-part critic's weights file holds both parts.
"$program" run "${quick[@]}" --set "$arms" --out exp1 >exp1.log
grep -q '"own_reward"' exp1/summary.json || fail "exp1 has no own_reward arm"
weights=exp1/weights/own_critic_seed1.txt
head -1 "$weights" | grep -qx "cbbg-weights 2" || fail "$weights is not version 2"
grep -qx "critic visits 49" "$weights" || fail "$weights lacks the critic's visits"
head -1 exp1/weights/cbbg_seed1.txt | grep -qx "cbbg-weights 1" ||
  fail "the paper's weights are no longer version 1"
# steps.csv records the reward the controller learns from: the pitch cost takes values the
# sliding-surface reward (0 or -1) never does.
column="$(head -1 exp1/steps.csv | tr ',' '\n' | grep -nx reward | cut -d: -f1)"
costs="$(grep "^own_reward," exp1/steps.csv | cut -d, -f"$column" | sort -u | wc -l)"
((costs > 2)) || fail "steps.csv's reward of own_reward has $costs values, not the pitch cost"

# exp3, each swap learning until its actor alone balances.
"$program" run "${quick[@]}" --experiment exp3 --set max_trials=10 --set "$arms" --out exp3 \
  >exp3.log
grep -q '"trials_to_skill"' exp3/summary.json || fail "exp3 has no trials to skill"

# Killed after its third task is recorded, resumed: the same bytes as a run never killed.
set +e
CBBG_FAULT_AT=task:record@3 "$program" run "${quick[@]}" --set "$arms" --out resumed \
  >/dev/null 2>&1
status=$?
set -e
[[ $status == 86 ]] || fail "the killed run exited $status, not at the fault point"
"$program" run --resume resumed --jobs 2 >/dev/null
diff -r exp1 resumed >/dev/null || fail "the resumed run differs from the run never killed"
if find . -name '*cbbg-tmp*' | grep -q .; then fail "a temporary file was left"; fi

# eval of the two-part critic's weights, on the arm that learnt them.
"$program" eval --load-weights "$weights" --set plant.kind=analytic --out eval >eval.log ||
  fail "eval of $weights failed: $(cat eval.log)"
test -s eval/evaluation.csv || fail "eval wrote no evaluation.csv"
echo "own blocks: ok"
