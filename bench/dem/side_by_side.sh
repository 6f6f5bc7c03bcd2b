#!/bin/bash
# wearscale's DEM beside LAMMPS (and LIGGGHTS when installed) on the anchor
# deck of this folder, one core, alternating, and the ratios of particle-steps
# per CPU-second. Run from the repository after building bench_dem:
#   bench/dem/side_by_side.sh [build/bench/bench_dem] [rounds]
# Skips an engine that is not installed, with a message. Prints the load
# average beside each figure (on shared cores the CPU-time figures are the
# ones to read).
set -u
bench=${1:-build/bench/bench_dem}
rounds=${2:-2}
decks=$(cd "$(dirname "$0")" && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
[ -x "$bench" ] || { echo "no $bench: build the bench_dem target first" >&2; exit 2; }
load() { cut -d' ' -f1-3 /proc/loadavg; }
# M particle-steps per CPU-second of one engine run: N steps / user seconds.
engine() {  # name n steps cmd...
  local name=$1 n=$2 steps=$3; shift 3
  if ! command -v "$1" > /dev/null; then echo "$name: '$1' not installed, skipped"; return; fi
  /usr/bin/time -f %U -o "$work/time" "$@" -log "$work/log" -screen none > /dev/null 2>&1 || {
    echo "$name: failed"; return; }
  awk -v n=$((4 * n * n * n)) -v s="$steps" -v name="$name" -v load="$(load)" \
    '{ printf "%-28s %6.2f M particle-steps per CPU-second  (load %s)\n", name, n * s / $1 / 1e6, load }' "$work/time"
}
ours() {  # filter
  OMP_NUM_THREADS=1 "$bench" --benchmark_filter="$1" 2>/dev/null |
    awk -v load="$(load)" '/Mpsteps_per_cpu_s/ { for (i = 1; i <= NF; ++i) if ($i ~ /^Mpsteps_per_cpu_s=/) {
      split($i, a, "="); printf "wearscale %-18s %6.2f M particle-steps per CPU-second  (load %s)\n", $1, a[2], load } }'
}
for r in $(seq "$rounds"); do
  echo "== round $r"
  for size in "20 1000 Hooke/20|Cohesive/20" "40 500 Hooke/40|Cohesive/40"; do
    set -- $size
    ours "$3"
    engine "LAMMPS gran/hooke/history n=$1" "$1" "$2" lmp -in "$decks/in.dem_anchor.lammps" -var n "$1" -var nsteps "$2" -var model hooke
    engine "LIGGGHTS hooke/history n=$1" "$1" "$2" liggghts -in "$decks/in.dem_anchor.liggghts" -var n "$1" -var nsteps "$2"
  done
done | tee "$work/all"
echo "== ratios (wearscale Hooke / engine, per round)"
awk 'function v() { match($0, /[0-9.]+ M particle/); return substr($0, RSTART, RLENGTH - 11) + 0 }
     /^wearscale Hooke\/20/ { w20 = v() } /^wearscale Hooke\/40/ { w40 = v() }
     /^LAMMPS.*n=20.*M particle/ { printf "32 000:  wearscale / LAMMPS   = %.2f\n", w20 / v() }
     /^LAMMPS.*n=40.*M particle/ { printf "256 000: wearscale / LAMMPS   = %.2f\n", w40 / v() }
     /^LIGGGHTS.*n=20.*M particle/ { printf "32 000:  wearscale / LIGGGHTS = %.2f\n", w20 / v() }
     /^LIGGGHTS.*n=40.*M particle/ { printf "256 000: wearscale / LIGGGHTS = %.2f\n", w40 / v() }' "$work/all"
