#!/usr/bin/env bash
# The robustness study's cost against an earlier release's, side by side in one run: the
# earlier commit's own robustness_study.sh and cbbg (built by baseline_tree.sh in
# build/bench-baseline/), then this tree's; the CPU time
# (user + system, of the script and every process it starts) and the wall time of each, their
# ratio, and whether the rows both tables make are the same bytes (an earlier study's push went
# through the motors; this one's comes from outside, a different perturbation).
#
#   scripts/bench_robustness_study.sh --against <commit> [--plant analytic|simbody]
#                                     [--seeds N] [--jobs J]
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
against="" plant=simbody seeds=10 jobs="$(nproc)"
usage() { echo "bench_robustness_study.sh: $1" >&2; exit 2; }
while [[ $# -gt 0 ]]; do
  [[ $# -ge 2 ]] || usage "$1 needs a value"
  case "$1" in
    --against) against="$2" ;;
    --plant) plant="$2" ;;
    --seeds) seeds="$2" ;;
    --jobs) jobs="$2" ;;
    *) usage "unknown option '$1'" ;;
  esac
  shift 2
done
[[ -n "$against" ]] || usage "--against <commit> is required"
commit="$(git -C "$root" rev-parse --verify --quiet "$against^{commit}")" ||
  usage "--against: '$against' is not a commit of this repository"

baseline="$("$root/scripts/baseline_tree.sh" "$commit" cbbg)"
cmake --build "$root/build" --parallel "$(nproc)" --target cbbg >/dev/null

out="$(mktemp -d "${TMPDIR:-/tmp}/cbbg-robustness-bench.XXXXXX")"
trap 'rm -rf "$out"' EXIT
# study <name> <sources> <build>: the sources' study with the build's cbbg; "<cpu s> <wall s>"
# in $out/<name>.cost
study() {
  local name="$1" sources="$2" build="$3"
  echo "== $name: $sources/scripts/robustness_study.sh --plant $plant --seeds $seeds --jobs $jobs" >&2
  CBBG="$build/apps/cbbg" /usr/bin/time -f "%U %S %e" -o "$out/$name.time" \
    "$sources/scripts/robustness_study.sh" --plant "$plant" --seeds "$seeds" --jobs "$jobs" \
    --out "$out/$name" >/dev/null 2>&1
  awk '{ printf "%.1f %.1f\n", $1 + $2, $3 }' "$out/$name.time" > "$out/$name.cost"
}
study baseline "$baseline/src" "$baseline/build"
study this "$root" "$root/build"
read -r base_cpu base_wall < "$out/baseline.cost"
read -r this_cpu this_wall < "$out/this.cost"
# The rows both studies make: a study from before the push from outside pushed through the
# motors (push on each wheel), a different perturbation, whose rows are left out.
shared_rows() { grep -v '^| push ' "$1"; }
same="the same bytes"
cmp -s <(shared_rows "$out/baseline/robustness.md") <(shared_rows "$out/this/robustness.md") ||
  same="DIFFERENT"
printf '| study (%s plant, %s seeds, %s jobs) | CPU s | wall s |\n|---|---|---|\n' \
  "$plant" "$seeds" "$jobs"
printf '| %s (its own script and cbbg) | %s | %s |\n' "${commit:0:7}" "$base_cpu" "$base_wall"
printf '| this tree | %s | %s |\n' "$this_cpu" "$this_wall"
awk -v a="$base_cpu" -v b="$this_cpu" 'BEGIN { printf "CPU ratio: %.1fx less\n", a / b }'
echo "robustness.md of the two, the rows both make (mass, CoM height, noise): $same"
[[ "$same" == "the same bytes" ]] ||
  diff <(shared_rows "$out/baseline/robustness.md") <(shared_rows "$out/this/robustness.md") || true
