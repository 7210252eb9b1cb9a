#!/usr/bin/env bash
# Installs the Debian packages cbbg builds, tests and plots with (only the missing ones),
# then the replay page's npm packages (three.js and its bundler, pinned by
# replay/page/package-lock.json) into replay/page/node_modules.
#   scripts/setup.sh          everything the tests need too (test.sh)
#   scripts/setup.sh --main   only what building and running the main job needs (run.sh):
#                             no sanitizer compiler, fuzzer, Slurm, GNU parallel, Chromium,
#                             PyTorch or documentation tools
#   scripts/setup.sh --docs   what the main job and the documentation site need (docs.sh)
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"

# Building, running and plotting (CMake's configure finds GoogleTest and Benchmark too).
packages=(
  build-essential cmake ninja-build pkg-config git
  libsimbody-dev libeigen3-dev libspdlog-dev libboost-dev
  libcli11-dev libyaml-cpp-dev nlohmann-json3-dev libssl-dev
  libgtest-dev libgmock-dev libbenchmark-dev
  graphviz python3 python3-dev python3-matplotlib python3-numpy pybind11-dev
  # plant.kind mujoco; MuJoCo's CMake package names libqhull_r's headers
  libmujoco-dev libqhull-dev
)
# The documentation site (docs/CMakeLists.txt): the API reference and the user guide.
docs_packages=(doxygen python3-sphinx python3-myst-parser python3-sphinx-rtd-theme)
# The tests' own tools and services.
test_packages=(
  clang clang-format libclang-rt-14-dev libfuzzer-14-dev time python3-pytest
  parallel slurm-wlm munge
  chromium
  # the deep-RL baseline's test (python/examples/ppo_balance.py)
  python3-torch
)
case "${1:-}" in
  "") packages+=("${test_packages[@]}" "${docs_packages[@]}") ;;
  --main) ;;
  --docs) packages+=("${docs_packages[@]}") ;;
  *) echo "setup.sh: unknown option '$1' (usage: scripts/setup.sh [--main | --docs])" >&2; exit 2 ;;
esac
# Node.js and npm may come from Debian or from NodeSource's nodejs (which brings npm along).
command -v node >/dev/null || packages+=(nodejs)
command -v npm >/dev/null || packages+=(npm)

missing=()
for package in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$package" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$package")
  fi
done
if ((${#missing[@]} > 0)); then
  echo "setup: installing ${missing[*]}"
  sudo=""
  if [ "$(id -u)" -ne 0 ]; then sudo="sudo"; fi
  $sudo apt-get update -q
  DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -q --no-install-recommends "${missing[@]}"
fi

# npm ci again only when the lock file is newer than what npm last installed.
page="$root/replay/page"
if [[ ! "$page/node_modules/.package-lock.json" -nt "$page/package-lock.json" ]]; then
  echo "setup: installing the replay page's npm packages (npm ci in replay/page)"
  (cd "$page" && npm ci --no-audit --no-fund --loglevel=error)
fi
