#!/usr/bin/env bash
# Builds an earlier commit of this repository beside the tree, for a benchmark that compares
# against it in one run (bench.sh, bench_robustness_study.sh): extracted with git archive into
# build/bench-baseline/src once per commit (a folder only these scripts make), built with
# the targets given into build/bench-baseline/build. Prints that folder.
#
#   scripts/baseline_tree.sh COMMIT TARGET...
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
commit="$1"
shift
baseline="$root/build/bench-baseline"
if [[ -e "$baseline" && ! -f "$baseline/.cbbg-bench-baseline" ]]; then
  echo "baseline_tree.sh: $baseline exists and was not made by cbbg's benchmarks; move it away" >&2
  exit 1
fi
if [[ "$(cat "$baseline/.cbbg-bench-baseline" 2>/dev/null)" != "$commit" ]]; then
  # Only ever a git archive this script extracted and its build. The build goes too: the
  # archive's files keep the commit's times, older than another commit's objects, which a
  # build kept would take for up to date and link with this commit's.
  rm -rf "$baseline/src" "$baseline/build"
  mkdir -p "$baseline/src"
  echo "$commit" > "$baseline/.cbbg-bench-baseline"
  git -C "$root" archive "$commit" | tar -x -C "$baseline/src"
fi
# The replay page's npm packages are this tree's (the archive has none; no download).
[[ -e "$baseline/src/replay/page/node_modules" ]] ||
  ln -s "$root/replay/page/node_modules" "$baseline/src/replay/page/node_modules"
echo "building the baseline $commit in $baseline ..." >&2
log="$baseline/build.log"
if ! { cmake -S "$baseline/src" -B "$baseline/build" -G Ninja -DCMAKE_BUILD_TYPE=Release &&
       cmake --build "$baseline/build" --parallel "$(nproc)" --target "$@"; } >"$log" 2>&1; then
  echo "baseline_tree.sh: building $commit failed; the end of $log:" >&2
  tail -n 15 "$log" >&2
  exit 1
fi
echo "$baseline"
