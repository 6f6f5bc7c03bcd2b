#!/usr/bin/env bash
# Builds lmp_cohesive (LAMMPS with the thesis' gran/cohesive/history) and,
# with --keep-history, lmp_cohesive_kept (the same style with the pair's
# beyond_contact flag set, so that LAMMPS keeps the tangential history of
# pairs in the cohesive zone across neighbour-list rebuilds).
#   bash build.sh DIR_WITH_PAIR_STYLE [--keep-history]
# DIR holds pair_gran_cohesive_history.{h,cpp} from the thesis' LAMMPS fork
# (public: sphamba/lammps, src/GRANULAR/). Needs liblammps-dev, mpicxx and
# the LAMMPS source of Debian's version for the GRANULAR headers
# (apt-get source lammps, with deb-src in the apt sources).
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
src="${1:?usage: bash build.sh DIR_WITH_PAIR_STYLE [--keep-history]}"
keep="${2:-}"
work="${WORK:-$here/build}"
mkdir -p "$work"
if [ ! -d "$work/lammps-src" ]; then
  (cd "$work" && apt-get source --download-only lammps >/dev/null)
  mkdir -p "$work/lammps-src"
  tar -xJf "$work"/lammps_*.orig.tar.xz -C "$work/lammps-src" --strip-components=1 --wildcards '*/src/*.h'
fi
build_one() {  # $1 output name, $2 extra sed on the header
  local d="$work/$1.src"
  rm -rf "$d" && mkdir -p "$d"
  cp "$src/pair_gran_cohesive_history.h" "$src/pair_gran_cohesive_history.cpp" "$d/"
  # LAMMPS 29Sep2021 (Debian 12) spells the pair's forward communication forward_comm_pair.
  sed -i 's/comm->forward_comm(this)/comm->forward_comm_pair(this)/' "$d/pair_gran_cohesive_history.cpp"
  [ -n "$2" ] && sed -i "$2" "$d/pair_gran_cohesive_history.cpp"
  mpicxx -O2 -std=c++17 -DLAMMPS_SMALLBIG -I"$d" -I/usr/include/lammps -I"$work/lammps-src/src/GRANULAR" \
    -I"$work/lammps-src/src" "$here/lmp_cohesive.cpp" "$d/pair_gran_cohesive_history.cpp" -llammps -o "$work/$1"
  echo "built $work/$1"
}
build_one lmp_cohesive ""
if [ "$keep" = "--keep-history" ]; then
  build_one lmp_cohesive_kept \
    '/PairGranHookeHistory(lmp) *{/ s/{/{ beyond_contact = 1;/'
fi
