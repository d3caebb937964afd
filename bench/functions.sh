#!/usr/bin/env bash
# Usage: bench/functions.sh [LUMEN] [REPEATS]
# The function VM against POV-Ray's, in the same run, the two renderers alternating and the
# median of REPEATS (default 3) kept:
# 1. evaluations per second: a height_field { function 2000, 2000 { F } } evaluates F four
#    million times while the scene is parsed; each renderer's reported parse time (POV-Ray's
#    "Parse Time", lumen's "parsed in") less that of the same field of the trivial function
#    `x` (which costs the field's building and one call a sample) gives the rate of F's own
#    work, for an arithmetic body, f_noise3d, and a user function calling internal ones;
# 2. examples/isosurface.pov at 640x480 +A0.3 +WT2: wall seconds and the ratio lumen/POV-Ray.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
lumen=$(realpath "${1:-$root/build/lumen}")
repeats=${2:-3}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
median() { printf '%s\n' "$@" | sort -g | awk '{v[NR]=$1} END {print (NR%2) ? v[(NR+1)/2] : (v[NR/2]+v[NR/2+1])/2}'; }

bodies=("x * x + y * y - sin(x * 10) * 0.1 + select(x - 0.5, 0, 0.2)"
        "f_noise3d(x * 10, y * 10, 0)"
        "Twist(x, y, 0.3, 1.5)")
names=("arithmetic" "f_noise3d" "user+internal")
scene() {  # body side
    cat <<POV
#version 3.7;
#include "functions.inc"
#declare Twist = function(x, y, z, a) { f_rounded_box(x * cos(a * y) - z * sin(a * y), y, x * sin(a * y) + z * cos(a * y), 0.1, 0.5, 0.5, 0.5) }
camera { location <0.5, 2, -1> look_at <0.5, 0, 0.5> }
height_field { function $2, $2 { $1 } pigment { rgb 1 } }
POV
}
pov_parse() { povray "+I$1" +W8 +H8 -D -F 2>&1 | sed -n 's/.*Parse Time:.*(\s*\([0-9.]*\) seconds).*/\1/p' | head -1; }
lumen_parse() { "$lumen" "+I$1" +W8 +H8 "+O$work/l.png" 2>&1 | sed -n 's/.*parsed in \([0-9.]*\) s.*/\1/p'; }

printf '%-14s %14s %14s %7s\n' function "lumen evals/s" "povray evals/s" ratio
for i in "${!bodies[@]}"; do
    scene "${bodies[$i]}" 2000 >"$work/big.pov"
    scene "x" 2000 >"$work/small.pov"
    lb=() ls=() pb=() ps=()
    for ((r = 0; r < repeats; ++r)); do
        lb+=("$(lumen_parse "$work/big.pov")") ls+=("$(lumen_parse "$work/small.pov")")
        pb+=("$(pov_parse "$work/big.pov")") ps+=("$(pov_parse "$work/small.pov")")
    done
    lt=$(echo "$(median "${lb[@]}") - $(median "${ls[@]}")" | bc -l)
    pt=$(echo "$(median "${pb[@]}") - $(median "${ps[@]}")" | bc -l)
    printf '%-14s %14.3g %14.3g %7.2f\n' "${names[$i]}" "$(echo "4000000 / $lt" | bc -l)" \
        "$(echo "4000000 / $pt" | bc -l)" "$(echo "$pt / $lt" | bc -l)"
done

TIMEFORMAT=%R
lw=() pw=()
for ((r = 0; r < repeats; ++r)); do
    lw+=("$( { time "$lumen" "+I$root/examples/isosurface.pov" +W640 +H480 +A0.3 +WT2 "+O$work/l.png" >/dev/null 2>&1; } 2>&1 )")
    pw+=("$( { time povray "+I$root/examples/isosurface.pov" +W640 +H480 +A0.3 +WT2 -D -GA "+O$work/p.png" >/dev/null 2>&1; } 2>&1 )")
done
l=$(median "${lw[@]}") p=$(median "${pw[@]}")
printf 'examples/isosurface.pov 640x480 +A0.3 +WT2: lumen %.2f s, POV-Ray %.2f s, ratio %.2f\n' \
    "$l" "$p" "$(echo "$l / $p" | bc -l)"
