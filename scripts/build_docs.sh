#!/usr/bin/env bash
# Builds the documentation site (the CMake target `docs` runs it; scripts/docs.sh is the
# command a user types):
#   1. the API reference, Doxygen over the headers, into EXTRA/api;
#   2. the presets' block diagrams, `cbbg graph`, into EXTRA/graphs;
#   3. the user guide, Sphinx over SOURCE (docs/), with EXTRA beside it, into OUT.
# Any warning of Doxygen or Sphinx fails the build (exit 1) and leaves OUT as it was; the
# site is written into OUT.partial and renamed into place only when whole.
set -euo pipefail
usage="usage: build_docs.sh --source DIR --doxyfile FILE --extra DIR --cbbg EXE --sphinx EXE --out DIR"
while (($# > 0)); do
  case "$1" in
    --source) source_dir="$2" ;;
    --doxyfile) doxyfile="$2" ;;
    --extra) extra="$2" ;;
    --cbbg) cbbg="$2" ;;
    --sphinx) sphinx="$2" ;;
    --out) out="$2" ;;
    *) echo "build_docs.sh: unknown option '$1' ($usage)" >&2; exit 2 ;;
  esac
  shift 2 || { echo "build_docs.sh: $1 needs a value ($usage)" >&2; exit 2; }
done
for name in source_dir doxyfile extra cbbg sphinx out; do
  [[ -n "${!name:-}" ]] || { echo "build_docs.sh: missing option ($usage)" >&2; exit 2; }
done

partial="$out.partial"
trap 'rm -rf "$partial" "$extra.partial"' EXIT
rm -rf "$extra.partial" "$partial"
mkdir -p "$extra.partial/graphs"

# Doxygen writes OUTPUT_DIRECTORY/api; the Doxyfile names EXTRA, so point it at the partial.
(cat "$doxyfile"; echo "OUTPUT_DIRECTORY = $extra.partial") | doxygen -
for preset in cbbg cbbg_weighted bg_only cb_only pd_only learnt_actor; do
  "$cbbg" graph --diagram "$preset" -o "$extra.partial/graphs/$preset.svg" > /dev/null
done
rm -rf "$extra"
mv "$extra.partial" "$extra"

CBBG_DOCS_EXTRA="$extra" "$sphinx" -W --keep-going -q -b html -c "$source_dir/site" \
  -d "$out.doctrees" "$source_dir" "$partial"
rm -rf "$out"
mv "$partial" "$out"
