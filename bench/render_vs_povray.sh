#!/usr/bin/env bash
# Usage: bench/render_vs_povray.sh [LUMEN] [THREADS]
# Renders each examples/*.pov at 800x600 +A0.3 with lumen and with POV-Ray (same +WT thread
# count, default: all cores) and prints both wall times and their ratio.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
lumen=$(realpath "${1:-$root/build/lumen}")
threads=${2:-$(nproc)}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
opts=(+W800 +H600 +A0.3 +AM1 +R3 -J "+WT$threads")

wall() {  # prints the wall time of a command, in seconds
    local start end
    start=$(date +%s.%N)
    "$@" >"$work/log" 2>&1 || { echo "failed: $*" >&2; cat "$work/log" >&2; return 1; }
    end=$(date +%s.%N)
    echo "$end - $start" | bc -l
}

printf '%-24s %10s %10s %8s\n' scene "lumen s" "povray s" ratio
for scene in "$root"/examples/*.pov; do
    name=$(basename "$scene" .pov)
    dir=$(dirname "$scene")
    l=$(cd "$work" && wall "$lumen" "$scene" "${opts[@]}" "+L$dir" "+O$work/$name-lumen.png") || continue
    p=$(cd "$work" && wall povray -D -V +FN "${opts[@]}" "+L$dir" "+I$scene" "+O$work/$name-pov.png") || continue
    printf '%-24s %10.2f %10.2f %8.2f\n' "$name" "$l" "$p" "$(echo "$l / $p" | bc -l)"
done
