#!/bin/bash
# wearscale's anchor block on one and two threads, this build beside a
# baseline build of bench_dem, alternating in one run; with the particles
# renumbered along the cells at every tenth build (HookeSorted) and without
# (Hooke, the switch off). Run from the repository:
#   bench/dem/threads.sh BASE_BENCH [NEW_BENCH] [ROUNDS]
# (BASE_BENCH: a bench_dem built from the code to compare with; NEW_BENCH
# defaults to build/bench/bench_dem.) Per line: M particle-steps per
# wall-second, per CPU-second, per CPU-second of the busiest thread (an
# upper bound of the wall-clock figure with a core per thread, which a
# loaded machine can still measure), and the load average. Then, per round,
# two threads against one (wall clock, and the busiest thread's bound) for
# each binary and numbering, and their medians. The wall-clock ratio means
# something only with both cores free (load below 2).
set -u
base=${1:?usage: bench/dem/threads.sh BASE_BENCH [NEW_BENCH] [ROUNDS]}
new=${2:-build/bench/bench_dem}
rounds=${3:-3}
min_time=${WEARSCALE_BENCH_MIN_TIME:-3}
for b in "$base" "$new"; do [ -x "$b" ] || { echo "no $b: build the bench_dem target first" >&2; exit 2; }; done
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
load() { cut -d' ' -f1-3 /proc/loadavg; }
one() {  # label binary filter threads
  OMP_NUM_THREADS=$4 "$2" --benchmark_filter="$3" --benchmark_min_time="$min_time" 2>/dev/null |
    awk -v label="$1" -v t="$4" -v load="$(load)" '/Mpsteps_per_cpu_s/ { for (i = 1; i <= NF; ++i) { split($i, a, "=")
        if (a[1] == "Mpsteps_per_cpu_s") c = a[2]; if (a[1] == "Mpsteps_per_wall_s") w = a[2]
        if (a[1] == "Mpsteps_per_busiest_thread_cpu_s") b = a[2] }
      printf "%-22s %dT wall %6.2f  cpu %6.2f  busiest %6.2f  (load %s)\n", label, t, w, c, b, load }'
}
for r in $(seq "$rounds"); do
  echo "== round $r"
  for n in 20 40; do
    for t in 1 2; do
      one "base Hooke/$n" "$base" "^Hooke/$n/" $t
      one "new Hooke/$n" "$new" "^Hooke/$n/" $t
      one "new HookeSorted/$n" "$new" "^HookeSorted/$n/[0-9]+/10/" $t
    done
  done
done | tee "$work/all"
echo "== 2 threads / 1 thread, per round: wall clock (busiest thread's CPU bound)"
awk '{ key = $1 " " $2; t = $3; match($0, /wall +[0-9.]+/); w = substr($0, RSTART + 5, RLENGTH - 5) + 0
       match($0, /busiest +[0-9.]+/); b = substr($0, RSTART + 8, RLENGTH - 8) + 0
       if (t == "1T") { w1[key] = w; b1[key] = b }
       if (t == "2T") { if (!(key in seen)) order[++k] = key; seen[key] = seen[key] sprintf(" %.2f (%.2f)", w / w1[key], b / b1[key])
                        r[key, ++m[key]] = w / w1[key] } }
     END { for (i = 1; i <= k; ++i) { key = order[i]; c = m[key]
             for (a = 2; a <= c; ++a) for (j = a; j > 1 && r[key, j - 1] > r[key, j]; --j) { x = r[key, j]; r[key, j] = r[key, j - 1]; r[key, j - 1] = x }
             printf "%-22s median %.2f  rounds:%s\n", key, c % 2 ? r[key, (c + 1) / 2] : (r[key, c / 2] + r[key, c / 2 + 1]) / 2, seen[key] } }' "$work/all"
