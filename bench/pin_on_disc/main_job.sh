#!/usr/bin/env bash
# The main job (cases/oxide_thickness_sweep.toml, 2 workers) timed side by side
# with a baseline program, interleaved (hyperfine alternates the commands run
# by run when given --runs and the commands in one call), with the machine's
# load before and after. Then, for each program, one run with --json: the
# contact solves and BEM iterations of each run of the sweep.
#
#   bash bench/pin_on_disc/main_job.sh BASELINE_WEARSCALE [NEW_WEARSCALE] [RUNS]
#
# BASELINE_WEARSCALE: a wearscale program built from the commit to compare
# with (e.g. `git worktree add /tmp/base <commit>` and build it there). Extra
# --set options for both: the environment variable SET, e.g.
# SET="--set scale.macro.integrator=adaptive" to give the baseline's adaptive run.
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/../.."
base="${1:?usage: main_job.sh BASELINE_WEARSCALE [NEW_WEARSCALE] [RUNS]}"
new="${2:-build/apps/wearscale}"
runs="${3:-5}"
out="$(mktemp -d)"
trap 'rm -rf "$out"' EXIT
echo "load before: $(uptime)"
hyperfine --runs "$runs" --warmup 1 --export-markdown "$out/times.md" \
  -n baseline "$base -q -j 2 run cases/oxide_thickness_sweep.toml ${SET:-} --out $out/base" \
  -n new "$new -q -j 2 run cases/oxide_thickness_sweep.toml ${SET:-} --out $out/new"
echo "load after: $(uptime)"
cat "$out/times.md"
for which in base new; do
  program="$base"; [ "$which" = new ] && program="$new"
  "$program" -q -j 2 run cases/oxide_thickness_sweep.toml ${SET:-} --out "$out/json_$which" --json > "$out/$which.json"
  python3 - "$out/$which.json" "$which" <<'PY'
import json, sys
d = json.load(open(sys.argv[1]))
print(f"{sys.argv[2]}: h_layer, contact solves, BEM iterations, iterations per solve")
total_s = total_i = 0
for r in d["sweep"]["runs"]:
    res = r["results"]
    s = res["contact_solves"]["value"]
    i = res.get("contact_iterations", {}).get("value")
    total_s += s
    total_i += i or 0
    print(f"  {r['value']:>8} {s:8.0f} {i if i is not None else '-':>10} {(i / s) if i else '-':>8}")
print(f"  total {total_s:.0f} solves" + (f", {total_i:.0f} iterations, {total_i / total_s:.1f} a solve" if total_i else ""))
PY
done
