#!/usr/bin/env bash
# lumen farm against one lumen process, in one run: a 16-tile 3840x2160 still
# (examples/showcase.pov) and a 30-frame radiosity animation (tests/farm/room.pov), through a
# Slurm cluster (a one-node cluster on loopback from tools/slurm-local-cluster unless
# SLURM_CONF is set) and locally; every farmed file is compared with the single run's.
# usage: bench/farm.sh [LUMEN] [CPUS_PER_TASK]
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
lumen=$(realpath "${1:-$root/build/lumen}")
cpus=${2:-1}
work=$(mktemp -d)
cluster=""
cleanup() { [ -n "$cluster" ] && "$root/tools/slurm-local-cluster" stop "$cluster"; rm -rf "$work"; }
trap cleanup EXIT
if [ -z "${SLURM_CONF:-}" ]; then
    cluster="$work/cluster"
    eval "$("$root/tools/slurm-local-cluster" start "$cluster")"
fi
cd "$work"
cp "$root/examples/showcase.pov" "$root/tests/farm/room.pov" .
seconds() { local t0; t0=$(date +%s.%N); "$@" > /dev/null 2>&1 || { echo "failed: $*" >&2; exit 1; }; echo "$(date +%s.%N) - $t0" | bc; }
same() { for f in "$@"; do cmp -s "one/$f" "farm/$f" || { echo "DIFFERENT: $f" >&2; exit 1; }; done; echo "identical"; }
mkdir one farm
echo "nodes: $(sinfo -h -o '%D nodes, %c CPUs each')"

still=(showcase.pov +W3840 +H2160 +A0.3)
t1=$(seconds "$lumen" "${still[@]}" +Oone/still.png)
t2=$(seconds "$lumen" farm --slurm --parts=16 --cpus-per-task="$cpus" "${still[@]}" +Ofarm/still.png)
printf 'still 3840x2160, 16 tiles: one process %.1f s, Slurm %.1f s (%s)\n' "$t1" "$t2" "$(same still.png)"
t3=$(seconds "$lumen" farm --parts=16 --jobs=2 "${still[@]}" +Ofarm/still.png)
printf 'still 3840x2160, 16 tiles: local --jobs=2 %.1f s (%s)\n' "$t3" "$(same still.png)"

anim=(room.pov +W640 +H480 +A0.3 +KFI1 +KFF30 +KI0 +KF1)
frames=$(for i in $(seq -w 1 30); do echo "room$i.png"; done)
t4=$(seconds "$lumen" "${anim[@]}" +Oone/)
t5=$(seconds "$lumen" farm --slurm --parts=8 --cpus-per-task="$cpus" "${anim[@]}" +Ofarm/)
# shellcheck disable=SC2086
printf 'animation 30 frames 640x480, radiosity: one process %.1f s, Slurm %.1f s in 8 parts (%s)\n' "$t4" "$t5" "$(same $frames)"
