#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Builds the kd-tree benchmark in Release (-DPHOTON_BUILD_BENCH=ON) and runs it: photon::KdTree
# against nanoflann, single-threaded, ending with the Markdown ratio tables of bench/README.md.
#
#   scripts/bench-kdtree.sh                   # full run, N up to 4M (a few minutes)
#   scripts/bench-kdtree.sh --quick           # N up to 1M
#   scripts/bench-kdtree.sh --benchmark_filter='query/cornell/1000000/.*'   # any Google Benchmark flag
#
# The build directory is $PHOTON_BENCH_BUILD_DIR, default build-bench/ in the repository.
set -euo pipefail

source "$(dirname "${BASH_SOURCE[0]}")/bench-common.sh"
bench_build kdtree_bench
"$build/bench/kdtree_bench" "$@"
