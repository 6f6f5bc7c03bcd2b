#!/usr/bin/env bash
# The main job's wall and CPU time, one program or several side by side.
#   bash bench/main_job_time.sh [-n RUNS] PROGRAM [PROGRAM...] [-- extra run arguments]
# e.g. the MPI program against a serial one of the same commit, five rounds:
#   bash bench/main_job_time.sh -n 5 build/apps/wearscale /tmp/serial/apps/wearscale
# Each round runs every program once, in turn (interleaved, so that a change
# of the machine's load falls on all of them alike):
#   wearscale -q run cases/oxide_thickness_sweep.toml --out <scratch> [extra]
# and prints wall, user and system seconds (GNU time) with the load average
# before the run; then the median of each per program. Wall time follows the
# load of a shared machine: quote it with the load, and compare CPU seconds.
set -euo pipefail
runs=3
if [ "${1:-}" = "-n" ]; then runs="$2"; shift 2; fi
programs=()
while [ $# -gt 0 ] && [ "$1" != "--" ]; do programs+=("$1"); shift; done
[ "${1:-}" = "--" ] && shift
[ ${#programs[@]} -ge 1 ] || { echo "usage: bash bench/main_job_time.sh [-n RUNS] PROGRAM [PROGRAM...] [-- run arguments]" >&2; exit 2; }
command -v /usr/bin/time >/dev/null || { echo "main_job_time: needs GNU time (apt-get install time)" >&2; exit 2; }
cd "$(dirname "${BASH_SOURCE[0]}")/.."
scratch="$(mktemp -d)"
trap 'rm -rf "$scratch"' EXIT
for p in "${programs[@]}"; do [ -x "$p" ] || { echo "main_job_time: $p is not a program" >&2; exit 2; }; done
printf "%-5s %-45s %8s %8s %8s  %s\n" round program wall user sys "load before"
for ((r = 1; r <= runs; r++)); do
  for p in "${programs[@]}"; do
    rm -rf "$scratch/out"
    load="$(cut -d' ' -f1 /proc/loadavg)"
    /usr/bin/time -o "$scratch/time" -f "%e %U %S" "$p" -q run cases/oxide_thickness_sweep.toml --out "$scratch/out" "$@" >/dev/null
    read -r wall user sys < "$scratch/time"
    printf "%-5s %-45s %8s %8s %8s  %s\n" "$r" "$p" "$wall" "$user" "$sys" "$load"
    echo "$p $wall $user $sys" >> "$scratch/all"
  done
done
echo "median over $runs rounds:"
for p in "${programs[@]}"; do
  awk -v p="$p" '$1 == p { w[++n] = $2; u[n] = $3; s[n] = $4 }
    function median(a, n,   i, j, t) { for (i = 1; i <= n; i++) for (j = i + 1; j <= n; j++) if (a[j] < a[i]) { t = a[i]; a[i] = a[j]; a[j] = t }
                                       return n % 2 ? a[(n + 1) / 2] : (a[n / 2] + a[n / 2 + 1]) / 2 }
    END { printf "%-45s wall %.2f s  user %.2f s  sys %.2f s\n", p, median(w, n), median(u, n), median(s, n) }' "$scratch/all"
done
