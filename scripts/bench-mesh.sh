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

source "$(dirname "${BASH_SOURCE[0]}")/bench-common.sh"
bench_build mesh_bench
echo "embree: $(dpkg-query -W -f='${Version}' libembree-dev 2>/dev/null || echo unknown)"
"$build/bench/mesh_bench" "$@"
