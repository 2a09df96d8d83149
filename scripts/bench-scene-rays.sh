#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Rays per CPU second on the paper's Cornell box (examples/scenes/cornell.pov): photon's ray tracer
# (`--mode rt`) against POV-Ray 3.7's (examples/scenes/povray/rt.inc: no radiosity, no photons) in
# the same run, both on 1 thread, 1 camera ray per pixel (no anti-aliasing), max_trace_level 4 from
# the scene file, 81 shadow samples per shading point on both (photon --shadow-samples 81, 9 x 9
# strata of the sphere light; POV-Ray's 9 x 9 area_light of the scene file), and again with the
# area light made a point light (one shadow ray per point, each through the whole scene's bounding
# hierarchy: the scene-level BVH's own test), at two image sizes so that the per-ray cost can be
# told from parsing and set-up (difference quotient between the sizes).
# Both write an 8-bit binary PPM, the cheapest image either writes (an EXR's zip compression cost
# photon a fifth of a 1600x1200 point-light run), so that the whole command is mostly tracing.
# Prints a Markdown table (bench/README.md keeps the last runs' summary) and leaves every image, log and
# statistics file in the output directory.
#
#   scripts/bench-scene-rays.sh                          # 800x600 and 1600x1200, 70 to 90 s
#   scripts/bench-scene-rays.sh --sizes 200x150,400x300  # quicker, for a trial
#   scripts/bench-scene-rays.sh --shadow-samples 16      # photon's own default instead of 81
#   scripts/bench-scene-rays.sh --lights area            # the scene's area light only (or point)
#
# Environment: PHOTON_RENDER_BENCH_BUILD_DIR (default build-render-bench/, as bench-render.sh).
set -euo pipefail

root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
sizes=800x600,1600x1200
shadow_samples=81
lights="area point"
while [ $# -gt 0 ]; do
  case "$1" in
    --sizes) sizes="$2"; shift 2 ;;
    --shadow-samples) shadow_samples="$2"; shift 2 ;;
    --lights) lights="${2//,/ }"; shift 2 ;;
    -h|--help) sed -n '3,20p' "$0"; exit 0 ;;
    *) echo "bench-scene-rays: unknown argument '$1' (try --help)" >&2; exit 2 ;;
  esac
done
IFS=, read -r -a size_list <<<"$sizes"

source "$root/scripts/bench-common.sh"
echo "date: $(date -u '+%Y-%m-%d %H:%M UTC')"
render_bench_build
scene="$root/examples/scenes/cornell.pov"
out="$build/scene-rays-bench"
mkdir -p "$out"
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
# rate RAYS SECONDS: millions of rays per second, "-" for no time measured.
rate() { awk "BEGIN { if ($2 > 0) printf \"%.2f M\", $1 / $2 / 1e6; else printf \"-\" }"; }

rows=()
summary=()
declare -A rays cpu
# The scene as it is (a 9 x 9 area light: 81 shadow rays per shading point, photon's tested against
# the objects near each point-to-light box, found once per point), and the same with its
# `area_light` line removed (a point light: one shadow ray per point, through the whole scene's
# bounding hierarchy in both programs).
sed '/^ *area_light /d' "$scene" >"$out/cornell-point-light.pov"
for light in $lights; do
  case "$light" in
    area) file="$scene" ;;
    point) file="$out/cornell-point-light.pov" ;;
    *) echo "bench-scene-rays: unknown light '$light' (area or point)" >&2; exit 2 ;;
  esac
  for size in "${size_list[@]}"; do
    w=${size%x*} h=${size#*x}
    key=$light-$size

    # photon: ray tracing only (direct light by shadow rays, mirror and glass), 1 spp and no adaptive
    # anti-aliasing (photon render's rt mode takes --aa-threshold 0.1 unless told), 1 thread.
    log="$out/photon-$key.log"
    read -r user sys wall < <(timed "$log" "$photon" render "$file" -o "$out/photon-$key.ppm" --mode rt \
      --width "$w" --height "$h" --ray-depth 4 --spp 1 --aa-threshold 0 --shadow-samples "$shadow_samples" --threads 1)
    line1=$(grep -m1 '^  rays (pass 2) ' "$log")
    line2=$(grep -A1 -m1 '^  rays (pass 2) ' "$log" | tail -n 1)
    total=$(sed -n 's/.* \([0-9]*\) total:.*/\1/p' <<<"$line1")
    camera=$(sed -n 's/.*camera \([0-9]*\),.*/\1/p' <<<"$line1")
    shadow=$(sed -n 's/.*shadow \([0-9]*\),.*/\1/p' <<<"$line1")
    refl=$(sed -n 's/.*reflection \([0-9]*\),.*/\1/p' <<<"$line1")
    refr=$(sed -n 's/.*refraction \([0-9]*\),.*/\1/p' <<<"$line2")
    # photon's own time of pass 2 (wall clock; one thread): the render phase.
    render=$(sed -n 's/.*render \([0-9.]*\) s, total.*/\1/p' "$log" | head -n 1)
    c=$(num %.2f "$user + $sys")
    rays[photon,$key]=$total cpu[photon,$key]=$c
    rows+=("| photon rt | $light | $size | $total | $camera + $shadow + $(num %d "$refl + $refr") | $c | $(rate "$total" "$c") | $render | $(rate "$total" "$render") |")
    echo "photon $key: $total rays, $c CPU-s (wall $wall s)" >&2

    # POV-Ray: the same scene file, rt.inc (no radiosity, no photons), no anti-aliasing, 1 thread.
    log="$out/povray-$key.log"
    read -r user sys wall < <(timed "$log" povray -D +W"$w" +H"$h" -A +WT1 +HI"$root/examples/scenes/povray/rt.inc" +FP \
      +O"$out/povray-$key.ppm" "$file")
    prays=$(sed -n 's/^Rays: *\([0-9]*\).*/\1/p' "$log")
    ptests=$(sed -n 's/^Shadow Ray Tests: *\([0-9]*\).*/\1/p' "$log")
    phits=$(sed -n 's/^Shadow Cache Hits: *\([0-9]*\).*/\1/p' "$log")
    preflected=$(sed -n 's/^Reflected Rays: *\([0-9]*\).*/\1/p' "$log")
    prefracted=$(sed -n 's/^Refracted Rays: *\([0-9]*\).*/\1/p' "$log")
    # POV-Ray's own time of its trace (the render phase), wall clock as photon's: "Trace Time: ... (N seconds)".
    ptrace=$(grep -m1 'Trace Time:' "$log" | sed -n 's/.*(\([0-9.]*\) seconds).*/\1/p')
    ptotal=$(num %d "$prays + $ptests")
    c=$(num %.2f "$user + $sys")
    rays[povray,$key]=$ptotal cpu[povray,$key]=$c
    rows+=("| POV-Ray rt.inc | $light | $size | $ptotal | $(num %d "$prays - ${preflected:-0} - ${prefracted:-0}") + $ptests ($phits cache hits) + $(num %d "${preflected:-0} + ${prefracted:-0}") | $c | $(rate "$ptotal" "$c") | $ptrace | $(rate "$ptotal" "$ptrace") |")
    echo "povray $key: $ptotal rays, $c CPU-s (wall $wall s)" >&2
    summary+=("$(printf 'photon / POV-Ray rays per CPU-s, %s light, %s: %.2f' "$light" "$size" \
      "$(num %.6f "($total / ${cpu[photon,$key]}) / ($ptotal / $c)")")")
  done
  if [ ${#size_list[@]} -ge 2 ]; then
    a=$light-${size_list[0]} b=$light-${size_list[-1]}
    margin=true
    for p in photon povray; do
      dr=$(num %d "${rays[$p,$b]} - ${rays[$p,$a]}")
      dc=$(num %.6f "${cpu[$p,$b]} - ${cpu[$p,$a]}")
      if awk "BEGIN { exit !($dc <= 0) }"; then  # images too small for the clock to see the difference
        summary+=("$p, $light light: no more CPU-s measured at ${size_list[-1]} than at ${size_list[0]}; no per-ray cost (use larger --sizes)")
        margin=false
        continue
      fi
      q=$(num %.6f "$dr / $dc")
      eval "q_$p=$q"
      summary+=("$(printf '%s, %s light, %s to %s: %d more rays in %.2f more CPU-s: %.2f M rays per CPU-s at the margin; fixed cost (CPU-s extrapolated to 0 rays) %.2f' \
        "$p" "$light" "${size_list[0]}" "${size_list[-1]}" "$dr" "$dc" "$(num %.6f "$q / 1e6")" "$(num %.6f "${cpu[$p,$a]} - ${rays[$p,$a]} / $q")")")
    done
    if $margin; then
      summary+=("$(printf 'photon / POV-Ray at the margin, %s light: %.2f' "$light" "$(num %.6f "$q_photon / $q_povray")")")
    fi
  fi
done

echo "| program | light | size | rays | camera + shadow + reflection/refraction | CPU-s (whole command) | rays per CPU-s | render phase s (own statistics) | rays per render-phase s |"
echo "|---|---|---|---:|---:|---:|---:|---:|---:|"
printf '%s\n' "${rows[@]}"
echo
printf '%s\n' "${summary[@]}"
echo "images, logs and statistics: $out"
