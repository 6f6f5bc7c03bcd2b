#!/bin/sh
# Builds the manual's site: Doxygen's XML of the public headers, then
# sphinx-build -W (warnings, broken internal links included, are errors).
# Usage: build_site.sh DOXYGEN SPHINX_BUILD DOXYFILE XML_DIR DOCS_SRC OUT VERSION MISSING
# Exits 77 (ctest: skipped) with a message when a tool is missing.
doxygen=$1 sphinx=$2 doxyfile=$3 xml=$4 src=$5 out=$6 version=$7 missing=$8
if [ -n "$missing" ]; then
  echo "docs: skipped, missing: $missing"
  exit 77
fi
set -e
mkdir -p "$out/doxygen"
"$doxygen" "$doxyfile"
WEARSCALE_DOXYGEN_XML=$xml WEARSCALE_VERSION=$version \
  "$sphinx" -W --keep-going -q -b html -d "$out/doctrees" "$src" "$out/html"
echo "docs: $out/html/index.html"
