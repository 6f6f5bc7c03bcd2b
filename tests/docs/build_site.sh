#!/bin/sh
# Builds the manual's site: Doxygen's XML of the public headers, then
# sphinx-build -W (warnings, broken internal links included, are errors).
# Usage: build_site.sh DOXYGEN SPHINX_BUILD DOXYFILE XML_DIR DOCS_SRC OUT VERSION \
#          python_dir=DIR missing=TEXT
# python_dir: the build tree's python/, for the Python API page (empty: none);
# missing: the tools not found (non-empty: exit 77, ctest's "skipped", saying so).
doxygen=$1 sphinx=$2 doxyfile=$3 xml=$4 src=$5 out=$6 version=$7
python_dir= missing=
for arg in "$8" "$9"; do
  case $arg in
    python_dir=*) python_dir=${arg#python_dir=} ;;
    missing=*) missing=${arg#missing=} ;;
  esac
done
if [ -n "$missing" ]; then
  echo "docs: skipped, missing: $missing"
  exit 77
fi
set -e
mkdir -p "$out/doxygen"
"$doxygen" "$doxyfile"
WEARSCALE_DOXYGEN_XML=$xml WEARSCALE_VERSION=$version WEARSCALE_PYTHON_DIR=$python_dir \
  "$sphinx" -W --keep-going -q -b html -d "$out/doctrees" "$src" "$out/html"
echo "docs: $out/html/index.html"
