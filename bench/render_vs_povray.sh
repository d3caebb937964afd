#!/usr/bin/env bash
# Usage: bench/render_vs_povray.sh [LUMEN] [THREADS] [REPEATS] [SCENE...]
# Renders each examples/*.pov (or the SCENEs given) at 800x600 +A0.3 (SIZE=640x480 in the
# environment for another size) with lumen and with
# POV-Ray (same +WT thread count, default: all cores), REPEATS times each (default 3, the two
# renderers alternating), and prints per scene the median wall and CPU (user+sys) seconds of
# each and the ratio of the median walls lumen/POV-Ray; the last line gives the worst and the
# geometric-mean ratio. On a busy machine the CPU times are the steadier figures.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
lumen=$(realpath "${1:-$root/build/lumen}")
threads=${2:-$(nproc)}
repeats=${3:-3}
shift $(( $# < 3 ? $# : 3 ))
scenes=("$@")
[ ${#scenes[@]} -eq 0 ] && scenes=("$root"/examples/*.pov)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
# POV-Ray's default anti-aliasing (AM1, depth 3, jitter 1.0): lumen's jitter is POV's.
size=${SIZE:-800x600}
opts=("+W${size%x*}" "+H${size#*x}" +A0.3 "+WT$threads")

measure() {  # prints "wall cpu" for a command run in $work
    local TIMEFORMAT='%R %U %S' t
    t=$( { time (cd "$work" && "$@" >"$work/log" 2>&1) ; } 2>&1 ) || {
        echo "failed: $*" >&2; cat "$work/log" >&2; return 1; }
    read -r wall user sys <<<"$t"
    echo "$wall $(echo "$user + $sys" | bc -l)"
}

median() { printf '%s\n' "$@" | sort -g | awk '{v[NR]=$1} END {print (NR%2) ? v[(NR+1)/2] : (v[NR/2]+v[NR/2+1])/2}'; }

printf '%-16s %9s %9s %9s %9s %7s\n' scene "lumen s" "lumen cpu" "povray s" "pov cpu" ratio
worst=0 log_sum=0 count=0
for scene in "${scenes[@]}"; do
    scene=$(realpath "$scene")
    name=$(basename "$scene" .pov)
    dir=$(dirname "$scene")
    lw=() lc=() pw=() pc=()
    for ((i = 0; i < repeats; ++i)); do
        read -r w c < <(measure "$lumen" "$scene" "${opts[@]}" "+L$dir" "+O$work/$name-lumen.png") || continue 2
        lw+=("$w") lc+=("$c")
        read -r w c < <(measure povray -D -V +FN "${opts[@]}" "+L$dir" "+I$scene" "+O$work/$name-pov.png") || continue 2
        pw+=("$w") pc+=("$c")
    done
    mlw=$(median "${lw[@]}") mlc=$(median "${lc[@]}") mpw=$(median "${pw[@]}") mpc=$(median "${pc[@]}")
    ratio=$(echo "$mlw / $mpw" | bc -l)
    printf '%-16s %9.3f %9.2f %9.3f %9.2f %7.3f\n' "$name" "$mlw" "$mlc" "$mpw" "$mpc" "$ratio"
    worst=$(echo "if ($ratio > $worst) $ratio else $worst" | bc -l)
    log_sum=$(echo "$log_sum + l($ratio)" | bc -l)
    count=$((count + 1))
done
[ "$count" -gt 0 ] && printf 'wall ratio lumen/povray over %d scenes (median of %d runs): worst %.3f, geometric mean %.3f\n' \
    "$count" "$repeats" "$worst" "$(echo "e($log_sum / $count)" | bc -l)"
