#!/usr/bin/env bash
# lumen farm on this machine gives the files one lumen run writes, byte for byte: a still in
# tiles and a radiosity animation in frame ranges; a scene error stops it before any part.
# usage: farm_local.sh LUMEN SCENE_FOLDER
set -euo pipefail
lumen=$1; scenes=$(cd "$2" && pwd)
work=$(mktemp -d); trap 'rm -rf "$work"' EXIT
cd "$work"
cp "$scenes/room.pov" .
check() { cmp "$1" "$2" || { echo "FAIL: $1 differs from $2" >&2; exit 1; }; }

still=(room.pov +W96 +H72 +A0.1 +AM2 +R2)
"$lumen" "${still[@]}" +Osingle.png +V 2> single_still.log
# The scene has radiosity point gathers (their per-block caches keep pixels independent of
# threads and tiles), and one thread gives what two do.
grep -q "point gathers" single_still.log || { echo "FAIL: no point gathers to test" >&2; exit 1; }
"$lumen" "${still[@]}" +WT1 +Oone_thread.png 2> /dev/null
check one_thread.png single.png
"$lumen" farm --jobs=2 --parts=6 "${still[@]}" +Ofarmed.png
check farmed.png single.png
[ ! -e farmed.farm ] || { echo "FAIL: the work folder was left behind" >&2; exit 1; }
# The plan printed as a script gives the same file.
"$lumen" farm --plan --parts=4 "${still[@]}" +Oscripted.png > plan.sh
[ ! -e scripted.farm ] || { echo "FAIL: --plan ran something" >&2; exit 1; }
sh plan.sh 2> /dev/null
check scripted.png single.png

anim=(room.pov +W48 +H36 +KFI1 +KFF4 +KI0 +KF0.6)
mkdir single farmed
"$lumen" "${anim[@]}" +V +Osingle/ 2> single.log
[ "$(grep -c "solution reused" single.log)" = 3 ] ||
    { echo "FAIL: the frames do not share one radiosity solution" >&2; exit 1; }
"$lumen" farm --jobs=2 --parts=3 --keep "${anim[@]}" +V +Ofarmed/ 2> farm.log
for f in 1 2 3 4; do check "farmed/room$f.png" "single/room$f.png"; done
grep -q "after a radiosity solve" farm.log || { echo "FAIL: no radiosity solve" >&2; exit 1; }
ls farmed/room.farm/radiosity/*.rad > /dev/null
# Every part loaded the solve's solution rather than solving again.
for log in farmed/room.farm/logs/part-*.log; do
    grep -q "solution loaded from" "$log" || { echo "FAIL: $log did not load the solution" >&2; exit 1; }
done

# SIGTERM stops every part (each removes its unfinished file) and writes no image.
"$lumen" farm --jobs=2 --parts=4 room.pov +W1920 +H1080 +A0.0 +R3 +Ostopped.png 2> stopped.log &
pid=$!
for _ in $(seq 400); do [ -e stopped.farm/logs/part-0.log ] && break; sleep 0.05; done
sleep 0.2
kill -TERM "$pid"
status=0; wait "$pid" || status=$?
[ "$status" = 143 ] || { echo "FAIL: lumen farm ended with $status after SIGTERM" >&2; cat stopped.log >&2; exit 1; }
[ ! -e stopped.png ] && [ -z "$(ls -A stopped.farm/parts)" ] ||
    { echo "FAIL: files left after SIGTERM" >&2; ls -aR stopped.farm >&2; exit 1; }

printf '#version 3.7;\nsphere { 0, 1 pigment { colour Nope } }\n' > bad.pov
if "$lumen" farm --jobs=2 bad.pov +W32 +H24 2> bad.log; then
    echo "FAIL: a broken scene was farmed" >&2; exit 1
fi
grep -q "bad.pov:2" bad.log || { echo "FAIL: no located error:" >&2; cat bad.log >&2; exit 1; }
[ ! -e bad.farm ] || { echo "FAIL: a work folder for a broken scene" >&2; exit 1; }
echo "farm_local: ok"
