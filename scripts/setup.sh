#!/usr/bin/env bash
# Installs the Debian packages cbbg builds, tests and plots with; only the missing ones.
set -euo pipefail

packages=(
  build-essential cmake ninja-build pkg-config git
  libsimbody-dev libeigen3-dev libspdlog-dev libboost-dev
  libcli11-dev libyaml-cpp-dev
  libgtest-dev libgmock-dev libbenchmark-dev
  clang clang-format libclang-rt-14-dev libfuzzer-14-dev time
  graphviz python3 python3-matplotlib python3-numpy
  parallel slurm-wlm munge
)

missing=()
for package in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$package" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$package")
  fi
done
if ((${#missing[@]} == 0)); then
  exit 0
fi

echo "setup: installing ${missing[*]}"
sudo=""
if [ "$(id -u)" -ne 0 ]; then sudo="sudo"; fi
$sudo apt-get update -q
DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -q --no-install-recommends "${missing[@]}"
