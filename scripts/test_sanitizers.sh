#!/usr/bin/env bash
# Builds cbbg with AddressSanitizer and UndefinedBehaviorSanitizer (the `asan` preset of
# CMakePresets.json: build-asan/, -O1 -g1, assertions on, no benchmarks) and runs its tests.
# -g1 keeps the line tables a report needs and drops the rest, a quarter of the compile time.
# A memory error, a leak or any undefined behaviour fails the test it happens in.
#   test_sanitizers.sh         the tests of framework/, config/, blocks/, diagrams/,
#                              experiments/, environment/, store/ and replay/ (several run both
#                              plants, Simbody's too)
#   test_sanitizers.sh --all   every test: adds plant/'s and the cbbg command's, and takes
#                              about half as long again (the sanitizers make compiling slow)
# --all leaves out example_find_package (it links the installed, sanitized libraries into a
# plain build of examples/, which cannot link), and format_check and PlotResults (they run no
# compiled code); scripts/test.sh runs all three.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
areas=(framework config blocks diagrams records experiments environment store replay)
case "${1:-}" in
  "") all=false ;;
  --all) all=true ;;
  *)
    echo "usage: test_sanitizers.sh [--all]" >&2
    exit 2
    ;;
esac

cd "$root"  # the presets are found from the working directory
cmake --preset asan >/dev/null
export ASAN_OPTIONS=detect_leaks=1
export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1

if $all; then
  cmake --build --preset asan --parallel "$(nproc)"
  ctest --test-dir "$root/build-asan" --output-on-failure --parallel "$(nproc)" \
    --exclude-regex '^(example_find_package|format_check|PlotResults)$'
  exit
fi

# Each area's directory target builds just its tests (and what they link); ctest run in an
# area's build directory runs just the tests registered there.
targets=()
for area in "${areas[@]}"; do targets+=("tests/$area/all"); done
cmake --build --preset asan --parallel "$(nproc)" --target "${targets[@]}"
failed=()
for area in "${areas[@]}"; do
  ctest --test-dir "$root/build-asan/tests/$area" --output-on-failure --parallel "$(nproc)" ||
    failed+=("$area")
done
if ((${#failed[@]} > 0)); then
  echo "sanitizers: tests failed in ${failed[*]}" >&2
  exit 1
fi
