#!/usr/bin/env bash
# The compile CPU of one build target, cold (no ccache), per translation unit.
#   bash bench/compile_cpu.sh <new build folder> <target> [cmake options...]
# e.g. the program as `quickstart main` builds it on a fresh machine (no MPI,
# no LAMMPS engine, no tests):
#   bash bench/compile_cpu.sh /tmp/cold wearscale -DWEARSCALE_BUILD_TESTS=OFF -DWEARSCALE_BUILD_BENCH=OFF \
#        -DWEARSCALE_BUILD_LONG_TESTS=OFF -DWEARSCALE_MPI=OFF -DWEARSCALE_DEM_LAMMPS=OFF -DWEARSCALE_PYTHON=OFF
# Every compiler run goes through a launcher that appends "user sys wall object"
# to <build folder>/compile-cpu.log (GNU time); the summary adds them up per
# target and lists the heaviest objects. User + system seconds, not wall: the
# figure holds on a loaded machine. Links are not counted.
set -euo pipefail
[ $# -ge 2 ] || { echo "usage: bash bench/compile_cpu.sh <new build folder> <target> [cmake options...]" >&2; exit 2; }
tree="$1"; target="$2"; shift 2
[ ! -e "$tree" ] || { echo "compile_cpu: $tree exists; give a new folder (a cold build)" >&2; exit 2; }
command -v /usr/bin/time >/dev/null || { echo "compile_cpu: needs GNU time (apt-get install time)" >&2; exit 2; }
cd "$(dirname "${BASH_SOURCE[0]}")/.."
mkdir -p "$tree"
tree="$(cd "$tree" && pwd)"
log="$tree/compile-cpu.log"
cat > "$tree/timed-compile" <<LAUNCHER
#!/usr/bin/env bash
out=""; prev=""
for a in "\$@"; do [ "\$prev" = "-o" ] && out="\$a"; prev="\$a"; done
exec /usr/bin/time -a -o "$log" -f "%U %S %e \$out" "\$@"
LAUNCHER
chmod +x "$tree/timed-compile"
cmake -S . -B "$tree" -DCMAKE_BUILD_TYPE=Release -DCMAKE_CXX_COMPILER_LAUNCHER="$tree/timed-compile" \
      -DCMAKE_C_COMPILER_LAUNCHER="$tree/timed-compile" "$@" >/dev/null
start=$SECONDS
cmake --build "$tree" -j "$(nproc 2>/dev/null || echo 2)" --target "$target" >/dev/null
echo "compile_cpu: $target built in $((SECONDS - start)) s wall, load average now $(cut -d' ' -f1-3 /proc/loadavg)"
# Failed compiles (GNU time's "Command exited..." lines) are not in the sums.
grep -E '^[0-9.]+ [0-9.]+ [0-9.]+ ' "$log" | awk '
  { n = split($4, p, "/"); t = p[1]; for (i = 1; i <= n; i++) if (p[i] ~ /\.dir$/) t = p[i];
    cpu = $1 + $2; sum[t] += cpu; cnt[t]++; total += cpu; runs++ }
  END { for (t in sum) printf "%8.1f s  %3d runs  %s\n", sum[t], cnt[t], t;
        printf "%8.1f s  %3d runs  total (user + system CPU of the compiler runs)\n", total, runs }' | sort -n
echo "heaviest:"
grep -E '^[0-9.]+ [0-9.]+ [0-9.]+ ' "$log" | awk '{ printf "%8.1f s  %s\n", $1 + $2, $4 }' | sort -rn | head -15
