#!/usr/bin/env bash
# Usage: tools/tsan-check.sh LUMEN_TSAN_BINARY
# Renders multithreaded (+WT2) scenes with a ThreadSanitizer build of lumen (`make tsan`
# builds one) and fails if TSan reports anything: the examples with anti-aliasing (text.pov
# opens FreeType on first use), an animation, the teapot (meshes traced through Embree, also
# opened on first use), cornell.pov with both radiosity displays (the irradiance cache is
# shared by the render threads), radiosity through CSG and media photons. Small sizes: TSan
# runs 5-15x slower.
set -uo pipefail
lumen=$(realpath "${1:?usage: tools/tsan-check.sh LUMEN_TSAN_BINARY}")
root=$(cd "$(dirname "$0")/.." && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
export TSAN_OPTIONS="halt_on_error=0 exitcode=66"
status=0
check() {  # name, lumen arguments...
    local name=$1; shift
    (cd "$work" && timeout 900 "$lumen" "$@" +WT2 "+O$work/$name.png") >"$work/$name.log" 2>&1
    local rc=$? reports
    reports=$(grep -c 'WARNING: ThreadSanitizer' "$work/$name.log")
    printf '%-22s exit %3d  tsan reports %d\n' "$name" "$rc" "$reports"
    if [ "$rc" -ne 0 ] || [ "$reports" -ne 0 ]; then
        status=1
        grep -A30 'WARNING: ThreadSanitizer' "$work/$name.log" | head -60
    fi
}
for scene in showcase glass lights csg patterns antialias irid isosurface media image_map caustics text; do
    check "$scene" "$root/examples/$scene.pov" +W96 +H72 +A0.3
done
check animation "$root/examples/animation.pov" +W48 +H36 +KFI1 +KFF3
check focal-blur "$root/tests/cameras/focal_blur.pov" +W48 +H36 +A0.3 Declare=S=60
# Bicubic patches tessellated into meshes big enough for Embree (render/shapes/mesh_embree.hpp).
check teapot /usr/share/povray-3.7/scenes/advanced/teapot/teapot.pov +W96 +H72 +A0.3
cornell=/usr/share/povray-3.7/scenes/radiosity/cornell.pov
check cornell-preview "$cornell" +W60 +H60 -A Radiosity_Display=preview
check cornell-gather "$cornell" +W60 +H60 -A Radiosity_Display=gather
# CSG the mesher does not cut: vertex gathers that gather again through their worker's caches.
check radiosity-csg /usr/share/povray-3.7/scenes/radiosity/radiosity_37.pov +W48 +H36 -A
# Media photons: shot on every thread, gathered by every media sample.
check media-photons "$root/tests/photons/media_photons.pov" +W48 +H36 -A
exit $status
