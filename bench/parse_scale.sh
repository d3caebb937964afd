#!/usr/bin/env bash
# Parsing big inputs, lumen against POV-Ray in the same run: wall time and peak memory (RSS)
# against input size, for
#   mesh:  a mesh2 grid as a model exporter writes it (one vertex or face per line), 10k to
#          2M triangles;
#   expr:  one #declare whose right side is a sum of 10k to 2M terms.
# Both renderers get +W16 +H12 -F, so that parsing dominates. Each point is the median of
# REPEATS runs (default 3), the two renderers alternating. Prints a table with the ratios,
# writes docs/parse_scale.csv and draws docs/parse_scale.png (gnuplot).
#
# Usage: bench/parse_scale.sh [--quick] [--repeats N] [--lumen PATH] [--out DIR]
#   --quick   sizes up to 200k only, one run each
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
lumen=$root/build/lumen
out=$root/docs
repeats=3
meshes=(10000 50000 200000 1000000 2000000)
exprs=(10000 100000 200000 1000000 2000000)
while [ $# -gt 0 ]; do
    case $1 in
        --quick) repeats=1; meshes=(10000 50000 200000); exprs=(10000 100000 200000) ;;
        --repeats) repeats=$2; shift ;;
        --lumen) lumen=$2; shift ;;
        --out) out=$2; shift ;;
        *) echo "unknown option $1" >&2; exit 2 ;;
    esac
    shift
done
source "$root/bench/measure_common.sh"
mkdir -p "$out"
csv=$out/parse_scale.csv

# mesh2 of about T triangles: an n x n grid of quads, two triangles each.
gen_mesh() {
    awk -v t="$1" 'BEGIN {
        n = int(sqrt(t / 2) + 0.5); m = n + 1
        print "#version 3.7;"
        print "camera { location <0.5, 2, -1.5> look_at <0.5, 0, 0.5> }"
        print "light_source { <2, 5, -3> rgb 1 }"
        print "mesh2 {"
        printf "  vertex_vectors {\n    %d,\n", m * m
        for (j = 0; j < m; j++) for (i = 0; i < m; i++) {
            x = i / n; z = j / n; y = 0.1 * sin(x * 12.9898 + z * 78.233) * cos(z * 9.1)
            printf "    <%.6f,%.6f,%.6f>%s\n", x, y, z, (i == n && j == n) ? "" : ","
        }
        printf "  }\n  face_indices {\n    %d,\n", 2 * n * n
        for (j = 0; j < n; j++) for (i = 0; i < n; i++) {
            a = j * m + i; b = a + 1; c = a + m; d = c + 1
            printf "    <%d,%d,%d>,\n    <%d,%d,%d>%s\n", a, b, d, a, d, c,
                   (i == n - 1 && j == n - 1) ? "" : ","
        }
        print "  }\n  pigment { rgb 1 }\n}"
    }'
}

# One sum of N terms.
gen_expr() {
    awk -v n="$1" 'BEGIN {
        print "#version 3.7;"
        printf "#declare S = 0"
        for (i = 1; i <= n; i++) printf " + %d * 0.5", i % 97
        print ";\nsphere { 0, 1 pigment { rgb S / 1e9 } }"
    }'
}

# Prints "wall_s peak_mib" of one run, or "fail fail".
run_one() {
    local r
    if r=$(/usr/bin/time -f "%e %M" "$@" 2>&1 >/dev/null | tail -1) && [[ $r =~ ^[0-9.]+\ [0-9]+$ ]]; then
        awk -v r="$r" 'BEGIN { split(r, a, " "); printf "%s %.1f\n", a[1], a[2] / 1024 }'
    else
        echo "fail fail"
    fi
}

median() { printf '%s\n' "$@" | sort -g | awk '{v[NR]=$1} END {print (NR%2) ? v[(NR+1)/2] : (v[NR/2]+v[NR/2+1])/2}'; }

echo "kind,size,bytes,lumen_s,povray_s,lumen_mib,povray_mib" >"$csv"
printf '%-5s %9s %9s %9s %9s %6s %10s %10s %6s\n' kind size MB lumen_s povray_s ratio lumen_MiB povray_MiB ratio
measure() {  # kind size file
    local lw=() pw=() lm=() pm=() l p
    for ((r = 0; r < repeats; ++r)); do
        read -r a b < <(run_one "$lumen" "$3" +W16 +H12 -F -D)
        lw+=("$a"); lm+=("$b")
        read -r a b < <(run_one povray "+I$3" +W16 +H12 -F -D -V)
        pw+=("$a"); pm+=("$b")
    done
    l=$(median "${lw[@]}") p=$(median "${pw[@]}")
    local lmm pmm bytes
    lmm=$(median "${lm[@]}") pmm=$(median "${pm[@]}") bytes=$(stat -c %s "$3")
    echo "$1,$2,$bytes,$l,$p,$lmm,$pmm" >>"$csv"
    awk -v k="$1" -v s="$2" -v b="$bytes" -v l="$l" -v p="$p" -v lm="$lmm" -v pm="$pmm" 'BEGIN {
        printf "%-5s %9d %9.1f %9.2f %9.2f %6.2f %10.0f %10.0f %6.1f\n",
               k, s, b / 1e6, l, p, l / p, lm, pm, lm / pm }'
}
for t in "${meshes[@]}"; do
    gen_mesh "$t" >"$work/mesh.pov"
    measure mesh "$t" "$work/mesh.pov"
done
for n in "${exprs[@]}"; do
    gen_expr "$n" >"$work/expr.pov"
    measure expr "$n" "$work/expr.pov"
done
echo "wrote $csv"

if command -v gnuplot >/dev/null; then
    gnuplot <<EOF
set terminal pngcairo size 1100,800 font ",10"
set output "$out/parse_scale.png"
set datafile separator ","
set logscale xy
set key top left
set grid
set multiplot layout 2,2 title "Parsing big inputs: lumen against POV-Ray 3.7 (+W16 +H12 -F, median of $repeats)"
do for [i = 1:2] {
    kind = word("mesh expr", i)
    set xlabel word("triangles terms", i)
    set ylabel "wall seconds"
    set title (i == 1 ? "mesh2" : "one long expression") . ": time"
    plot "$csv" using (strcol(1) eq kind ? \$2 : 1/0):4 with linespoints title "lumen", \
         "" using (strcol(1) eq kind ? \$2 : 1/0):5 with linespoints title "POV-Ray"
    set ylabel "peak MiB"
    set title (i == 1 ? "mesh2" : "one long expression") . ": memory"
    plot "$csv" using (strcol(1) eq kind ? \$2 : 1/0):6 with linespoints title "lumen", \
         "" using (strcol(1) eq kind ? \$2 : 1/0):7 with linespoints title "POV-Ray"
}
unset multiplot
EOF
    echo "wrote $out/parse_scale.png"
else
    echo "gnuplot missing: no chart (tools/install-deps.sh --bench)"
fi
