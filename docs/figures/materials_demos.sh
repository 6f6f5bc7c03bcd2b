#!/bin/sh
# The strengths of the two demonstration pairs (docs/materials.md,
# "Demonstrations"), as Fig. 9.18 draws Si's and SiO2's: σ_max(p) and σ_dyn(p)
# of the shipped tables computed by wearscale's MD shear test (copper, EAM of
# Mishin et al. 2001; diamond, Tersoff 1989; silicon, Stillinger-Weber), with
# the line σ = p whose crossing with σ_max is p_crit (7.5).
#   sh docs/figures/materials_demos.sh [data-folder] [out-folder]
# Writes <out-folder>/materials_demos.png and keeps materials_demos.gp beside
# it (gnuplot materials_demos.gp redraws it). Needs gnuplot.
set -eu
here=$(cd "$(dirname "$0")/../.." && pwd)
data=${1:-$here/materials/data}
out=${2:-$here/docs/figures}
mkdir -p "$out"
command -v gnuplot >/dev/null || { echo "gnuplot not found: the tables are $data/lammps_smoke_{Cu,diamond,Si}.csv"; exit 0; }
cat > "$out/materials_demos.gp" <<GP
set terminal pngcairo size 1200,450 font 'sans,11'
set output '$out/materials_demos.png'
set datafile separator ','
set multiplot layout 1,3
set grid
set key top left
set xlabel 'normal pressure p [GPa]'
set ylabel 'shear strength [GPa]'
g = 1e-9
do for [m in "Cu Si diamond"] {
  f = sprintf('$data/lammps_smoke_%s.csv', m)
  set title sprintf('%s (wearscale MD shear test)', m)
  plot f using (\$1*g):(\$2*g) every ::1 with linespoints lw 2 pt 7 title 'σ_{max}', \
       f using (\$1*g):(\$3*g) every ::1 with linespoints lw 2 pt 5 title 'σ_{dyn}', \
       x with lines dt 2 lc rgb 'black' title 'σ = p'
}
unset multiplot
GP
gnuplot "$out/materials_demos.gp"
echo "wrote $out/materials_demos.png"
