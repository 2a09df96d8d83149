#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Rays per CPU second on the paper's Cornell box (examples/scenes/cornell.pov): photon's ray tracer
# (`--mode rt`) against POV-Ray 3.7's (examples/scenes/povray/rt.inc: no radiosity, no photons) in
# the same run, both on 1 thread, 1 camera ray per pixel (no anti-aliasing), max_trace_level 4 from
# the scene file, 81 shadow samples per shading point on both (photon --shadow-samples 81, 9 x 9
# strata of the sphere light; POV-Ray's 9 x 9 area_light of the scene file), at two image sizes so
# that the per-ray cost can be told from parsing and set-up (difference quotient between sizes).
# Prints a Markdown table (bench/README.md keeps the last one) and leaves every image, log and
# statistics file in the output directory.
#
#   scripts/bench-scene-rays.sh                          # 400x300 and 800x600, about a minute
#   scripts/bench-scene-rays.sh --sizes 200x150,400x300  # quicker, for a trial
#   scripts/bench-scene-rays.sh --shadow-samples 16      # photon's own default instead of 81
#
# Environment: PHOTON_RENDER_BENCH_BUILD_DIR (default build-render-bench/, as bench-render.sh).
set -euo pipefail

root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
sizes=400x300,800x600
shadow_samples=81
while [ $# -gt 0 ]; do
  case "$1" in
    --sizes) sizes="$2"; shift 2 ;;
    --shadow-samples) shadow_samples="$2"; shift 2 ;;
    -h|--help) sed -n '3,17p' "$0"; exit 0 ;;
    *) echo "bench-scene-rays: unknown argument '$1' (try --help)" >&2; exit 2 ;;
  esac
done
IFS=, read -r -a size_list <<<"$sizes"

"$root/scripts/install-deps.sh" bench
build="${PHOTON_RENDER_BENCH_BUILD_DIR:-$root/build-render-bench}"
cmake -S "$root" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release -DPHOTON_BUILD_TESTS=OFF \
  -DPHOTON_BUILD_EXAMPLES=OFF -DPHOTON_BUILD_BENCH=OFF -DPHOTON_INSTALL=OFF >/dev/null
cmake --build "$build" --target photon_cli >/dev/null
photon="$build/photon"
scene="$root/examples/scenes/cornell.pov"
out="$build/scene-rays-bench"
mkdir -p "$out"

echo "date: $(date -u '+%Y-%m-%d %H:%M UTC')"
echo "machine: $(lscpu | sed -n 's/^Model name: *//p'), $(nproc) logical cores; load average $(cut -d' ' -f1-3 /proc/loadavg)"
echo "photon: $(git -C "$root" rev-parse --short HEAD), $("$(sed -n 's/^CMAKE_CXX_COMPILER:[A-Z]*=//p' "$build/CMakeCache.txt")" --version | head -n 1)," \
  "flags -std=c++20 $(sed -n 's/^CMAKE_CXX_FLAGS_RELEASE:[A-Z]*=//p' "$build/CMakeCache.txt")"
echo "POV-Ray: $(povray --version 2>&1 | sed -n 's/^POV-Ray \(Unix \)\{0,1\}\([0-9][^ ]*\).*/\2/p' | head -n 1)"
echo

# timed LOG COMMAND...: runs COMMAND under /usr/bin/time, its stdout and stderr into LOG; prints
# "user sys wall" seconds of the whole command (children included).
timed() {
  local log="$1" t="$1.time"
  shift
  /usr/bin/time -o "$t" -f '%U %S %e' "$@" >"$log" 2>&1 || { tail -n 20 "$log" >&2; exit 1; }
  tail -n 1 "$t"
}
num() { awk "BEGIN { printf \"$1\", $2 }"; }

rows=()
declare -A rays cpu
for size in "${size_list[@]}"; do
  w=${size%x*} h=${size#*x}

  # photon: ray tracing only (direct light by shadow rays, mirror and glass), 1 spp, 1 thread.
  log="$out/photon-$size.log"
  read -r user sys wall < <(timed "$log" "$photon" render "$scene" -o "$out/photon-$size.exr" --mode rt \
    --width "$w" --height "$h" --spp 1 --shadow-samples "$shadow_samples" --threads 1)
  line1=$(grep -m1 '^  rays (pass 2) ' "$log")
  line2=$(grep -A1 -m1 '^  rays (pass 2) ' "$log" | tail -n 1)
  total=$(sed -n 's/.* \([0-9]*\) total:.*/\1/p' <<<"$line1")
  camera=$(sed -n 's/.*camera \([0-9]*\),.*/\1/p' <<<"$line1")
  shadow=$(sed -n 's/.*shadow \([0-9]*\),.*/\1/p' <<<"$line1")
  refl=$(sed -n 's/.*reflection \([0-9]*\),.*/\1/p' <<<"$line1")
  refr=$(sed -n 's/.*refraction \([0-9]*\),.*/\1/p' <<<"$line2")
  render=$(sed -n 's/.*render \([0-9.]*\) s, total.*/\1/p' "$log" | head -n 1)
  c=$(num %.2f "$user + $sys")
  rays[photon,$size]=$total cpu[photon,$size]=$c
  rows+=("| photon rt | $size | $total | $camera + $shadow + $(num %d "$refl + $refr") | $c | $render | $(num %.2f "$total / $c / 1e6") M |")
  echo "photon $size: $total rays, $c CPU-s (wall $wall s)" >&2

  # POV-Ray: the same scene file, rt.inc (no radiosity, no photons), no anti-aliasing, 1 thread.
  log="$out/povray-$size.log"
  read -r user sys wall < <(timed "$log" povray -D +W"$w" +H"$h" -A +WT1 +HI"$root/examples/scenes/povray/rt.inc" +FE \
    +O"$out/povray-$size.exr" "$scene")
  prays=$(sed -n 's/^Rays: *\([0-9]*\).*/\1/p' "$log")
  ptests=$(sed -n 's/^Shadow Ray Tests: *\([0-9]*\).*/\1/p' "$log")
  phits=$(sed -n 's/^Shadow Cache Hits: *\([0-9]*\).*/\1/p' "$log")
  preflected=$(sed -n 's/^Reflected Rays: *\([0-9]*\).*/\1/p' "$log")
  prefracted=$(sed -n 's/^Refracted Rays: *\([0-9]*\).*/\1/p' "$log")
  ptrace=$(sed -n 's/.*(\([0-9.]*\) seconds).*/\1/p' <<<"$(grep -A0 'Trace Time:' "$log")")
  ptotal=$(num %d "$prays + $ptests")
  c=$(num %.2f "$user + $sys")
  rays[povray,$size]=$ptotal cpu[povray,$size]=$c
  rows+=("| POV-Ray rt.inc | $size | $ptotal | $(num %d "$prays - ${preflected:-0} - ${prefracted:-0}") + $ptests ($phits cache hits) + $(num %d "${preflected:-0} + ${prefracted:-0}") | $c | $ptrace | $(num %.2f "$ptotal / $c / 1e6") M |")
  echo "povray $size: $ptotal rays, $c CPU-s (wall $wall s)" >&2
done

echo "| program | size | rays | camera + shadow + reflection/refraction | CPU-s (whole command) | render/trace wall s (own statistics) | rays per CPU-s |"
echo "|---|---|---:|---:|---:|---:|---:|"
printf '%s\n' "${rows[@]}"
echo
for size in "${size_list[@]}"; do
  printf 'photon / POV-Ray rays per CPU-s at %s: %.2f\n' "$size" \
    "$(num %.6f "(${rays[photon,$size]} / ${cpu[photon,$size]}) / (${rays[povray,$size]} / ${cpu[povray,$size]})")"
done
if [ ${#size_list[@]} -ge 2 ]; then
  a=${size_list[0]} b=${size_list[-1]}
  for p in photon povray; do
    dr=$(num %d "${rays[$p,$b]} - ${rays[$p,$a]}")
    dc=$(num %.6f "${cpu[$p,$b]} - ${cpu[$p,$a]}")
    q=$(num %.6f "$dr / $dc")
    eval "q_$p=$q"
    fixed=$(num %.3f "${cpu[$p,$a]} - ${rays[$p,$a]} / $q")
    printf '%s, %s to %s: %d more rays in %.2f more CPU-s: %.2f M rays per CPU-s per added ray; fixed cost (CPU-s at 0 rays) %s\n' \
      "$p" "$a" "$b" "$dr" "$dc" "$(num %.6f "$q / 1e6")" "$fixed"
  done
  printf 'photon / POV-Ray, difference quotient: %.2f\n' "$(num %.6f "$q_photon / $q_povray")"
fi
echo "images, logs and statistics: $out"
