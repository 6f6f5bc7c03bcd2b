#!/bin/sh
# The oxide-thickness sweep (Fig. 9.21) with the nanoscale from the analytic
# junction model (nano/analytic, cases/oxide_thickness_sweep.toml) beside the
# sheared DEM junctions (nano/dem, cases/pin_on_disc_dem.toml: the Si
# interface amorphous, §9.3.3; and again with the Si interface on the HCP
# lattice), on one plot with the experimental fit μ ≈ 0.337 + 0.070 h_layer
# (9.1) and the measured end points (0.33 bare Si, 0.55 bulk SiO2, §9.2.1).
#   sh docs/figures/oxide_sweep_nano.sh [build/apps/wearscale] [out-folder]
# Runs both sweeps (or reuses their finished runs: --resume) and writes
# <out-folder>/oxide_sweep_nano.png (needs gnuplot).
set -eu
here=$(cd "$(dirname "$0")/../.." && pwd)
wearscale=${1:-$here/build/apps/wearscale}
out=${2:-$here/out/oxide-sweep-nano}
mkdir -p "$out"
sweep() {  # case, folder, --set options
  c=$1; d=$2; shift 2
  if [ -d "$out/$d" ]; then
    "$wearscale" run "$here/cases/$c.toml" --resume "$out/$d" "$@" >/dev/null
  else
    "$wearscale" run "$here/cases/$c.toml" --out "$out/$d" "$@" >/dev/null
  fi
}
sweep oxide_thickness_sweep oxide_thickness_sweep
sweep pin_on_disc_dem pin_on_disc_dem
sweep pin_on_disc_dem pin_on_disc_dem_hcp --set scale.nano.amorphous=none

command -v gnuplot >/dev/null || { echo "gnuplot not found: tables in $out/*/friction_vs_thickness.csv"; exit 0; }
gnuplot <<GP
set terminal pngcairo size 1000,700 font 'sans,11'
set output '$out/oxide_sweep_nano.png'
set datafile separator ','
set datafile commentschars '#'
h(x) = (x > 1) ? 6 : x*1e6   # bulk (inf) drawn at 6 µm, as in Fig. 9.25
set xlabel 'oxide layer thickness h_{layer} [µm] (bulk at 6)'
set ylabel 'friction coefficient μ'
set xrange [-0.3:6.5]
set yrange [0:*]
set grid
set key bottom right
set title 'Oxide sweep: nanoscale from the junction model (§7.1.2) and from DEM junctions (§7.1.1)'
plot '$out/oxide_thickness_sweep/friction_vs_thickness.csv' using (h(\$1)):(column('mu_mean')) \
       with linespoints pt 7 lw 2 title 'nano/analytic: time-averaged μ', \
     '$out/pin_on_disc_dem/friction_vs_thickness.csv' using (h(\$1)):(column('mu_mean')) \
       with linespoints pt 5 lw 2 title 'nano/dem, amorphous Si interface: time-averaged μ', \
     '$out/pin_on_disc_dem_hcp/friction_vs_thickness.csv' using (h(\$1)):(column('mu_mean')) \
       with linespoints pt 4 lw 2 title 'nano/dem, HCP Si interface: time-averaged μ', \
     [0:6] 0.337 + 0.070*x with lines dt 2 lw 2 title 'experiments: μ ≈ 0.337 + 0.070 h (9.1)', \
     '-' using 1:2 with points pt 9 ps 2 lc rgb 'black' title 'experiments: bare Si, bulk SiO_2 (§9.2.1)'
0,0.33
6,0.55
e
GP
echo "wrote $out/oxide_sweep_nano.png"
