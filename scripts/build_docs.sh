#!/usr/bin/env bash
# Builds the documentation site (the CMake target `docs` runs it; scripts/docs.sh is the
# command a user types):
#   1. the API reference, Doxygen over the headers, into EXTRA/api;
#   2. the presets' block diagrams, `cbbg graph`, into EXTRA/graphs;
#   3. the user guide, Sphinx over SOURCE (docs/), with EXTRA beside it, into OUT.
# Any warning of Doxygen or Sphinx fails the build (exit 1) and leaves OUT as it was; the
# site is written into a fresh OUT.partial.* and renamed into place only when whole; an OUT
# or EXTRA that this script did not make is refused (exit 2), never replaced.
set -euo pipefail
usage="usage: build_docs.sh --source DIR --doxyfile FILE --extra DIR --cbbg EXE --sphinx EXE --out DIR"
source_dir="" doxyfile="" extra="" cbbg="" sphinx="" out=""
while (($# > 0)); do
  [[ $# -ge 2 ]] || { echo "build_docs.sh: $1 needs a value ($usage)" >&2; exit 2; }
  case "$1" in
    --source) source_dir="$2" ;;
    --doxyfile) doxyfile="$2" ;;
    --extra) extra="$2" ;;
    --cbbg) cbbg="$2" ;;
    --sphinx) sphinx="$2" ;;
    --out) out="$2" ;;
    *) echo "build_docs.sh: unknown option '$1' ($usage)" >&2; exit 2 ;;
  esac
  shift 2
done
for given in "$source_dir" "$doxyfile" "$extra" "$cbbg" "$sphinx" "$out"; do
  [[ -n "$given" ]] || { echo "build_docs.sh: every option is needed ($usage)" >&2; exit 2; }
done
# Only what this script made is ever replaced: a site (Sphinx's .buildinfo) and the folder of
# the reference and diagrams (its marker file); or an empty folder (the build tool makes OUT's).
marker=".cbbg-docs-extra"
ours_or_empty() { [[ ! -e "$1" || -f "$1/$2" || ( -d "$1" && -z "$(ls -A "$1")" ) ]]; }
if ! ours_or_empty "$out" .buildinfo; then
  echo "build_docs.sh: $out exists and is not a site this build made; give another --out" >&2
  exit 2
fi
if ! ours_or_empty "$extra" "$marker"; then
  echo "build_docs.sh: $extra exists and is not this build's; give another --extra" >&2
  exit 2
fi

mkdir -p "$(dirname "$out")" "$(dirname "$extra")"
partial="$(mktemp -d "$out.partial.XXXXXX")"
extra_partial="$(mktemp -d "$extra.partial.XXXXXX")"
trap 'rm -rf "$partial" "$extra_partial"' EXIT
touch "$extra_partial/$marker"
mkdir "$extra_partial/graphs"

# Doxygen writes OUTPUT_DIRECTORY/api; the Doxyfile names EXTRA, so point it at the partial.
(cat "$doxyfile"; echo "OUTPUT_DIRECTORY = $extra_partial") | doxygen -
for preset in cbbg cbbg_weighted bg_only cb_only pd_only learnt_actor; do
  "$cbbg" graph --diagram "$preset" -o "$extra_partial/graphs/$preset.svg" > /dev/null
done
rm -rf "$extra"
mv "$extra_partial" "$extra"

CBBG_DOCS_EXTRA="$extra" "$sphinx" -W --keep-going -q -b html -c "$source_dir/site" \
  -d "$out.doctrees" "$source_dir" "$partial"
rm -rf "$out"
mv "$partial" "$out"
