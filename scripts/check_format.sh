#!/usr/bin/env bash
# Fails, listing the files, where clang-format (the repo's .clang-format) would change C++ code.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cd "$root"
mapfile -t files < <(find framework codegen plant realtime blocks config parameters diagrams records experiments environment store replay apps python \
  tests bench examples \
  \( -name '*.h' -o -name '*.cc' \) -type f 2>/dev/null | sort)
unformatted=()
for file in "${files[@]}"; do
  if ! clang-format --dry-run --Werror "$file" >/dev/null 2>&1; then unformatted+=("$file"); fi
done
if ((${#unformatted[@]})); then
  echo "clang-format would change these files (run: clang-format -i FILE):"
  printf '  %s\n' "${unformatted[@]}"
  exit 1
fi
echo "format: ${#files[@]} files checked, all formatted"
