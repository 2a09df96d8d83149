#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Render benchmark: the paper's Cornell box at the paper's settings and at photon's own fast
# settings, 1 and 2 threads, with and without precomputed irradiance, and POV-Ray's radiosity
# render of the same scene file in the same run. Prints a Markdown table (bench/README.md keeps
# the last one) and leaves every image and statistics file in the output directory.
#
#   scripts/bench-render.sh                # 800x600, as the paper (about 3 minutes on 2 cores)
#   scripts/bench-render.sh --size 400x300 # quicker, for a trial
#
# Environment: PHOTON_RENDER_BENCH_BUILD_DIR (default build-render-bench/), POVRAY_MODE (the
# examples/scenes/povray/<mode>.inc POV-Ray runs with, default radphot_hq as the comparison).
set -euo pipefail

root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
size=800x600
while [ $# -gt 0 ]; do
  case "$1" in
    --size) size="$2"; shift 2 ;;
    -h|--help) sed -n '3,12p' "$0"; exit 0 ;;
    *) echo "bench-render: unknown argument '$1' (try --help)" >&2; exit 2 ;;
  esac
done
width=${size%x*}
height=${size#*x}
povray_mode=${POVRAY_MODE:-radphot_hq}

source "$root/scripts/bench-common.sh"
render_bench_build
scene="$root/examples/scenes/cornell.pov"
out="$build/render-bench"
mkdir -p "$out"
echo "POV-Ray: $(povray --version 2>&1 | sed -n 's/^POV-Ray \(Unix \)\{0,1\}\([0-9][^ ]*\).*/\2/p' | head -n 1)," \
  "examples/scenes/povray/$povray_mode.inc"
echo

now() { date +%s.%N; }
# Fields of a statistics file written by `photon render`, e.g. field "time" "render".
stat_seconds() { sed -n "s/.*$2 \([0-9.]*\) s.*/\1/p" "$1" | head -n 1; }
stat_line() { grep -m1 "^  $2 " "$1"; }

rows=()
# run NAME DESCRIPTION PAPER_SECONDS photon-options...
run() {
  local name="$1" what="$2" paper="$3"
  shift 3
  local stats="$out/$name.txt" t0 t1
  t0=$(now)
  # --no-error-estimate: the render alone, as the paper timed it (pm's short sppm run, which
  # estimates its error, would add up to half its time again; other modes ignore the flag).
  "$photon" render "$scene" -o "$out/$name.exr" --width "$width" --height "$height" --no-error-estimate "$@" 2>"$stats.log" >"$stats" ||
    { cat "$stats.log" >&2; exit 1; }
  t1=$(now)
  cat "$stats.log" >>"$stats"
  local wall trace_g trace_c build_g build_c emitted_g emitted_c pre cache render rays
  wall=$(echo "$t1 - $t0" | bc -l)
  trace_g=$(stat_line "$stats" "global map" | sed -n 's/.*trace \([0-9.]*\) s.*/\1/p')
  build_g=$(stat_line "$stats" "global map" | sed -n 's/.*build \([0-9.]*\) s.*/\1/p')
  trace_c=$(stat_line "$stats" "caustic map" | sed -n 's/.*trace \([0-9.]*\) s.*/\1/p')
  build_c=$(stat_line "$stats" "caustic map" | sed -n 's/.*build \([0-9.]*\) s.*/\1/p')
  emitted_g=$(stat_line "$stats" "global map" | sed -n 's/.* \([0-9]*\) emitted.*/\1/p')
  emitted_c=$(stat_line "$stats" "caustic map" | sed -n 's/.* \([0-9]*\) emitted.*/\1/p')
  pre=$(stat_seconds "$stats" precompute)
  cache=$(stat_seconds "$stats" cache)
  render=$(stat_seconds "$stats" render)
  rays=$(stat_line "$stats" "rays (pass 2)" | sed -n 's/.*) *\([0-9]*\) total.*/\1/p')
  local trace build photons_per_s rays_per_s pass2 ratio
  trace=$(echo "${trace_g:-0} + ${trace_c:-0}" | bc -l)
  build=$(echo "${build_g:-0} + ${build_c:-0}" | bc -l)
  photons_per_s=$(echo "${emitted_g:-0} + ${emitted_c:-0}" | bc -l)
  photons_per_s=$( [ "$(echo "$trace > 0" | bc)" = 1 ] && printf '%.2f M' "$(echo "$photons_per_s / $trace / 1000000" | bc -l)" || echo "-")
  pass2=$(echo "${pre:-0} + ${cache:-0} + ${render:-0}" | bc -l)
  rays_per_s=$(printf '%.1f M' "$(echo "${rays:-0} / $pass2 / 1000000" | bc -l)")
  ratio=$( [ "$paper" != "-" ] && printf '%.1fx' "$(echo "$paper / $wall" | bc -l)" || echo "-")
  rows+=("| $what | $(printf '%.2f' "$wall") s | $(printf '%.2f' "$trace") s | $(printf '%.2f' "$build") s | $(printf '%.2f' "${pre:-0}") s | $(printf '%.2f' "${cache:-0}") s | $(printf '%.2f' "${render:-0}") s | $photons_per_s | $(printf '%.1f M' "$(echo "${rays:-0} / 1000000" | bc -l)") | $rays_per_s | $paper | $ratio |")
  echo "$name: $(printf '%.2f' "$wall") s" >&2
  eval "wall_$name=$wall"
}

paper=(--mode pm --global-photons 250000 --caustic-photons 0 --global-k 2000 --shadow-samples 400 --spp 1
       --final-gather 0 --ray-depth 4 --photon-depth 10)
run paper "paper's settings: pm, 250k photons, k 2000, 400 shadow samples, 1 spp" 156.257 "${paper[@]}" --threads 2
run paper_1t "the same, 1 thread" - "${paper[@]}" --threads 1
run rt_ss "rt, 400 shadow samples, 1 spp (paper's Table 1 'SS')" 39.308 --mode rt --shadow-samples 400 --spp 1 --threads 2
run fast "fast: pm as cornell.pov (final gather 256, cache, precomputed irradiance, 16 stratified shadow samples, 4 spp)" - --threads 2
run fast_1t "the same, 1 thread" - --threads 1
run fast_noprecompute "fast without precomputed irradiance (a density estimate per gather ray)" - --threads 2 --irradiance-stride 0

# POV-Ray: the same scene file, radiosity and caustic photons, all cores.
t0=$(now)
povray -D +W"$width" +H"$height" +A0.3 +AM2 +R3 +WT2 +HI"$root/examples/scenes/povray/$povray_mode.inc" +FE \
  +O"$out/povray.exr" "$scene" >"$out/povray.log" 2>&1 || { tail -n 20 "$out/povray.log" >&2; exit 1; }
t1=$(now)
wall_povray=$(echo "$t1 - $t0" | bc -l)
echo "povray: $(printf '%.2f' "$wall_povray") s" >&2

echo
echo "| setting | wall | photon tracing | map build | precompute | cache | render | photons/s | rays (pass 2) | rays/s (pass 2) | paper | speed-up vs paper |"
echo "|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|"
printf '%s\n' "${rows[@]}"
echo "| POV-Ray 3.7 $povray_mode (radiosity + photons), 2 threads | $(printf '%.2f' "$wall_povray") s | | | | | | | | | | |"
echo
printf 'thread scaling 1 -> 2: paper settings %.2fx, fast %.2fx\n' \
  "$(echo "$wall_paper_1t / $wall_paper" | bc -l)" "$(echo "$wall_fast_1t / $wall_fast" | bc -l)"
printf 'precomputed irradiance: fast render %.2fx faster than without\n' "$(echo "$wall_fast_noprecompute / $wall_fast" | bc -l)"
printf 'POV-Ray / photon wall time: fast setting %.2fx, paper settings %.2fx\n' \
  "$(echo "$wall_povray / $wall_fast" | bc -l)" "$(echo "$wall_povray / $wall_paper" | bc -l)"
echo "images and statistics: $out"
