#!/usr/bin/env bash
# Configures and builds cbbg (Release) in build/, installing missing packages first, then
# installs the Python module where Debian's python3 finds it (/usr/local/lib/python3.X/
# dist-packages), so `/usr/bin/python3 -c "import cbbg"` works; the build tree's copy is
# build/python (PYTHONPATH=build/python).
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
"$root/scripts/setup.sh"
cmake -S "$root" -B "$root/build" -G Ninja -DCMAKE_BUILD_TYPE=Release
cmake --build "$root/build" --parallel "$(nproc)"
sudo=""
if [ "$(id -u)" -ne 0 ]; then sudo="sudo"; fi
$sudo cmake --install "$root/build" --component python > /dev/null
