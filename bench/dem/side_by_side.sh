#!/bin/bash
# wearscale's DEM beside LAMMPS (and LIGGGHTS when installed) on the anchor
# deck of this folder, one core, alternating, and the ratios of particle-steps
# per CPU-second. Run from the repository after building bench_dem:
#   bench/dem/side_by_side.sh [build/bench/bench_dem] [rounds]
# Skips an engine that is not installed, with a message. Prints the load
# average beside each figure (on shared cores the CPU-time figures are the
# ones to read), and wearscale's Hooke block on two threads (wall clock;
# waiting threads spin briefly, then sleep, as bench_dem and the CLI set it:
# docs/dem.md) against one: that speed-up means something only on a quiet
# machine (load < 1); on a loaded one read the busiest thread's CPU figure
# against one thread's (an upper bound: no waiting counted). Beside it, what
# the machine itself gives two cores: two one-thread runs at once against one
# alone (their summed wall-clock figures; shared caches, memory bandwidth and
# clocks make it less than 2), and LAMMPS on two MPI ranks against one (when
# mpirun is there). Each benchmark runs in its own process.
set -u
bench=${1:-build/bench/bench_dem}
rounds=${2:-2}
# Seconds each wearscale benchmark runs at least (Google Benchmark's default,
# 0.5 s, is a tenth of the LAMMPS deck's 32 000-sphere run: a host's dip of a
# second or two then moves wearscale's figure alone).
min_time=${WEARSCALE_BENCH_MIN_TIME:-3}
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
ours() {  # filter [threads]: one line per benchmark, each in its own process (the peak RSS is then its own):
  # CPU- and wall-second figures, bytes per particle, and on threads the busiest thread's CPU figure
  # (an upper bound of the wall-clock speed with a core per thread) and all threads' CPU over it
  local f
  for f in $(echo "$1" | tr '|' ' '); do
    OMP_NUM_THREADS=${2:-1} "$bench" --benchmark_filter="$f" --benchmark_min_time="$min_time" 2>/dev/null |
      awk -v load="$(load)" -v t="${2:-1}" '/Mpsteps_per_cpu_s/ { c = w = b = m = u = r = 0
        for (i = 1; i <= NF; ++i) { split($i, a, "=")
          if (a[1] == "Mpsteps_per_cpu_s") c = a[2]; if (a[1] == "Mpsteps_per_wall_s") w = a[2]
          if (a[1] == "peak_RSS_B_per_particle") b = a[2]; if (a[1] == "peak_RSS_above_start_B_per_particle") m = a[2]
          if (a[1] == "Mpsteps_per_busiest_thread_cpu_s") u = a[2]; if (a[1] == "cpu_over_busiest_thread") r = a[2] }
        extra = t > 1 ? sprintf(", %6.2f per busiest-thread CPU-second (CPU / busiest %.2f)", u, r) : ""
        printf "wearscale %-18s %dT %6.2f M particle-steps per CPU-second, %6.2f per wall-second%s, %4.0f B/particle (%4.0f above the start)  (load %s)\n",
          $1, t, c, w, extra, b, m, load }'
  done
}
two_alone() {  # filter: two one-thread runs at once, their summed wall-clock figures
  local f=$1
  OMP_NUM_THREADS=1 "$bench" --benchmark_filter="$f" --benchmark_min_time="$min_time" > "$work/a" 2>/dev/null &
  OMP_NUM_THREADS=1 "$bench" --benchmark_filter="$f" --benchmark_min_time="$min_time" > "$work/b" 2>/dev/null
  wait
  cat "$work/a" "$work/b" | awk -v f="$f" -v load="$(load)" '/Mpsteps_per_wall_s/ { for (i = 1; i <= NF; ++i) {
      split($i, a, "="); if (a[1] == "Mpsteps_per_wall_s") w += a[2] } }
    END { printf "two 1T runs at once %-9s %6.2f M particle-steps per wall-second, summed  (load %s)\n", f, w, load }'
}
lammps_ranks() {  # n steps: LAMMPS's wall seconds on 1 and 2 MPI ranks
  local n=$1 steps=$2 np t1 t2
  if ! command -v lmp > /dev/null || ! command -v mpirun > /dev/null; then echo "LAMMPS on 2 ranks: lmp or mpirun not installed, skipped"; return; fi
  for np in 1 2; do
    /usr/bin/time -f %e -o "$work/time$np" mpirun --allow-run-as-root --oversubscribe -np $np lmp \
      -in "$decks/in.dem_anchor.lammps" -var n "$n" -var nsteps "$steps" -var model hooke -log "$work/log" -screen none \
      > /dev/null 2>&1 || { echo "LAMMPS on $np ranks n=$n: failed"; return; }
  done
  t1=$(cat "$work/time1"); t2=$(cat "$work/time2")
  awk -v n="$n" -v a="$t1" -v b="$t2" -v load="$(load)" \
    'BEGIN { printf "LAMMPS 2 ranks / 1 rank n=%s (wall, MPI start included) %.2f  (%.1f s, %.1f s; load %s)\n", n, a / b, a, b, load }'
}
for r in $(seq "$rounds"); do
  echo "== round $r"
  for size in "20 1000 Hooke/20|Cohesive/20" "40 500 Hooke/40|Cohesive/40"; do
    set -- $size
    ours "$3"
    ours "Hooke/$1" 2
    two_alone "Hooke/$1/"
    lammps_ranks "$1" "$2"
    engine "LAMMPS gran/hooke/history n=$1" "$1" "$2" lmp -in "$decks/in.dem_anchor.lammps" -var n "$1" -var nsteps "$2" -var model hooke
    engine "LIGGGHTS hooke/history n=$1" "$1" "$2" liggghts -in "$decks/in.dem_anchor.liggghts" -var n "$1" -var nsteps "$2"
  done
done | tee "$work/all"
echo "== ratios (per round; wearscale one thread against the engine's CPU-time figure)"
# Each ratio is taken within its round (figures minutes apart on the same
# host); the median over the rounds comes last, the figure to quote from a
# host whose speed drifts.
awk 'function v() { match($0, /[0-9.]+ M particle/); return substr($0, RSTART, RLENGTH - 11) + 0 }
     function wall() { match($0, /[0-9.]+ per wall/); return substr($0, RSTART, RLENGTH - 9) + 0 }
     function busiest() { match($0, /[0-9.]+ per busiest/); return substr($0, RSTART, RLENGTH - 12) + 0 }
     function keep(name, x, fmt) { printf fmt, x; if (!(name in seen)) order[++names] = name; seen[name] = seen[name] " " sprintf("%.2f", x) }
     /^wearscale Hooke\/20.* 1T/ { w20 = v(); s20 = wall() } /^wearscale Hooke\/40.* 1T/ { w40 = v(); s40 = wall() }
     /^wearscale Cohesive\/20.* 1T/ { c20 = v() } /^wearscale Cohesive\/40.* 1T/ { c40 = v() }
     /^two 1T runs at once Hooke\/20/ { keep("32 000:  two 1T runs at once / one alone", v() / s20, "32 000:  two 1T runs at once / one     = %.2f  (the machine'"'"'s own two-core figure)\n") }
     /^two 1T runs at once Hooke\/40/ { keep("256 000: two 1T runs at once / one alone", v() / s40, "256 000: two 1T runs at once / one     = %.2f  (the machine'"'"'s own two-core figure)\n") }
     /^LAMMPS 2 ranks.*n=20/ { match($0, /\) [0-9.]+/); keep("32 000:  LAMMPS 2 ranks / 1 rank (wall)", substr($0, RSTART + 2, RLENGTH - 2) + 0, "32 000:  LAMMPS 2 ranks / 1 rank (wall) = %.2f\n") }
     /^LAMMPS 2 ranks.*n=40/ { match($0, /\) [0-9.]+/); keep("256 000: LAMMPS 2 ranks / 1 rank (wall)", substr($0, RSTART + 2, RLENGTH - 2) + 0, "256 000: LAMMPS 2 ranks / 1 rank (wall) = %.2f\n") }
     /^wearscale Hooke\/20.* 2T/ { keep("32 000:  2 threads / 1 thread (wall)", wall() / s20, "32 000:  2 threads / 1 thread (wall)   = %.2f")
                                   printf ", busiest thread CPU / 1 thread CPU = %.2f\n", busiest() / w20 }
     /^wearscale Hooke\/40.* 2T/ { keep("256 000: 2 threads / 1 thread (wall)", wall() / s40, "256 000: 2 threads / 1 thread (wall)   = %.2f")
                                   printf ", busiest thread CPU / 1 thread CPU = %.2f\n", busiest() / w40 }
     /^LAMMPS.*n=20.*M particle/ { keep("32 000:  wearscale Hooke / LAMMPS", w20 / v(), "32 000:  wearscale Hooke / LAMMPS    = %.2f")
                                   keep("32 000:  cohesive / LAMMPS Hooke", c20 / v(), ", cohesive / LAMMPS Hooke = %.2f\n") }
     /^LAMMPS.*n=40.*M particle/ { keep("256 000: wearscale Hooke / LAMMPS", w40 / v(), "256 000: wearscale Hooke / LAMMPS    = %.2f")
                                   keep("256 000: cohesive / LAMMPS Hooke", c40 / v(), ", cohesive / LAMMPS Hooke = %.2f\n") }
     /^LIGGGHTS.*n=20.*M particle/ { keep("32 000:  wearscale Hooke / LIGGGHTS", w20 / v(), "32 000:  wearscale Hooke / LIGGGHTS  = %.2f\n") }
     /^LIGGGHTS.*n=40.*M particle/ { keep("256 000: wearscale Hooke / LIGGGHTS", w40 / v(), "256 000: wearscale Hooke / LIGGGHTS  = %.2f\n") }
     END { print "== median over the rounds"
           for (o = 1; o <= names; ++o) { name = order[o]; m = split(substr(seen[name], 2), x, " ")
             for (i = 2; i <= m; ++i) for (j = i; j > 1 && x[j - 1] > x[j]; --j) { t = x[j]; x[j] = x[j - 1]; x[j - 1] = t }
             printf "%-40s %.2f  (rounds:%s)\n", name, m % 2 ? x[(m + 1) / 2] : (x[m / 2] + x[m / 2 + 1]) / 2, seen[name] } }' "$work/all"
