#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Compile time of photon's headers, as a user and a developer meet it: the CPU seconds (user + sys)
# and peak memory of one translation unit each, compiled with the project's own flags (taken from
# compile_commands.json of a Release build in $PHOTON_COMPILE_BUILD_DIR, default build-compile/):
#   - the umbrella header alone (#include <photon/photon.hpp>, nothing used),
#   - examples/cornell.cpp (one render() call on a hand-built scene), twice: header-only (target
#     cornell_header_only) and linking the optional compiled unit photon::compiled (target cornell),
#     which makes the render functions of DefaultScene<float> `extern template`,
#   - the CLI: each of its units (dsl/cli/*.cpp, which compile in parallel) and their sum,
#   - the compiled units of the render instantiations and the scene language (src/*.cpp,
#     dsl/src/*.cpp),
#   - one scene-language test file (tests/dsl/scenes_test.cpp), with its test executable's flags
#     (the tests compile as unity files, so a test file has no entry of its own).
# Each unit is compiled --repeat times (default 1) and the fastest run kept. With --full it also
# builds every target from scratch with -j$(nproc) and reports the wall and summed job time.
# Usage: scripts/bench-compile.sh [--repeat N] [--full]
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
build="${PHOTON_COMPILE_BUILD_DIR:-$root/build-compile}"
repeat=1
full=0
while [ $# -gt 0 ]; do
  case "$1" in
    --repeat) repeat=$2; shift 2 ;;
    --full) full=1; shift ;;
    *) echo "usage: $0 [--repeat N] [--full]" >&2; exit 2 ;;
  esac
done

"$root/scripts/install-deps.sh" test >/dev/null
cmake -S "$root" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release -DCMAKE_EXPORT_COMPILE_COMMANDS=ON >/dev/null
tmp="$(mktemp -d)"
trap 'rm -rf "$tmp"' EXIT
printf '#include <photon/photon.hpp>\nint main() { return 0; }\n' >"$tmp/umbrella.cpp"

# command_for SOURCE [AS] [TARGET_DIR]: the compile command of SOURCE from compile_commands.json (of
# the target whose objects go to TARGET_DIR when given), compiling AS instead when given (the
# umbrella header borrows the flags of examples/cornell.cpp), to $tmp/out.o.
# A source compiled inside a unity file takes the flags of the unity file of its own directory.
command_for() {
  /usr/bin/env python3 - "$build/compile_commands.json" "$1" "${2:-$1}" "$tmp/out.o" "$root" "$build" "${3:-}" <<'EOF'
import json, os, shlex, sys
db, source, compiled, out, root, build, target = sys.argv[1:]
entries = json.load(open(db))
matches = [e for e in entries if e["file"] == source and
           (not target or "/" + target + "/" in e.get("output", e["command"]))]
if not matches:  # <build>/tests/dsl/CMakeFiles/test_dsl.dir/Unity/unity_0_cxx.cxx for <root>/tests/dsl/x.cpp
    folder = os.path.relpath(os.path.dirname(source), root)
    matches = [e for e in entries if "/Unity/" in e["file"] and
               os.path.relpath(e["file"], build).split("/CMakeFiles/")[0] == folder]
if not matches:
    sys.exit("no compile command for " + source)
args = shlex.split(matches[0]["command"])
args = [a for a in args if a not in ("-MD",)]
i = 0; kept = []
while i < len(args):  # drop -o X, -MT X, -MF X and the source
    if args[i] in ("-o", "-MT", "-MF"): i += 2; continue
    if args[i] == "-c": i += 2; continue
    kept.append(args[i]); i += 1
print(matches[0]["directory"]); print(shlex.join(kept + ["-c", compiled, "-o", out]))
EOF
}

# sources_of TARGET_DIR: the sources compiled into the target whose objects go to TARGET_DIR
# (e.g. photon_cli.dir), in the order of compile_commands.json.
sources_of() {
  /usr/bin/env python3 - "$build/compile_commands.json" "$1" <<'EOF'
import json, sys
db, target = sys.argv[1:]
for e in json.load(open(db)):
    if "/" + target + "/" in e.get("output", e["command"]): print(e["file"])
EOF
}

# measure LABEL SOURCE [AS] [TARGET_DIR]: one table row, the fastest of $repeat runs; sets cpu_s
# and peak_mb.
measure() {
  local label=$1 source=$2 as=${3:-$2} target=${4:-} lines=() dir cmd best="" mem=""
  cpu_s=0 peak_mb=0
  [ -f "$source" ] || return 0
  mapfile -t lines < <(command_for "$source" "$as" "$target")
  if [ ${#lines[@]} -ne 2 ]; then echo "bench-compile: no compile command for $source" >&2; exit 1; fi
  dir=${lines[0]} cmd=${lines[1]}
  for _ in $(seq "$repeat"); do
    if ! (cd "$dir" && /usr/bin/time -f "%U %S %M" -o "$tmp/time" bash -c "$cmd" 2>"$tmp/log"); then
      cat "$tmp/log" >&2; echo "bench-compile: $label does not compile" >&2; exit 1
    fi
    read -r user sys kb <"$tmp/time"
    local cpu
    cpu=$(awk -v u="$user" -v s="$sys" 'BEGIN { printf "%.1f", u + s }')
    if [ -z "$best" ] || awk -v a="$cpu" -v b="$best" 'BEGIN { exit !(a < b) }'; then best=$cpu mem=$((kb / 1024)); fi
  done
  cpu_s=$best peak_mb=$mem
  printf '| %s | %s | %s |\n' "$label" "$best" "$mem"
}

compiler="$(sed -n 's/^CMAKE_CXX_COMPILER:[A-Z]*=//p' "$build/CMakeCache.txt")"
flags="$(sed -n 's/^CMAKE_CXX_FLAGS_RELEASE:[A-Z]*=//p' "$build/CMakeCache.txt")"
echo "compiler: $("$compiler" --version | head -n 1), flags: -std=c++20 $flags"
echo "cpu: $(lscpu | sed -n 's/^Model name: *//p'), $(nproc) logical cores; load average $(cut -d' ' -f1-3 /proc/loadavg)"
echo
echo "| translation unit | CPU s | peak MB |"
echo "|---|---:|---:|"
measure "umbrella header alone" "$root/examples/cornell.cpp" "$tmp/umbrella.cpp" cornell_header_only.dir
measure "examples/cornell.cpp, header-only" "$root/examples/cornell.cpp" "" cornell_header_only.dir
measure "examples/cornell.cpp, with photon::compiled" "$root/examples/cornell.cpp" "" cornell.dir
mapfile -t cli_units < <(sources_of photon_cli.dir)
cli_total=0 cli_peak=0
for unit in "${cli_units[@]}"; do
  measure "CLI unit ${unit#"$root"/}" "$unit"
  cli_total=$(awk -v a="$cli_total" -v b="$cpu_s" 'BEGIN { printf "%.1f", a + b }')
  [ "$peak_mb" -gt "$cli_peak" ] && cli_peak=$peak_mb
done
if [ ${#cli_units[@]} -gt 1 ]; then
  printf '| CLI, its %d units together | %s | %s |\n' "${#cli_units[@]}" "$cli_total" "$cli_peak"
fi
for unit in "$root"/src/*.cpp "$root"/dsl/src/*.cpp; do
  [ -f "$unit" ] && measure "compiled unit ${unit#"$root"/}" "$unit"
done
measure "one test file (tests/dsl/scenes_test.cpp)" "$root/tests/dsl/scenes_test.cpp"

if [ "$full" = 1 ]; then
  cmake --build "$build" --target clean >/dev/null
  start=$SECONDS
  cmake --build "$build" -j "$(nproc)" >/dev/null
  wall=$((SECONDS - start))
  jobs=$(awk 'NR > 1 { t[$4] = $2 - $1 } END { for (k in t) s += t[k]; printf "%.0f", s / 1000 }' "$build/.ninja_log")
  echo
  echo "full build of every target: ${wall} s wall with -j$(nproc), ${jobs} s summed over the jobs"
fi
