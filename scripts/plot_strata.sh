#!/usr/bin/env bash
# Draws the 24 strata from `strata samples`: the hemisphere seen from above, one colour per stratum,
# each labelled with its id at the mean of its samples. Usage: bash scripts/plot_strata.sh [OUT.png]
set -euo pipefail
cd "$(dirname "$0")/.."
out=${1:-assets/readme/strata24.png}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
build/app/strata samples --sampler strata24 --passes 150 --seed 1 > "$work/samples.csv"
awk -F, 'NR > 1 { x[$4] += $5; y[$4] += $6; n[$4]++ }
         END { for (s in n) printf "%.4f,%.4f,%d\n", x[s] / n[s], y[s] / n[s], s }' \
  "$work/samples.csv" > "$work/labels.txt"
mkdir -p "$(dirname "$out")"
gnuplot <<GNUPLOT
set terminal pngcairo size 720,760 font "DejaVu Sans,11"
set output "$out"
set datafile separator ","
array C[24] = [0xe6194b, 0x3cb44b, 0x4363d8, 0xf58231, 0x911eb4, 0x42d4f4, \
               0xf032e6, 0x9a6324, 0x469990, 0x800000, 0x000075, 0x808000, \
               0xbfef45, 0xffd8b1, 0xdcbeff, 0xfabed4, 0xaaffc3, 0xa9a9a9, \
               0x1b9e77, 0xd95f02, 0x7570b3, 0xe7298a, 0x66a61e, 0xe6ab02]
set size ratio -1
set xrange [-1.05:1.05]
set yrange [-1.05:1.05]
set title "The 24 strata seen from above the normal (strata samples, 150 passes)\nid = 6 quadrant + order; quadrants counter-clockwise from +x+y"
set xlabel "x (tangent)"
set ylabel "y (bitangent)"
plot "$work/samples.csv" every ::1 using 5:6:(C[int(\$4) + 1]) with points pt 7 ps 0.45 lc rgb variable notitle, \
     "$work/labels.txt" using 1:2:3 with labels font "DejaVu Sans Bold,12" notitle
GNUPLOT
echo "wrote $out"
