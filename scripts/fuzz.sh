#!/usr/bin/env bash
# Builds the config loader's libFuzzer targets (tests/fuzz, with clang, in build-fuzz/) and runs
# each on RUNS generated inputs (default 20000), starting from its seed corpus in
# tests/fuzz/corpus/<target>/. Exits non-zero if any target crashes, hangs (an input taking over
# 5 s), leaks or trips a sanitizer; the input that did it is saved as
# build-fuzz/artifacts/<target>-crash-... (or timeout-, leak-, oom-) and can be replayed with
#   build-fuzz/<target> build-fuzz/artifacts/<file>
#   fuzz.sh [RUNS]
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
runs="${1:-20000}"
max_seconds=300  # per target: a safety cap in case inputs become slow; RUNS normally ends first
build="$root/build-fuzz"

cmake -S "$root/tests/fuzz" -B "$build" -G Ninja -DCMAKE_CXX_COMPILER=clang++ >/dev/null
cmake --build "$build" --parallel 2

export ASAN_OPTIONS=detect_leaks=1
export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
mkdir -p "$build/artifacts"
failed=()
for target in config_fuzzer set_fuzzer; do
  # New inputs go to a scratch corpus in the build tree; the seeds in the source tree stay as
  # they are.
  corpus="$build/corpus/$target"
  mkdir -p "$corpus"
  echo "fuzz: $target, $runs inputs"
  if ! "$build/$target" -runs="$runs" -max_total_time="$max_seconds" -timeout=5 \
    -rss_limit_mb=2048 -dict="$root/tests/fuzz/config.dict" \
    -artifact_prefix="$build/artifacts/$target-" -print_final_stats=1 \
    "$corpus" "$root/tests/fuzz/corpus/$target"; then
    failed+=("$target")
  fi
done

if ((${#failed[@]} > 0)); then
  echo "fuzz: FAILED: ${failed[*]} (inputs in $build/artifacts/)" >&2
  exit 1
fi
echo "fuzz: no crash, hang, leak or sanitizer report in $runs inputs per target"
