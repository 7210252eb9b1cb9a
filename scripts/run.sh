#!/usr/bin/env bash
# Sets up, builds and runs the main job: the paper's experiment 1 with the built-in defaults
# (`cbbg run`: arms cbbg and bg_only, 20 seeds, the Simbody plant), results in results/.
# It builds only what the job needs (scripts/build.sh --main: the `cbbg` command and the
# Python module), not the tests (scripts/test.sh builds those).
# Extra arguments go to `cbbg run` (see `build/apps/cbbg run --help`).
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
"$root/scripts/build.sh" --main
cd "$root"
exec "$root/build/apps/cbbg" run "$@"
