#!/usr/bin/env bash
# The vectorised environment's steps per second (bench/python/bench_vec_env.py) against the
# build tree's module, with Debian's python3 (the one with NumPy): cbbg.VecBalanceEnv against
# N cbbg.BalanceEnv stepped from Python, for each plant kind built, in one run.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${BUILD_DIR:-$root/build}"
PYTHONPATH="$build/python" exec /usr/bin/python3 "$root/bench/python/bench_vec_env.py" "$@"
