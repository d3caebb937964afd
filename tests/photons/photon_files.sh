#!/bin/sh
# photons { save_file } then { load_file }: the loaded map renders the very image the shot one
# did (Kind 1: photons by count, the gather radius chosen from the map), no temporary file is
# left beside the map, and a missing map stops the render at the load_file keyword with no
# image written.
#   photon_files.sh LUMEN COMPARE SCENE WORK_DIR
set -eu
lumen=$1 compare=$2 scene=$3 work=$4
rm -rf "$work"
mkdir -p "$work"
cd "$work"
run() { "$lumen" "$scene" +W96 +H72 -A -D Declare=Kind=1 "$@"; }
run +Oshot.png Declare=File=1 > shot.log 2>&1 || { cat shot.log; exit 1; }
[ -s photons.ph ] || { echo "save_file wrote no photons.ph"; exit 1; }
run +Oloaded.png Declare=File=2 > loaded.log 2>&1 || { cat loaded.log; exit 1; }
psnr=$("$compare" --compare shot.png loaded.png heat.png | cut -d' ' -f1)
[ "$psnr" = inf ] || { echo "loaded map renders differently: $psnr dB"; exit 1; }
leftovers=$(ls | grep -v -e '^shot' -e '^loaded' -e '^heat' -e '^photons.ph$' || true)
[ -z "$leftovers" ] || { echo "left behind: $leftovers"; exit 1; }
rm photons.ph
if run +Omissing.png Declare=File=2 > missing.log 2>&1; then
    echo "a missing map rendered"; exit 1
fi
grep -q "photons.pov:[0-9]*:[0-9]*: error: photon map file 'photons.ph': cannot be read" missing.log ||
    { cat missing.log; exit 1; }
[ ! -e missing.png ] || { echo "an image was written without its map"; exit 1; }
echo "photon files: saved, loaded (same image), missing map refused"
