# SPDX-License-Identifier: MIT
# Sourced by the Google Benchmark scripts (bench-kdtree.sh, bench-mesh.sh).
# bench_build TARGET: configures the Release benchmark build in $PHOTON_BENCH_BUILD_DIR (default
# build-bench/ in the repository), builds TARGET, prints compiler, flags and CPU, and sets
# `build` to the build directory.
bench_build() {
  local root target=$1
  root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
  build="${PHOTON_BENCH_BUILD_DIR:-$root/build-bench}"
  "$root/scripts/install-deps.sh" bench
  local generator=()
  if command -v ninja >/dev/null 2>&1; then generator=(-G Ninja); fi
  if [ ! -f "$build/CMakeCache.txt" ]; then
    cmake -S "$root" -B "$build" "${generator[@]}" -DCMAKE_BUILD_TYPE=Release -DPHOTON_BUILD_BENCH=ON \
      -DPHOTON_BUILD_TESTS=OFF -DPHOTON_BUILD_EXAMPLES=OFF -DPHOTON_BUILD_CLI=OFF -DPHOTON_INSTALL=OFF >/dev/null
  else
    cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Release -DPHOTON_BUILD_BENCH=ON >/dev/null
  fi
  cmake --build "$build" --target "$target"

  local flags compiler
  flags="$(sed -n 's/^CMAKE_CXX_FLAGS_RELEASE:[A-Z]*=//p' "$build/CMakeCache.txt")"
  compiler="$(sed -n 's/^CMAKE_CXX_COMPILER:[A-Z]*=//p' "$build/CMakeCache.txt")"
  echo "compiler: $("$compiler" --version | head -n 1), flags: -std=c++20 $flags"
  if command -v lscpu >/dev/null 2>&1; then
    echo "cpu: $(lscpu | sed -n 's/^Model name: *//p'), $(nproc) logical cores; the benchmark is single-threaded"
  fi
}
