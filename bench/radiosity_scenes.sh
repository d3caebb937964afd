#!/usr/bin/env bash
# Radiosity error against time on every scene with a converged reference (issue 14 item 5):
# for each line of tests/radiosity/references.txt, POV-Ray at its shipped settings and at a
# sweep of count / error_bound (the scene included unchanged, a later radiosity block naming
# only those two), and lumen at its defaults and over its display methods; the mean absolute
# error against the converged reference (the differential tool's 4th figure) and the wall
# time, both renderers +WT2, no anti-aliasing, the first frame of an animation. Writes
# docs/radiosity_scenes.csv and docs/radiosity_scenes.png (one log-log panel per scene), and
# prints per scene POV-Ray's shipped figures against lumen's defaults.
#
# Usage: bench/radiosity_scenes.sh [--lumen PATH] [--out DIR] [--repeats N] [--plot-only]
#   --repeats N  runs per point, the median wall time kept (default 1; the machine is noisy)
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
lumen=$root/build/lumen
compare=$root/build/tests/differential/differential
out=$root/docs
repeats=1
plot_only=0
while [ $# -gt 0 ]; do
    case $1 in
        --lumen) lumen=$2; shift ;;
        --out) out=$2; shift ;;
        --repeats) repeats=$2; shift ;;
        --plot-only) plot_only=1 ;;
        *) echo "usage: $0 [--lumen PATH] [--out DIR] [--repeats N] [--plot-only]" >&2; exit 2 ;;
    esac
    shift
done
lumen=$(realpath "$lumen")
scenes=/usr/share/povray-3.7/scenes
csv=$out/radiosity_scenes.csv
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT INT TERM
mkdir -p "$out"

wall_of() {  # runs a command (in $work) $repeats times; prints the median wall seconds
    local walls=() i s e
    for ((i = 0; i < repeats; ++i)); do
        s=$(date +%s.%N)
        "$@" >"$work/log" 2>&1 || { echo "failed: $*" >&2; tail -3 "$work/log" >&2; return 1; }
        e=$(date +%s.%N)
        walls+=("$(echo "$e - $s" | bc -l)")
    done
    printf '%s\n' "${walls[@]}" | sort -g | awk '{v[NR]=$1} END {print v[int((NR+1)/2)]}'
}

mae_of() { "$compare" --compare "$1" "$2" "$work/heat.png" | cut -d' ' -f4; }

sweep_scene() {  # scene WxH reference
    local scene=$1 w=${2%x*} h=${2#*x} ref=$root/tests/data/$3 src dir name wall
    src=$scenes/$scene
    dir=$(dirname "$src")
    name=$(basename "$scene" .pov)
    local pov=(povray -D -GA +WT2 "+W$w" "+H$h" -A +FN +KFI1 +KFF1 "+L$dir")
    local lum=("$lumen" "+W$w" "+H$h" -A +WT2 +FN +KFI1 +KFF1 "+L$dir")
    row() { echo "$name,$1,$2,$3,$4" >>"$csv"; printf '  %-9s %-34s %7.2f s  mae %s\n' "$1" "$2" "$3" "$4" >&2; }
    echo "$scene $2" >&2
    wall=$(cd "$dir" && wall_of "${pov[@]}" "+I$src" "+O$work/p.png") &&
        row "POV-Ray" "POV-Ray as shipped" "$wall" "$(mae_of "$ref" "$work/p.png")"
    local s count bound
    for s in "35 1.8" "100 0.8" "200 0.5" "400 0.3"; do
        read -r count bound <<<"$s"
        printf '#include "%s"\nglobal_settings { radiosity { count %s error_bound %s } }\n' \
            "$src" "$count" "$bound" >"$work/sweep.pov"
        wall=$(cd "$dir" && wall_of "${pov[@]}" "+I$work/sweep.pov" "+O$work/p.png") &&
            row "POV-Ray" "POV-Ray: count / error_bound" "$wall" "$(mae_of "$ref" "$work/p.png")"
    done
    lumen_point() {  # series options...
        local series=$1
        shift
        wall=$(cd "$dir" && wall_of "${lum[@]}" "$src" "+O$work/l.png" "$@") &&
            row "lumen" "$series" "$wall" "$(mae_of "$ref" "$work/l.png")"
    }
    lumen_point "lumen defaults"
    for g in 32 128 256; do lumen_point "lumen preview: gather rays" Radiosity_Gather_Rays=$g; done
    for e in 0.4 0.2 0.1; do lumen_point "lumen preview: cache error" Radiosity_Cache_Error=$e; done
    for e in 0.3 0.1 0.05; do
        lumen_point "lumen gather display: cache error" Radiosity_Display=gather Radiosity_Cache_Error=$e
    done
}

plot() {
    command -v gnuplot >/dev/null || { echo "gnuplot missing: tools/install-deps.sh --bench" >&2; exit 1; }
    local names=() n i=0 series=() k
    mapfile -t names < <(awk -F, 'NR > 1 && !/^#/ {print $1}' "$csv" | awk '!seen[$0]++')
    mapfile -t series < <(awk -F, 'NR > 1 && !/^#/ {print $3}' "$csv" | awk '!seen[$0]++')
    local cols=3 rows=$(( (${#names[@]} + 2) / 3 ))
    {
        echo 'set terminal pngcairo size 1500,'$((rows * 420))' font "sans,9" noenhanced'
        echo "set output \"$out/radiosity_scenes.png\""
        echo 'set datafile separator ","'
        echo 'set logscale xy'
        echo 'set grid xtics ytics mxtics mytics lc rgb "#dddddd"'
        echo 'set xlabel "wall time (s), +WT2"'
        echo 'set ylabel "mean abs. error vs converged POV-Ray"'
        echo "set multiplot layout $rows,$cols title \"Radiosity: error against time per scene (bench/radiosity_scenes.sh)\""
        for n in "${names[@]}"; do
            i=$((i + 1))
            echo "set title \"$n\""
            [ $i -eq 1 ] && echo 'set key top right font ",7"' || echo 'unset key'
            local clauses=()
            for k in "${!series[@]}"; do
                awk -F, -v n="$n" -v s="${series[$k]}" '$1 == n && $3 == s' "$csv" | sort -t, -g -k4,4 \
                    >"$work/s_${i}_$k.csv"
                local style="linespoints lt $((k + 1)) pt $((k % 13 + 1))"
                case ${series[$k]} in
                    "POV-Ray as shipped") style="points pt 6 ps 2.5 lc rgb \"black\"" ;;
                    "lumen defaults") style="points pt 7 ps 1.8 lc rgb \"red\"" ;;
                esac
                clauses+=("\"$work/s_${i}_$k.csv\" using 4:5 with $style title \"${series[$k]}\"")
            done
            local joined
            joined=$(printf '%s, ' "${clauses[@]}")
            echo "plot ${joined%, }"
        done
        echo 'unset multiplot'
    } | gnuplot
    echo "wrote $out/radiosity_scenes.png" >&2
}

summary() {  # POV-Ray as shipped against lumen's defaults, per scene
    awk -F, '!/^#/ && NR > 1 {
        if ($3 == "POV-Ray as shipped") { pw[$1] = $4; pe[$1] = $5; order[++n] = $1 }
        if ($3 == "lumen defaults") { lw[$1] = $4; le[$1] = $5 }
    } END {
        printf "%-18s %9s %9s %9s %9s %7s\n", "scene", "POV s", "POV mae", "lumen s", "lumen mae", "ratio"
        for (i = 1; i <= n; ++i) { s = order[i]
            printf "%-18s %9.2f %9.5f %9.2f %9.5f %7.3f\n", s, pw[s], pe[s], lw[s], le[s], lw[s] / pw[s] }
    }' "$csv"
}

if [ $plot_only = 0 ]; then
    echo "scene,renderer,series,wall_s,mae" >"$csv"
    while read -r scene size _bar ref; do
        sweep_scene "$scene" "$size" "$ref"
    done < <(grep -v '^#' "$root/tests/radiosity/references.txt" | grep .)
    echo "# $(date -u +%F) load average before the plot: $(cut -d' ' -f1-3 /proc/loadavg); $(nproc) cores; repeats $repeats" >>"$csv"
fi
plot
summary
