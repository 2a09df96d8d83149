#!/usr/bin/env bash
# Renders the paper's four scenes with ray tracing (rt) and photon mapping (pm) at 800x600 and
# writes the side-by-side pictures of docs/gallery.md to docs/images/ (JPEG, to keep the repository
# light), plus each render's statistics to docs/images/<scene>-<mode>.txt.
# Usage: scripts/render-gallery.sh [build-dir]
set -euo pipefail
cd "$(dirname "$0")/.."
build=${1:-build-render}
scripts/install-deps.sh render
cmake -S . -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build "$build" --target photon_cli
out=docs/images
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
mkdir -p "$out"
for scene in cornell recursive room1 room2; do
  for mode in rt pm; do
    echo "== $scene $mode"
    # Keep the statistics table and the wall time, drop the progress lines.
    /usr/bin/time -f "  wall time                   %e s" "$build/photon" render "examples/scenes/$scene.pov" \
      --mode "$mode" -o "$tmp/$scene-$mode.png" 2>&1 | grep -v '^photon:' | tee "$out/$scene-$mode.txt"
  done
  oiiotool "$tmp/$scene-rt.png" "$tmp/$scene-pm.png" --mosaic 2x1 --compression jpeg:90 \
    -o "$out/$scene-rt-pm.jpg"
done
