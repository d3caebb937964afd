#!/usr/bin/env bash
# Copies of one mesh, lumen against POV-Ray in the same run: a 20,000-triangle mesh2 declared
# once and placed 1 to 400 times (`object { M translate ... }`, as scenes place trees or
# chess pieces), rendered at 320x240 without anti-aliasing, +WT2. Both renderers share the
# mesh's data between copies; the table shows wall time and peak memory (RSS) per count,
# each the median of REPEATS runs (default 3), the two renderers alternating.
#
# Usage: bench/mesh_copies.sh [--repeats N] [--lumen PATH]
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
lumen=$root/build/lumen
repeats=3
args=("$@")
for ((i = 0; i < ${#args[@]}; i += 2)); do  # each option takes a value
    case ${args[i]}=${args[i + 1]:-} in
        --repeats=?*) repeats=${args[i + 1]} ;;
        --lumen=?*) lumen=${args[i + 1]} ;;
        *) echo "usage: $0 [--repeats N] [--lumen PATH]" >&2; exit 2 ;;
    esac
done
source "$root/bench/measure_common.sh"

# The scene with `copies` copies of a bumpy 100 x 100 sphere grid, in rows of 20.
gen_scene() {
    awk -v copies="$1" 'BEGIN {
        n = 100; pi = 3.14159265358979
        print "#version 3.7;\nglobal_settings { assumed_gamma 1 }"
        print "camera { location <0, 30, -60> look_at <0, 0, 10> angle 60 }"
        print "light_source { <20, 40, -20> rgb 1 }\nplane { y, -1.2 pigment { rgb 0.6 } }"
        printf "#declare M = mesh2 { vertex_vectors { %d,\n", (n + 1) * (n + 1)
        for (j = 0; j <= n; ++j) for (i = 0; i <= n; ++i) {
            u = i / n * 2 * pi; v = j / n * pi; r = 1 + 0.1 * sin(5 * u) * sin(4 * v)
            printf "<%.6f,%.6f,%.6f>,\n", r * sin(v) * cos(u), r * cos(v), r * sin(v) * sin(u)
        }
        printf "}\nface_indices { %d,\n", 2 * n * n
        for (j = 0; j < n; ++j) for (i = 0; i < n; ++i) {
            a = j * (n + 1) + i; c = a + n + 1
            printf "<%d,%d,%d>, <%d,%d,%d>,\n", a, a + 1, c + 1, a, c + 1, c
        }
        print "}\npigment { rgb <0.8, 0.5, 0.3> } }"
        printf "#for (K, 0, %d) object { M translate <(mod(K, 20) - 9.5) * 2.5, 0, div(K, 20) * 2.5> } #end\n", copies - 1
    }' >"$work/copies.pov"
}

# Median "seconds KiB" of REPEATS runs of one renderer (1: lumen, 2: POV-Ray).
measure() {
    local i runs=()
    for ((i = 0; i < repeats; ++i)) {
        if [ "$1" = lumen ]; then
            /usr/bin/time -f "%e %M" -o "$work/t" "$lumen" "$work/copies.pov" +W320 +H240 -A +WT2 \
                "+O$work/l.png" >/dev/null 2>&1
        else
            /usr/bin/time -f "%e %M" -o "$work/t" povray "$work/copies.pov" +W320 +H240 -A +WT2 -D \
                "+O$work/p.png" >/dev/null 2>&1
        fi
        runs+=("$(tail -1 "$work/t")")
    }
    printf '%s\n' "${runs[@]}" | sort -g | awk '{v[NR] = $0} END {print v[int((NR + 1) / 2)]}'
}

printf '%7s %10s %10s %7s %12s %12s\n' copies lumen_s povray_s ratio lumen_MiB povray_MiB
for copies in 1 10 100 400; do
    gen_scene "$copies"
    l=$(measure lumen) p=$(measure povray)
    read -r ls lk <<<"$l"
    read -r ps pk <<<"$p"
    awk -v c="$copies" -v ls="$ls" -v ps="$ps" -v lk="$lk" -v pk="$pk" 'BEGIN {
        printf "%7d %10.2f %10.2f %7.3f %12.1f %12.1f\n", c, ls, ps, ls / ps, lk / 1024, pk / 1024 }'
done
