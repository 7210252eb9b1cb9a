#!/usr/bin/env bash
# Sets up, builds and runs the main job. Until the experiments land this is the demo
# diagram of examples/: it writes results/demo/ (a CSV log and the block diagram).
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
"$root/scripts/build.sh"
"$root/build/examples/spring_mass" "$root/results/demo"
