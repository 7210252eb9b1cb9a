#!/usr/bin/env bash
# The baseline study end to end, small (analytic plant, 2 seeds, a few PPO updates): refusals
# leave nothing; it writes the table's three rows and its figure; killed while PPO trains and
# run again, it ends with the figures of an uninterrupted study (the CPU times aside, which
# are measured) and no temporary; a folder it did not make is refused. Needs PyTorch, as the
# study does: without it, it fails saying so.
#   test_baseline_study.sh BUILD_DIR
set -euo pipefail
export CBBG="$(cd "$1" && pwd)/apps/cbbg"
study="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)/baseline_study.sh"
scratch="$(mktemp -d /tmp/cbbg-baseline.XXXXXX)"
killed_group=""
cleanup() {
  [[ -z "$killed_group" ]] || kill -9 -- "-$killed_group" 2>/dev/null || true
  rm -rf "$scratch"
}
trap cleanup EXIT
fail() { echo "test_baseline_study: $1" >&2; exit 1; }
/usr/bin/python3 -c "import torch" 2>/dev/null ||
  fail "python3-torch is not installed, so the study cannot run; scripts/setup.sh installs it"
small=(--plant analytic --seeds 2 --jobs 2 --steps 4096)

# refused MESSAGE OPTION...: exit 2, MESSAGE as the one line, nothing left of the folder.
refused() {
  local message="$1" status=0
  shift
  "$study" "$@" --out "$scratch/new/study" 2>"$scratch/err" || status=$?
  [[ "$status" == 2 && "$(wc -l <"$scratch/err")" == 1 && ! -e "$scratch/new" ]] &&
    grep -qF -- "$message" "$scratch/err" ||
    fail "$* exited $status and said: $(cat "$scratch/err")"
}
refused "baseline_study.sh: --steps must be a whole number from 1 to 999999999; got '0'" --steps 0
refused "baseline_study.sh: --plant must be analytic, simbody or mujoco; got 'moon'" --plant moon
refused "baseline_study.sh: unknown option '--arms'" --arms cbbg

whole="$scratch/whole"
"$study" "${small[@]}" --out "$whole" >/dev/null 2>&1 || fail "the small study failed"
for row in "| cbbg, the paper's learner | 20 (20–20) | 2/2 |" "| bg_only, without the teacher |" \
           "| PPO, 4096 steps |"; do
  grep -qF "$row" "$whole/baseline.md" || fail "baseline.md has no row '$row'"
done
grep -qF "| nominal | +30 % mass | +30 % CoM height | noise 0.05 rad | push 74 N |" \
  "$whole/baseline.md" || fail "baseline.md lacks a condition's column"
[[ "$(head -c 8 "$whole/baseline.png" | od -An -tx1 | tr -d ' \n')" == 89504e470d0a1a0a ]] ||
  fail "baseline.png is not a PNG"

# Killed (the whole process group, SIGKILL) while PPO trains, then run again.
killed="$scratch/killed"
setsid "$study" "${small[@]}" --steps 40960 --out "$killed" >/dev/null 2>&1 &
killed_group=$!
for _ in $(seq 600); do
  pgrep -f "ppo_balance.py .*$killed" >/dev/null && break
  sleep 0.1
done
sleep 1
kill -9 -- "-$killed_group" 2>/dev/null || fail "the study ended before it could be killed"
wait "$killed_group" 2>/dev/null || true
killed_group=""
"$study" "${small[@]}" --steps 40960 --out "$killed" >/dev/null 2>&1 || fail "the resumed study failed"
"$study" "${small[@]}" --steps 40960 --out "$scratch/uninterrupted" >/dev/null 2>&1 ||
  fail "the uninterrupted study failed"
/usr/bin/python3 - "$killed" "$scratch/uninterrupted" <<'EOF' || fail "the resumed study's figures differ"
import json, sys
def figures(folder, seed):
    with open(f"{folder}/ppo/seed_{seed}.json") as f:
        report = json.load(f)
    return {k: v for k, v in report.items() if not k.endswith("cpu_s")}
assert all(figures(sys.argv[1], s) == figures(sys.argv[2], s) for s in (1, 2))
EOF
[[ -z "$(find "$killed" -name '.ppo-*' -o -name '*.cbbg-tmp-*' -o -name '*.partial')" ]] ||
  fail "the resumed study left a temporary: $(find "$killed" -name '.*')"

mkdir "$scratch/mine"
status=0
"$study" "${small[@]}" --out "$scratch/mine" 2>"$scratch/err" || status=$?
[[ $status == 2 ]] && grep -qF "exists and was not made by this script" "$scratch/err" ||
  fail "a folder it did not make was not refused (exit $status)"
echo "test_baseline_study: ok"
