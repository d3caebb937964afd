#!/usr/bin/env bash
# Usage: tests/fuzz/run.sh FUZZER [SECONDS]
# Runs the libFuzzer target for SECONDS (default 600), seeded from tests/sdl/*.pov,
# examples/*.pov and tests/fuzz/regressions/ (its earlier findings). The corpus grows in
# <fuzzer dir>/fuzz-corpus; crashes, timeouts and out-of-memory inputs are saved in
# <fuzzer dir>/fuzz-artifacts (copy each into tests/fuzz/regressions/ once fixed).
set -euo pipefail
fuzzer=$(realpath "${1:?usage: tests/fuzz/run.sh FUZZER [SECONDS]}")
seconds=${2:-600}
root=$(cd "$(dirname "$0")/../.." && pwd)
dir=$(dirname "$fuzzer")
corpus=$dir/fuzz-corpus
seeds=$dir/fuzz-seeds
artifacts=$dir/fuzz-artifacts
work=$dir/fuzz-work  # the current folder for scenes that #write or #fopen files
mkdir -p "$corpus" "$seeds" "$artifacts" "$work"
rm -f "$seeds"/*
for f in "$root"/tests/sdl/*.pov "$root"/examples/*.pov "$root"/tests/fuzz/regressions/*; do
    [ -e "$f" ] && cp "$f" "$seeds/$(basename "$(dirname "$f")")_$(basename "$f")"
done
cd "$work"
echo "fuzzing for ${seconds}s; artifacts in $artifacts" >&2
status=0
"$fuzzer" -max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 -max_len=16384 \
    -dict="$root/tests/fuzz/sdl.dict" -artifact_prefix="$artifacts/" -print_final_stats=1 \
    "$corpus" "$seeds" || status=$?
if [ "$status" -ne 0 ]; then
    echo "fuzzer found a problem (status $status): see $artifacts" >&2
    exit "$status"
fi
