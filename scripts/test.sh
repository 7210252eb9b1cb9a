#!/usr/bin/env bash
# Sets up, builds and runs every test (the README's test command; CI runs it): the release
# build's ctest suite (unit tests, format check, plots, the installed-package example, the
# config fuzzers), then the unit tests again under AddressSanitizer and
# UndefinedBehaviorSanitizer (scripts/test_sanitizers.sh).
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
"$root/scripts/build.sh"
ctest --test-dir "$root/build" --output-on-failure --parallel "$(nproc)"
"$root/scripts/test_sanitizers.sh"
