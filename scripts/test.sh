#!/usr/bin/env bash
# Builds everything and runs the whole test suite three ways, stopping at the first failure:
#   1. Release build with g++, assertions on in every target: BUILD (default build/)
#   2. the core tests (the data structures, the shapes, the hard cases) under AddressSanitizer +
#      UndefinedBehaviorSanitizer, built with clang: BUILD-asan; with --sanitize-all, the whole
#      suite but the gallery, POV-Ray's checks, the install test and the [heavy] tests
#   3. the scene-language fuzzer for 60 s (clang, libFuzzer, the same sanitizers), beside 2:
#      BUILD-fuzz (fuzz/run.sh)
# Installs what it needs first. Usage: scripts/test.sh [--sanitize-all] [build-dir]
set -euo pipefail
cd "$(dirname "$0")/.."
sanitize_all=false
if [[ ${1:-} == --sanitize-all ]]; then sanitize_all=true; shift; fi
build=${1:-build}
jobs=$(nproc)
scripts/install-deps.sh test
# Wall seconds since the start, and the CPU seconds (user + system) of everything it ran: on a
# loaded machine the CPU time is the figure that compares between runs.
stamp() {
    local cpu times_file
    times_file=$(mktemp)
    times > "$times_file"  # in this shell: a subshell's `times` does not see this shell's children
    cpu=$(awk 'NR == 2 { split($1, u, /[ms]/); split($2, s, /[ms]/); printf "%.0f", u[1] * 60 + u[2] + s[1] * 60 + s[2] }' "$times_file")
    rm -f "$times_file"
    echo "test.sh: $* ($SECONDS s wall, $cpu CPU-s)"
}

cmake -S . -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release -DPHOTON_ASSERTS=ON -DPHOTON_MPI=ON  # MPI: the mpi: tests
cmake --build "$build" -j "$jobs"
ctest --test-dir "$build" --output-on-failure -j "$jobs"
stamp "release suite passed"

# 3. The fuzzer, started now in the background: its build is one unit and its run one process, so
# alone it would keep one core of two busy for about 150 s; beside the sanitizer build and suite,
# which fill both cores, it takes the time they leave. Its output goes to BUILD-fuzz.log, shown
# when it fails; its process group is stopped if this script stops first.
setsid bash -c 'CXX=clang++ cmake -S fuzz -B "$1-fuzz" -G Ninja && cmake --build "$1-fuzz" -j 1 &&
                fuzz/run.sh "$1-fuzz/parse_fuzzer" 60' fuzz "$build" >"$build-fuzz.log" 2>&1 &
fuzz_pid=$!
trap 'kill -- -"$fuzz_pid" 2>/dev/null || true' EXIT

# 2. -O1 keeps the instrumented build and run quick; -g1 (line tables) is enough for stack traces.
# clang, not g++: the instrumented build is the longest step of this script, and clang 14 compiles
# it in about half g++ 12's CPU time (test_dsl's unit: 109 against 231 CPU-s, 1.3 against 2.9 GB)
# with the same two sanitizers; the Release build above keeps g++, Debian's compiler.
# By default only the tests labelled `core` (tests/CMakeLists.txt says which and why): every
# program instrumented was about 1,900 of the command's 3,240 CPU-s (2026-12-04), which kept the
# command near 29 minutes on two cores. --sanitize-all runs the rest too (before changing the
# renderer's memory handling: the photon maps, the film, the irradiance cache, the CLI), leaving
# out POV-Ray's own checks and the install test (it builds a separate consumer project without
# the sanitizers), which run no instrumented photon code, the examples (demos), the scene-class
# gallery (minutes of rendering in Release; the same code paths as the unit tests), and the
# tests tagged [heavy] (statistical checks with many samples, 10-40 s each when instrumented,
# whose code paths lighter tests run).
if $sanitize_all; then
  targets=photon_test_programs; labels=(-LE "povray|install|gallery|heavy")
else
  targets=photon_core_test_programs; labels=(-L core)
fi
cmake -S . -B "$build-asan" -G Ninja -DCMAKE_CXX_COMPILER=clang++ -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -g1" \
    -DPHOTON_SANITIZE=ON -DPHOTON_BUILD_EXAMPLES=OFF
cmake --build "$build-asan" -j "$jobs" --target "$targets"  # what its ctest runs, no more
ASAN_OPTIONS=detect_leaks=1:abort_on_error=1:strict_string_checks=1:detect_stack_use_after_return=1 \
UBSAN_OPTIONS=print_stacktrace=1 \
    ctest --test-dir "$build-asan" --output-on-failure -j "$jobs" "${labels[@]}"
stamp "sanitizer suite passed"

if ! wait "$fuzz_pid"; then
  tail -80 "$build-fuzz.log"
  echo "test.sh: the fuzzing failed (log: $build-fuzz.log)"
  exit 1
fi
grep -E "DONE|number_of_executed_units" "$build-fuzz.log" || true
stamp "fuzzing passed"
