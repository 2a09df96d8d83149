#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Builds the mesh benchmark in Release (-DPHOTON_BUILD_BENCH=ON) and runs it: photon::TriangleMesh
# against Embree 3 on a 1M-triangle mesh, single-threaded, one ray at a time, ending with the
# Markdown tables of bench/README.md.
#
#   scripts/bench-mesh.sh                      # full run, about a minute
#   scripts/bench-mesh.sh --quick              # a 100k-triangle mesh
#   scripts/bench-mesh.sh --benchmark_filter='trace/random/.*'   # any Google Benchmark flag
#
# The build directory is $PHOTON_BENCH_BUILD_DIR, default build-bench/ in the repository.
set -euo pipefail

root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${PHOTON_BENCH_BUILD_DIR:-$root/build-bench}"
generator=()
if command -v ninja >/dev/null 2>&1; then generator=(-G Ninja); fi

if [ ! -f "$build/CMakeCache.txt" ]; then
  cmake -S "$root" -B "$build" "${generator[@]}" -DCMAKE_BUILD_TYPE=Release -DPHOTON_BUILD_BENCH=ON \
    -DPHOTON_BUILD_TESTS=OFF -DPHOTON_BUILD_EXAMPLES=OFF -DPHOTON_BUILD_CLI=OFF -DPHOTON_INSTALL=OFF >/dev/null
else
  cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Release -DPHOTON_BUILD_BENCH=ON >/dev/null
fi
cmake --build "$build" --target mesh_bench

flags="$(sed -n 's/^CMAKE_CXX_FLAGS_RELEASE:[A-Z]*=//p' "$build/CMakeCache.txt")"
compiler="$(sed -n 's/^CMAKE_CXX_COMPILER:[A-Z]*=//p' "$build/CMakeCache.txt")"
echo "compiler: $("$compiler" --version | head -n 1), flags: -std=c++20 $flags"
if command -v lscpu >/dev/null 2>&1; then
  echo "cpu: $(lscpu | sed -n 's/^Model name: *//p'), $(nproc) logical cores; the benchmark is single-threaded"
fi
echo "embree: $(dpkg-query -W -f='${Version}' libembree-dev 2>/dev/null || echo unknown)"
"$build/bench/mesh_bench" "$@"
