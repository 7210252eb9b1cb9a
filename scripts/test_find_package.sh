#!/usr/bin/env bash
# Installs the built framework into a scratch prefix, builds examples/ against it as a user's
# own project would (find_package(cbbg)), and runs the example.
#   test_find_package.sh BUILD_DIR
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="$1"
scratch="$(mktemp -d)"
trap 'rm -rf "$scratch"' EXIT
cmake --install "$build" --prefix "$scratch/prefix" >/dev/null
cmake -S "$root/examples" -B "$scratch/example" -G Ninja -DCMAKE_BUILD_TYPE=Release \
  -DCMAKE_PREFIX_PATH="$scratch/prefix" >/dev/null
cmake --build "$scratch/example" >/dev/null
"$scratch/example/spring_mass" "$scratch/out"
test -s "$scratch/out/position.csv"
grep -q "digraph" "$scratch/out/spring_mass.dot"
