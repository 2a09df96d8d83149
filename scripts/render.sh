#!/usr/bin/env bash
# Installs what rendering needs, builds the photon program and renders a scene (default: the
# paper's Cornell box) to an image. Usage: scripts/render.sh [scene.pov [image.png [photon options...]]]
set -euo pipefail
cd "$(dirname "$0")/.."
scene=${1:-examples/scenes/cornell.pov}
image=${2:-cornell.png}
shift $(( $# < 2 ? $# : 2 ))
scripts/install-deps.sh render
cmake -S . -B build-render -G Ninja -DCMAKE_BUILD_TYPE=Release -DPHOTON_BUILD_TESTS=OFF -DPHOTON_BUILD_EXAMPLES=OFF >/dev/null
cmake --build build-render --target photon_cli
build-render/photon render "$scene" -o "$image" "$@"
