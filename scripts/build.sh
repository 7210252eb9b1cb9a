#!/usr/bin/env bash
# Configures and builds cbbg (Release) in build/, installing missing packages first, then
# installs the Python module where Debian's python3 finds it (/usr/local/lib/python3.X/
# dist-packages), so `/usr/bin/python3 -c "import cbbg"` works; the build tree's copy is
# build/python (PYTHONPATH=build/python).
#   scripts/build.sh          everything: the tests, benchmarks, examples and the
#                             documentation site too (test.sh)
#   scripts/build.sh --main   only the main job's: the `cbbg` command (with the replay page it
#                             writes) and the Python module (run.sh)
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
targets=()
setup=()
case "${1:-}" in
  "") ;;
  --main) targets=(--target cbbg _cbbg) setup=(--main) ;;
  *) echo "build.sh: unknown option '$1' (usage: scripts/build.sh [--main])" >&2; exit 2 ;;
esac
"$root/scripts/setup.sh" "${setup[@]}"
cmake -S "$root" -B "$root/build" -G Ninja -DCMAKE_BUILD_TYPE=Release
# A build configured without the Python module (CBBG_BUILD_PYTHON=OFF) has no _cbbg.
if [[ ${#targets[@]} -gt 0 ]] && grep -qx 'CBBG_BUILD_PYTHON:BOOL=OFF' "$root/build/CMakeCache.txt"; then
  targets=(--target cbbg)
fi
cmake --build "$root/build" --parallel "$(nproc)" "${targets[@]}"
sudo=""
if [ "$(id -u)" -ne 0 ]; then sudo="sudo"; fi
$sudo cmake --install "$root/build" --component python > /dev/null
