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
  rm -rf "$baseline/src"  # only ever a git archive this script extracted
  mkdir -p "$baseline/src"
  echo "$commit" > "$baseline/.cbbg-bench-baseline"
  git -C "$root" archive "$commit" | tar -x -C "$baseline/src"
fi
# The replay page's npm packages are this tree's (the archive has none; no download).
[[ -e "$baseline/src/replay/page/node_modules" ]] ||
  ln -s "$root/replay/page/node_modules" "$baseline/src/replay/page/node_modules"
echo "building the baseline $commit in $baseline ..." >&2
cmake -S "$baseline/src" -B "$baseline/build" -G Ninja -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build "$baseline/build" --parallel "$(nproc)" --target "$@" >/dev/null
echo "$baseline"
