#!/bin/bash
# The examples of an installed wearscale run from the installed tree alone: every
# command's --help examples that name an example case (cases/<case>.toml: the CLI
# reads the one installed under share/wearscale when the working folder has none),
# each command's in order in a folder of its own, and the man page's EXAMPLES.
# Run by install_test.cmake (ctest install.cxx) with the installed program first on PATH.
#   run_examples.sh PREFIX WORK
set -u
prefix=$1
work=$2
export PATH="$prefix/bin:$PATH" CI=true WEARSCALE_CACHE="$work/cache"
unset WEARSCALE_DATA WEARSCALE_DATA_DIR
rm -rf "$work"
mkdir -p "$work"
failed=0
ran=0

# Runs the example lines on stdin one after the other in folder $1 (an example may read what one before wrote).
run_in() {
  local dir=$1 line
  mkdir -p "$dir"
  while IFS= read -r line; do
    [ -z "$line" ] && continue
    if [[ $line == *strength-table* ]] && ! command -v lmp > /dev/null; then
      echo "skipped (LAMMPS' lmp is not on PATH): $line"
      continue
    fi
    echo "+ (in $dir) $line"
    ran=$((ran + 1))
    if ! (cd "$dir" && bash -c "$line") > "$dir/example.log" 2>&1; then
      echo "FAILED from the installed tree: $line"
      cat "$dir/example.log"
      failed=1
    fi
  done
}

# wearscale --help-all: headings "wearscale <command>:", then "Examples:" and lines indented by two spaces.
help=$(wearscale --help-all) || { echo "wearscale --help-all failed"; exit 1; }
commands=$(awk '/^wearscale .*:$/ { cmd = substr($0, 11, length($0) - 11) } /^wearscale:/ { cmd = "" }
                /^Examples:$/ { ex = 1; next } ex && /^  / { if ($0 ~ /cases\//) print cmd; next } { ex = 0 }' <<< "$help" | sort -u)
if [ -z "$commands" ]; then
  echo "no example of --help-all names an example case (cases/...): is this the help?"
  exit 1
fi
while IFS= read -r cmd; do
  folder="$work/help-${cmd// /-}"
  [ -z "$cmd" ] && folder="$work/help-wearscale"
  awk -v want="$cmd" '/^wearscale .*:$/ { cmd = substr($0, 11, length($0) - 11) } /^wearscale:/ { cmd = "" }
                      /^Examples:$/ { ex = 1; next } ex && /^  / { if (cmd == want) print substr($0, 3); next } { ex = 0 }' \
    <<< "$help" | run_in "$folder"
done <<< "$commands"

# The man page's EXAMPLES (when help2man made one), its groff escapes undone.
page="$prefix/share/man/man1/wearscale.1"
if [ -f "$page" ]; then
  sed -n '/^\.SH EXAMPLES/,/^\.SH /p' "$page" | grep -v '^\.' | sed -e 's/\\-/-/g' -e 's/\\(aq/'"'"'/g' -e 's/\\e/\\/g' |
    run_in "$work/man"
  grep -q '^\.SH EXAMPLES' "$page" || { echo "the man page has no EXAMPLES section"; failed=1; }
else
  echo "no man page installed (help2man absent): its examples are not run"
fi
echo "$ran examples run from $prefix"
exit $failed
