#!/usr/bin/env bash
# Builds cbbg with AddressSanitizer and UndefinedBehaviorSanitizer (the `asan` preset of
# CMakePresets.json: build-asan/, -O1 -g, assertions on, no benchmarks) and runs its tests.
# A memory error, a leak or any undefined behaviour fails the test it happens in.
# Left out: example_find_package (it links the installed, sanitized libraries into a plain
# build of examples/, which cannot link), and format_check and PlotResults (they run no
# compiled code); scripts/test.sh runs all three.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cd "$root"  # the presets are found from the working directory
cmake --preset asan >/dev/null
cmake --build --preset asan --parallel "$(nproc)"

export ASAN_OPTIONS=detect_leaks=1
export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
ctest --test-dir "$root/build-asan" --output-on-failure --parallel "$(nproc)" \
  --exclude-regex '^(example_find_package|format_check|PlotResults)$'
