#!/usr/bin/env bash
# Usage: bench/render_vs_povray.sh [LUMEN] [THREADS]
# Renders each examples/*.pov at 800x600 +A0.3 with lumen and with POV-Ray (same +WT thread
# count, default: all cores) and prints wall and CPU (user+sys) seconds and the wall ratio.
# On a busy machine the CPU times are the steadier figures.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
lumen=$(realpath "${1:-$root/build/lumen}")
threads=${2:-$(nproc)}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
opts=(+W800 +H600 +A0.3 +AM1 +R3 -J "+WT$threads")

measure() {  # prints "wall cpu" for a command run in $work
    local TIMEFORMAT='%R %U %S' t
    t=$( { time (cd "$work" && "$@" >"$work/log" 2>&1) ; } 2>&1 ) || {
        echo "failed: $*" >&2; cat "$work/log" >&2; return 1; }
    read -r wall user sys <<<"$t"
    echo "$wall $(echo "$user + $sys" | bc -l)"
}

printf '%-16s %9s %9s %9s %9s %7s\n' scene "lumen s" "lumen cpu" "povray s" "pov cpu" ratio
for scene in "$root"/examples/*.pov; do
    name=$(basename "$scene" .pov)
    dir=$(dirname "$scene")
    read -r lw lc < <(measure "$lumen" "$scene" "${opts[@]}" "+L$dir" "+O$work/$name-lumen.png") || continue
    read -r pw pc < <(measure povray -D -V +FN "${opts[@]}" "+L$dir" "+I$scene" "+O$work/$name-pov.png") || continue
    printf '%-16s %9.2f %9.2f %9.2f %9.2f %7.2f\n' "$name" "$lw" "$lc" "$pw" "$pc" "$(echo "$lw / $pw" | bc -l)"
done
