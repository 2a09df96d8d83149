# SPDX-License-Identifier: MIT
# Sourced by the benchmark scripts: bench_build by the Google Benchmark ones (bench-kdtree.sh,
# bench-mesh.sh), render_bench_build by the ones that time the CLI (bench-render.sh,
# bench-scene-rays.sh).
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

# render_bench_build: configures the Release CLI build in $PHOTON_RENDER_BENCH_BUILD_DIR (default
# build-render-bench/ in the repository), builds `photon`, prints the machine and photon's
# compiler and flags, and sets `build` and `photon`.
render_bench_build() {
  local root
  root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
  "$root/scripts/install-deps.sh" bench
  build="${PHOTON_RENDER_BENCH_BUILD_DIR:-$root/build-render-bench}"
  cmake -S "$root" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release -DPHOTON_BUILD_TESTS=OFF \
    -DPHOTON_BUILD_EXAMPLES=OFF -DPHOTON_BUILD_BENCH=OFF -DPHOTON_INSTALL=OFF >/dev/null
  cmake --build "$build" --target photon_cli >/dev/null
  photon="$build/photon"
  echo "machine: $(lscpu | sed -n 's/^Model name: *//p'), $(nproc) logical cores; load average $(cut -d' ' -f1-3 /proc/loadavg)"
  echo "photon: $(git -C "$root" rev-parse --short HEAD 2>/dev/null || echo unknown commit)," \
    "$("$(sed -n 's/^CMAKE_CXX_COMPILER:[A-Z]*=//p' "$build/CMakeCache.txt")" --version | head -n 1)," \
    "flags -std=c++20 $(sed -n 's/^CMAKE_CXX_FLAGS_RELEASE:[A-Z]*=//p' "$build/CMakeCache.txt")"
}
