#!/usr/bin/env bash
# Sets up and builds the documentation site: the user guide (docs/) and the API reference
# generated from the headers, one HTML site in build/docs/html (open build/docs/html/index.html).
# `cmake --install build` installs it under share/doc/cbbg/html. Any warning fails the build.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
"$root/scripts/setup.sh" --docs
cmake -S "$root" -B "$root/build" -G Ninja -DCMAKE_BUILD_TYPE=Release > /dev/null
cmake --build "$root/build" --parallel "$(nproc)" --target docs
echo "docs: $root/build/docs/html/index.html"
