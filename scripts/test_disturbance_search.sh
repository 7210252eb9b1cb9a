#!/usr/bin/env bash
# The disturbance search end to end, small (analytic plant, 1 seed per point): bad options
# are refused; round 1's 288 points run as 3 shards through GNU parallel and merge, for the
# transfer protocol and for exp2; the costs and the front, holding ground included, are
# written; run again, it keeps the sweeps and writes the front again; round 2's grid is one
# cbbg checks.
#   test_disturbance_search.sh BUILD_DIR
set -euo pipefail
export CBBG="$(cd "$1" && pwd)/apps/cbbg"
search="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)/disturbance_search.sh"
scratch="$(mktemp -d /tmp/cbbg-search.XXXXXX)"
trap 'rm -rf "$scratch"' EXIT
fail() { echo "test_disturbance_search: $1" >&2; exit 1; }

status=0
"$search" --seeds 1 --shards 0 --out "$scratch/no" 2>"$scratch/err" || status=$?
[[ $status == 2 ]] && grep -qF "disturbance_search.sh: --shards must be a whole number from 1 to 9999; got '0'" "$scratch/err" ||
  fail "--shards 0 was not refused (exit $status): $(cat "$scratch/err")"
[[ ! -e "$scratch/no" && ! -e "$scratch/no.partial" ]] || fail "a refused search left a folder"
status=0
"$search" --seeds 1 --round 3 --out "$scratch/no" 2>"$scratch/err" || status=$?
[[ $status == 2 ]] && grep -qF "disturbance_search.sh: --round must be 1 or 2; got '3'" "$scratch/err" ||
  fail "--round 3 was not refused (exit $status): $(cat "$scratch/err")"
[[ ! -e "$scratch/no" ]] || fail "a refused search left a folder"

touch "$scratch/theirs-costs.txt"
status=0
"$search" --seeds 1 --out "$scratch/theirs" 2>"$scratch/err" || status=$?
[[ $status == 2 ]] && grep -qF "$scratch/theirs-costs.txt exists, but $scratch/theirs is no finished search: move it away first" "$scratch/err" ||
  fail "a costs file of someone else's was not refused (exit $status): $(cat "$scratch/err")"
[[ -e "$scratch/theirs-costs.txt" ]] || fail "a costs file of someone else's was removed"

out="$scratch/search"
"$search" --plant analytic --seeds 1 --jobs 2 --shards 3 --out "$out" >"$scratch/first" 2>&1 ||
  fail "the search failed: $(tail -3 "$scratch/first")"
for sweep in transfer exp2; do
  grep -q "^$sweep shards: 3 through GNU parallel, 2 at once; wall [0-9.]* s$" "$out-costs.txt" ||
    fail "the costs lack the $sweep shards' wall time: $(cat "$out-costs.txt")"
  grep -q "^$sweep merge: wall [0-9.]* s$" "$out-costs.txt" || fail "the costs lack the $sweep merge's time"
  grep -q "^$sweep bytes: [0-9]*; files: [0-9]*$" "$out-costs.txt" || fail "the costs lack the $sweep bytes"
done
for dir in "$out" "$out-holding"; do
  [[ "$(($(wc -l <"$dir/sweep.csv") - 1))" == 288 ]] || fail "$dir/sweep.csv has no row per grid point"
done
grep -qF "288 grid points x 1 seeds" "$out/front.md" || fail "front.md does not say its size"
grep -qE "^\| 001 \(the paper's\) \| .* \| (0|100)% \| [0-9.]+ \| [01]/1 \|$" "$out/front.md" ||
  fail "front.md lacks the paper's point, holding ground measured: $(grep -F "(the paper's)" "$out/front.md")"
cp "$out/sweep.csv" "$scratch/sweep.csv"
cp "$out-holding/sweep.csv" "$scratch/holding.csv"
"$search" --plant analytic --seeds 1 --jobs 2 --shards 3 --out "$out" >"$scratch/second" 2>&1 ||
  fail "the search run again failed"
cmp -s "$out/sweep.csv" "$scratch/sweep.csv" || fail "run again, the sweep changed"
cmp -s "$out-holding/sweep.csv" "$scratch/holding.csv" || fail "run again, the exp2 sweep changed"
out="$scratch/round2"
"$search" --plant analytic --seeds 1 --jobs 2 --shards 2 --round 2 --out "$out" >"$scratch/round2.log" 2>&1 ||
  fail "round 2 failed: $(tail -3 "$scratch/round2.log")"
for dir in "$out" "$out-holding"; do
  [[ "$(($(wc -l <"$dir/sweep.csv") - 1))" == 288 ]] || fail "round 2's $dir/sweep.csv has no row per grid point"
done
grep -qF "The paper's learner is not a point of this grid." "$out/front.md" ||
  fail "round 2's front.md claims the paper's point"
grep -qE "^\| [0-9]{3} \| inputs pitch.*, units (grid|per_axis), width [0-9.]+, .*body_mass_spread 0\.?[0-9]* \| .* \| (0|100)% \| " "$out/front.md" ||
  fail "round 2's front lacks its keys or holding ground: $(sed -n 8,9p "$out/front.md")"
echo "test_disturbance_search: ok"
