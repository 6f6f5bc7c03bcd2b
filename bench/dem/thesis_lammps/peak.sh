#!/usr/bin/env bash
# Prints the peak p_T [GPa] over the slide of a log written by in.junction_cell,
# and the slide [nm] at which it occurred.   bash peak.sh log.lammps
set -euo pipefail
awk '/^ *Step/{f=1;next} /^Loop/{f=0} f && NF==5 {print}' "$1" |
  awk -v dtline="$(grep -m1 '^A0 =' "$1")" '
    BEGIN { split(dtline, w, " "); for (k in w) { if (w[k] == "dt") dt = w[k+2]; if (w[k] == "settle") settle = w[k+2] } }
    $1 > settle && $3 > peak { peak = $3; at = ($1 - settle) * dt * 10 }
    END { printf "peak p_T %.2f GPa at a slide of %.1f nm\n", peak / 1e9, at * 1e9 }'
