#!/usr/bin/env bash
# Radiosity speed against accuracy (issue 4 item 7; radiosity-notes.md §4.3, §6.3).
#
# Renders POV-Ray's radiosity/cornell.pov, unchanged apart from its radiosity quality keywords,
# at 300x300 with POV-Ray at several count/error_bound settings and with lumen over its
# radiosity methods, records wall and CPU seconds and the error against the converged POV-Ray
# reference (tests/data/cornell_pov_converged_300.png) in one CSV, and draws error against wall
# time (log-log) with gnuplot. With a library sweep program it also runs the patch-level sweep
# (mesh x form factors x solver) and draws that chart.
#
# Usage: bench/radiosity_sweep.sh [--quick] [--no-images] [--plot-only] [--lumen PATH] [--library PATH] [--out DIR]
#   --quick     a few points of each kind (about a minute)
#   --no-images only the library sweep
#   --plot-only redraw the charts from the CSVs already in --out
#   --lumen     the lumen binary (default build/lumen); skipped when it has no radiosity options
#   --library   build/bench/radiosity_sweep_library, for docs/radiosity_solver_sweep.*
#   --out       where the CSVs and charts go (default docs/)
# Error = mean absolute difference of 8-bit values on a 0..1 scale over all pixels and channels
# (idiff -a "Mean error"); RMS likewise. Both renderers use 2 threads (+WT2).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
quick=0
images=1
plot_only=0
lumen=$root/build/lumen
library=
out=$root/docs
while [ $# -gt 0 ]; do
    case $1 in
        --quick) quick=1 ;;
        --no-images) images=0 ;;
        --plot-only) plot_only=1 ;;
        --lumen) lumen=$2; shift ;;
        --library) library=$2; shift ;;
        --out) out=$2; shift ;;
        *) echo "usage: $0 [--quick] [--no-images] [--plot-only] [--lumen PATH] [--library PATH] [--out DIR]" >&2
           exit 2 ;;
    esac
    shift
done
lumen=$(realpath -m "$lumen")  # the renders run in a temporary folder
[ -n "$library" ] && library=$(realpath "$library")
scene=/usr/share/povray-3.7/scenes/radiosity/cornell.pov
ref=$root/tests/data/cornell_pov_converged_300.png
command -v gnuplot >/dev/null || { echo "gnuplot missing: tools/install-deps.sh --bench" >&2; exit 1; }
mkdir -p "$out"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
csv=$out/radiosity_error_vs_time.csv
threads=2
size=(+W300 +H300)

measure() {  # prints "wall cpu" of a command run in $work
    local TIMEFORMAT='%R %U %S' t wall user sys
    t=$( { time (cd "$work" && "$@" >"$work/log" 2>&1) ; } 2>&1 ) || {
        echo "failed: $*" >&2; tail -5 "$work/log" >&2; return 1; }
    read -r wall user sys <<<"$t"
    echo "$wall $(echo "$user + $sys" | bc -l)"
}

error_of() {  # prints "mae rmse" of an image against the reference
    idiff -a "$1" "$ref" 2>&1 | awk '/Mean error/ {m = $4} /RMS error/ {r = $4} END {print m, r}' || true
}

record() {  # renderer method params image wall cpu
    local mae rmse
    read -r mae rmse < <(error_of "$4")
    printf '%s,%s,%s,%.3f,%.3f,%s,%s\n' "$1" "$2" "$3" "$5" "$6" "$mae" "$rmse" >>"$csv"
    printf '%-8s %-22s %-44s %8.2f s %8.2f cpu  mae %s\n' "$1" "$2" "$3" "$5" "$6" "$mae" >&2
}

# POV-Ray: count / error_bound / pretrace_end; these are the file's own values.
shipped="count 200 error_bound 0.5 pretrace_end 0.01"
pov_run() {  # count error_bound pretrace_end
    local name=pov_$1_$2_$3 wall cpu
    sed -e "s/count 200/count $1/" -e "s/error_bound 0.5/error_bound $2/" \
        -e "s/pretrace_end 0.01/pretrace_end $3/" "$scene" >"$work/$name.pov"
    grep -q "count $1" "$work/$name.pov" && grep -q "error_bound $2" "$work/$name.pov"
    read -r wall cpu < <(measure povray -D -GA "+WT$threads" "${size[@]}" +FN \
        "+I$work/$name.pov" "+O$work/$name.png")
    record povray POV-Ray "count $1 error_bound $2 pretrace_end $3" "$work/$name.png" "$wall" "$cpu"
}

# lumen: one render per option set; the method label is the chart series.
lumen_run() {  # method options...
    local method=$1 name wall cpu
    shift
    name=lumen_$(echo "$method $*" | tr -c 'A-Za-z0-9' _)
    read -r wall cpu < <(measure "$lumen" "$scene" "+WT$threads" "${size[@]}" +FN \
        "+O$work/$name.png" "$@") || return 0
    record lumen "$method" "$*" "$work/$name.png" "$wall" "$cpu"
}

# lumen over its methods (README "Radiosity"): mesh size with the preview (adaptive
# subdivision on, the default, and off), the preview's gather rays, the form-factor methods,
# the gather display's cache error and the solver. The series name says what varies.
lumen_sweep() {
    local v
    local sizes=(16 8 4 2.5 1.5) off_sizes=(8 4 2.5 1.5) gathers=(130 520 1040)
    local errors=(0.1 0.05 0.03) solvers=(jacobi matrix gauss_seidel progressive)
    local methods=("Radiosity_Form_Factors=raycast Radiosity_FF_Rays=64"
                   "Radiosity_Form_Factors=analytic" "Radiosity_Form_Factors=hemicube")
    if [ $quick = 1 ]; then
        sizes=(8) off_sizes=(8) gathers=(520) errors=(0.1) solvers=(matrix)
        methods=("Radiosity_Form_Factors=analytic")
    fi
    for v in "${sizes[@]}"; do
        lumen_run "lumen preview: patch size" Radiosity_Display=preview Radiosity_Patch_Size=$v
    done
    for v in "${off_sizes[@]}"; do
        lumen_run "lumen preview without subdivision: patch size" Radiosity_Display=preview \
            Radiosity_Subdivide=off Radiosity_Patch_Size=$v
    done
    for v in "${gathers[@]}"; do
        lumen_run "lumen preview: gather rays" Radiosity_Display=preview Radiosity_Gather_Rays=$v
    done
    for v in "${methods[@]}"; do
        # shellcheck disable=SC2086  # two options in one entry
        lumen_run "lumen preview: form factors" Radiosity_Display=preview $v
    done
    for v in "${errors[@]}"; do
        lumen_run "lumen gather: cache error (576 rays)" Radiosity_Display=gather \
            Radiosity_Cache_Error=$v Radiosity_Gather_Rays=576
    done
    # jacobi stops after the scene's recursion_limit bounces as POV does; the others converge.
    for v in "${solvers[@]}"; do
        lumen_run "lumen preview: solver" Radiosity_Display=preview Radiosity_Patch_Size=8 \
            Radiosity_Method=$v
    done
}
# Error against time, log-log, one series per distinct value of the method column (each
# series sorted by time into its own file, so its points join up).
plot() {  # csv png title method-column x-column y-column xlabel ylabel [extra plot clause]
    local methods=() m i=0 clauses=()
    mapfile -t methods < <(awk -F, -v c="$4" 'NR > 1 && !/^(#|n,)/ {print $c}' "$1" | awk '!seen[$0]++')
    for m in "${methods[@]}"; do
        i=$((i + 1))
        awk -F, -v c="$4" -v m="$m" '$c == m' "$1" | sort -t, -g -k"$5,$5" >"$work/series$i.csv"
        # colours repeat after 8 series; the point shape tells them apart
        clauses+=("\"$work/series$i.csv\" using $5:$6 with linespoints lt $i pt $((i % 13 + 1)) ps 0.9 title \"$m\"")
    done
    [ $# -ge 9 ] && clauses+=("$9")
    local joined
    joined=$(printf '%s, ' "${clauses[@]}")
    gnuplot <<EOF
set terminal pngcairo size 1000,640 font "sans,10" noenhanced
set output "$2"
set datafile separator ","
set title "$3"
set logscale xy
set xlabel "$7"
set ylabel "$8"
set grid xtics ytics mxtics mytics lc rgb "#dddddd"
set key outside right top
plot ${joined%, }
EOF
    echo "wrote $2" >&2
}

image_sweep() {
    echo "renderer,method,params,wall_s,cpu_s,mae,rmse" >"$csv"
    local load_before s
    load_before=$(cut -d' ' -f1-3 /proc/loadavg)
    if [ $quick = 1 ]; then
        pov_settings=("35 1.8 0.01" "200 0.5 0.01")
    else
        pov_settings=("35 1.8 0.01" "50 1.2 0.01" "100 0.8 0.01" "200 0.5 0.01" "400 0.3 0.01"
                      "800 0.2 0.01" "800 0.2 0.005")
    fi
    for s in "${pov_settings[@]}"; do pov_run $s; done
    if [ -x "$lumen" ] && "$lumen" --help 2>&1 | grep -qi radiosity_method; then
        lumen_sweep
    else
        echo "lumen at $lumen has no Radiosity_Method option: POV-Ray points only" >&2
    fi
    echo "# load average (1, 5, 15 min) before: $load_before; after: $(cut -d' ' -f1-3 /proc/loadavg); $(nproc) cores" >>"$csv"
    echo "wrote $csv" >&2
}

image_chart() {
    plot "$csv" "$out/radiosity_error_vs_time.png" \
        "cornell.pov 300x300: error against converged POV-Ray, $threads threads" \
        2 4 6 "wall time (s)" "mean absolute error (8-bit values, 0..1)" \
        "\"$csv\" using (strcol(3) eq \"$shipped\" ? \$4 : NaN):6 with points pt 6 ps 2.5 lc rgb \"black\" title \"POV-Ray as shipped\""
}

library_sweep() {
    local lib_csv=$out/radiosity_solver_sweep.csv flags=()
    [ $quick = 1 ] && flags=(--quick)
    "$library" "${flags[@]}" "$scene" >"$lib_csv"
    echo "wrote $lib_csv" >&2
}

library_chart() {
    local lib_csv=$out/radiosity_solver_sweep.csv
    plot "$lib_csv" "$out/radiosity_solver_sweep.png" \
        "cornell.pov geometry, patch level, 1 thread: along a series the mesh gets finer (max edge 24, 16, 12, 8)" \
        3 9 11 "form factors + solve CPU time (s)" "relative L1 error of B against the fine-mesh reference"
}

if [ $plot_only = 1 ]; then
    [ -f "$csv" ] && image_chart
    [ -f "$out/radiosity_solver_sweep.csv" ] && library_chart
    exit 0
fi
if [ $images = 1 ]; then image_sweep; image_chart; fi
if [ -n "$library" ]; then library_sweep; library_chart; fi
exit 0
