#!/usr/bin/env bash
# Installs the Debian packages lumen needs to build, test and fuzz, but only the missing ones:
# silent (and no apt-get update) when everything is already there.
set -euo pipefail

packages=(
    tao-pegtl-dev libglm-dev libpng-dev libjpeg-dev libopenimageio-dev openimageio-tools libgtest-dev
    libfreetype-dev  # text: TrueType fonts
    libembree-dev  # big meshes trace through Embree's BVH (render/shapes/mesh_embree.hpp)
    cmake g++ make pkg-config
    povray povray-includes povray-examples
    clang libclang-rt-14-dev
    bc  # bench/render_vs_povray.sh arithmetic
    python3  # tools/corpus, tools/compare-builds
    slurm-wlm munge  # lumen farm --slurm and its test cluster (tools/slurm-local-cluster)
)
# Optional: `--bench` adds what the benchmarks need: gnuplot for the charts (make
# bench-radiosity, bench/parse_scale.sh).
if [ "${1:-}" = "--bench" ]; then packages+=(gnuplot-nox); fi

missing=()
for p in "${packages[@]}"; do
    if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
        missing+=("$p")
    fi
done
[ ${#missing[@]} -eq 0 ] && exit 0

sudo=()
[ "$(id -u)" -ne 0 ] && sudo=(sudo)
echo "install-deps: installing ${missing[*]}" >&2
export DEBIAN_FRONTEND=noninteractive
"${sudo[@]}" apt-get update -qq
"${sudo[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}"
