#!/usr/bin/env bash
# lumen farm on a real Slurm cluster: a single node on loopback (tools/slurm-local-cluster),
# a tiled still and a 4-frame radiosity animation, byte-identical to one lumen run. Fails with
# the reason when the cluster cannot start.
# usage: farm_slurm.sh LUMEN SCENE_FOLDER CLUSTER_TOOL
set -euo pipefail
lumen=$1; scenes=$(cd "$2" && pwd); cluster_tool=$3
work=$(mktemp -d); cluster="$work/cluster"
trap '"$cluster_tool" stop "$cluster"; rm -rf "$work"' EXIT
conf=$("$cluster_tool" start "$cluster") || { echo "FAIL: the test cluster did not start" >&2; exit 1; }
eval "$conf"
cd "$work"
cp "$scenes/room.pov" .
check() { cmp "$1" "$2" || { echo "FAIL: $1 differs from $2" >&2; exit 1; }; }
# A cluster that takes jobs but never runs them must fail the test, not hang it.
slurm_farm() { timeout 120 "$lumen" farm --slurm --cpus-per-task=1 --poll=0.2 "$@"; }

still=(room.pov +W96 +H72 +A0.1 +AM2 +R2)
"$lumen" "${still[@]}" +WT2 +Osingle.png
slurm_farm --parts=4 "${still[@]}" +Ofarmed.png 2> still.log ||
    { cat still.log >&2; exit 1; }
check farmed.png single.png
grep -q "submitted jobs" still.log

anim=(room.pov +W48 +H36 +KFI1 +KFF4 +KI0 +KF0.6 +V)
mkdir single farmed
"$lumen" "${anim[@]}" +WT2 +Osingle/ 2> /dev/null
slurm_farm --parts=2 --keep "${anim[@]}" +Ofarmed/ 2> anim.log || { cat anim.log >&2; exit 1; }
for f in 1 2 3 4; do check "farmed/room$f.png" "single/room$f.png"; done
grep -q "solve" anim.log
for log in farmed/room.farm/logs/part-*.log; do
    grep -q "solution loaded from" "$log" || { echo "FAIL: $log did not load the solution" >&2; exit 1; }
done

# A part that fails is reported with its log, and the merge job never runs.
printf '#version 3.7;\n#if (frame_number = 2) #error "frame two is broken" #end\nsphere { 0, 1 pigment { rgb 1 } }\n' > bad.pov
if slurm_farm --parts=2 bad.pov +W16 +H12 +KFI1 +KFF2 2> bad.log; then
    echo "FAIL: a failing part went unnoticed" >&2; exit 1
fi
grep -q "frame two is broken" bad.log || { echo "FAIL: the failed part's log was not shown:" >&2; cat bad.log >&2; exit 1; }
echo "farm_slurm: ok"
