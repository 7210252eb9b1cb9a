#!/usr/bin/env bash
# The Python benchmark (bench/python/bench_python.py) against the build tree's module, with
# Debian's python3 (the one with NumPy): a Python block against its C++ twin per tick, and
# the environment's steps per second against a NumPy-only step, measured in one run.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${BUILD_DIR:-$root/build}"
PYTHONPATH="$build/python" exec /usr/bin/python3 "$root/bench/python/bench_python.py" "$@"
