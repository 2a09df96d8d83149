#!/usr/bin/env bash
# Renders the paper's four scenes with photon (pm mode) and with POV-Ray 3.7 (radiosity + caustic
# photons), times both on all cores, and measures how far apart the linear images are: RMSE, PSNR
# and the mean radiance of the whole image and of every wall (tools/compare_renders.cpp). Writes
# photon | POV-Ray | difference pictures to docs/images/povray/<scene>.jpg and the tables into
# docs/povray-comparison.md (between its compare-povray markers). docs/povray-comparison.md
# explains the settings and the differences.
#
# Usage: scripts/compare-povray.sh [--size WxH] [--scenes cornell,recursive,room1,room2]
#            [--pov-quality hq|normal] [--reference SPP] [--direct] [--reuse] [--build DIR]
#            [--doc FILE] [--images DIR]
#   --size        image size (default 800x600)
#   --scenes      which scenes, comma-separated (default all four)
#   --pov-quality hq: POV-Ray's IndoorHQ radiosity preset (radphot_hq.inc, default);
#                 normal: its Normal preset (radphot.inc), several times faster and blotchier
#   --reference   also render photon's unbiased path tracer with SPP samples per pixel and compare
#                 both renderers with it (the arbiter where they disagree)
#   --direct      also compare direct light alone: photon rt against POV-Ray without radiosity and
#                 photons (checks units, light falloff and that both images are linear)
#   --reuse       keep renders of an earlier run at the same size (and their times); render the rest
#   --doc, --images  where the table and the pictures go (defaults as above)
# The renders, logs and statistics stay in DIR/compare (DIR default build-compare).
set -euo pipefail
cd "$(dirname "$0")/.."
root=$PWD

size=800x600
scenes=cornell,recursive,room1,room2
quality=hq
reference_spp=0
direct=0
reuse=0
build=build-compare
doc=docs/povray-comparison.md
images=docs/images/povray
usage() { sed -n '/^# Usage:/,/^# The renders/p' "$0" | sed 's/^# \{0,1\}//' >&2; exit 2; }
while [ $# -gt 0 ]; do
  case "$1" in
    --direct) direct=1; shift; continue ;;
    --reuse) reuse=1; shift; continue ;;
  esac
  [ $# -ge 2 ] || usage
  case "$1" in
    --size) size=$2 ;;
    --scenes) scenes=$2 ;;
    --pov-quality) quality=$2 ;;
    --reference) reference_spp=$2 ;;
    --build) build=$2 ;;
    --doc) doc=$2 ;;
    --images) images=$2 ;;
    *) usage ;;
  esac
  shift 2
done
[[ $size =~ ^([0-9]+)x([0-9]+)$ ]] || { echo "compare-povray: --size must be WxH, e.g. 800x600" >&2; exit 2; }
width=${BASH_REMATCH[1]} height=${BASH_REMATCH[2]}
case "$quality" in
  hq) pov_header=examples/scenes/povray/radphot_hq.inc ;;
  normal) pov_header=examples/scenes/povray/radphot.inc ;;
  *) echo "compare-povray: --pov-quality must be hq or normal" >&2; exit 2 ;;
esac
[[ $reference_spp =~ ^[0-9]+$ ]] || { echo "compare-povray: --reference takes a number of samples per pixel" >&2; exit 2; }
IFS=, read -r -a scene_list <<<"$scenes"
for s in "${scene_list[@]}"; do
  [ -f "examples/scenes/$s.pov" ] || { echo "compare-povray: no scene examples/scenes/$s.pov" >&2; exit 2; }
done

scripts/install-deps.sh compare
cmake -S . -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release -DPHOTON_BUILD_TESTS=OFF -DPHOTON_BUILD_EXAMPLES=OFF >/dev/null
cmake --build "$build" --target photon_cli photon_compare
photon=$root/$build/photon
compare=$root/$build/photon-compare
work=$root/$build/compare
mkdir -p "$work" "$images"
cores=$(nproc)

# set_regions SCENE: the walls whose mean radiance is compared.
source "$root/scripts/scene-regions.sh"
# The rooms are far brighter than 1 W m^-2 sr^-1 near the window: a lower exposure keeps the pictures
# readable (the numbers do not depend on it).
exposure() { case "$1" in room2) echo 0.5 ;; *) echo 1 ;; esac; }

now() { date +%s.%N; }
elapsed() { awk -v a="$1" -v b="$2" 'BEGIN { printf "%.1f", b - a }'; }
povray_in_work() { (cd "$work" && povray "$@"); }

# Runs one render whose image is $work/NAME.exr, logging to NAME.log, and sets `seconds` to its
# wall time (kept in NAME.time, so that --reuse can skip a render done earlier at the same size).
timed_render() {
  local name=$1 t0
  shift
  if [ "$reuse" = 1 ] && [ -f "$work/$name.exr" ] && [ -f "$work/$name.time" ] &&
    [ "$(cut -f1 "$work/$name.time")" = "${width}x$height" ]; then
    seconds=$(cut -f2 "$work/$name.time")
    echo "   $seconds s (reused)"
    return
  fi
  t0=$(now)
  "$@" >"$work/$name.log" 2>&1 || { tail -20 "$work/$name.log" >&2; echo "compare-povray: $name failed" >&2; exit 1; }
  seconds=$(elapsed "$t0" "$(now)")
  printf '%s\t%s\n' "${width}x$height" "$seconds" >"$work/$name.time"
  echo "   $seconds s"
}

pov_options=(-D +W"$width" +H"$height" +A0.3 +AM2 +R3 +WT"$cores" +FE)
summary_rows=()
details=""
for scene in "${scene_list[@]}"; do
  pov=$root/examples/scenes/$scene.pov
  set_regions "$scene"
  photon_name=$scene-photon pov_name=$scene-povray-$quality

  echo "== $scene: photon pm, ${width}x$height"
  # --no-error-estimate: the image alone, as POV-Ray renders it (no short sppm run to judge it).
  timed_render "$photon_name" "$photon" render "$pov" --mode pm --no-error-estimate --width "$width" --height "$height" \
    -o "$work/$photon_name.exr"
  photon_s=$seconds
  echo "== $scene: POV-Ray $(basename "$pov_header" .inc), ${width}x$height, $cores threads"
  timed_render "$pov_name" povray_in_work "${pov_options[@]}" +HI"$root/$pov_header" +O"$pov_name.exr" "$pov"
  povray_s=$seconds

  table=$("$compare" "$pov" "$work/$photon_name.exr" "$work/$pov_name.exr" "${region_args[@]}" \
    --summary "$work/$scene.tsv" --side-by-side "$images/$scene.jpg" --mask "$work/$scene-mask.png" \
    --exposure "$(exposure "$scene")")
  read -r rmse psnr mean_photon mean_povray <"$work/$scene.tsv"
  ratio_time=$(awk -v a="$povray_s" -v b="$photon_s" 'BEGIN { printf "%.1f", a / b }')
  ratio_mean=$(awk -v a="$mean_photon" -v b="$mean_povray" 'BEGIN { printf "%.3f", a / b }')
  summary_rows+=("| $scene | $photon_s s | $povray_s s | $ratio_time | $rmse | $psnr dB | $mean_photon | $mean_povray | $ratio_mean |")
  details+=$'\n'"### $scene"$'\n\n'"![$scene: photon pm, POV-Ray, difference](images/povray/$scene.jpg)"$'\n\n'"$table"$'\n'

  if [ "$direct" = 1 ]; then
    echo "== $scene: direct light only, photon rt"
    timed_render "$scene-photon-rt" "$photon" render "$pov" --mode rt --width "$width" --height "$height" \
      -o "$work/$scene-photon-rt.exr"
    echo "== $scene: direct light only, POV-Ray rt"
    timed_render "$scene-povray-rt" povray_in_work "${pov_options[@]}" +HI"$root/examples/scenes/povray/rt.inc" \
      +O"$scene-povray-rt.exr" "$pov"
    details+=$'\n'"Direct light only (photon \`rt\` against POV-Ray without radiosity and photons, where the glass casts no shadow):"$'\n\n'
    details+="$("$compare" "$pov" "$work/$scene-photon-rt.exr" "$work/$scene-povray-rt.exr" "${region_args[@]}" \
      --labels "photon rt,POV-Ray rt")"$'\n'
  fi
  if [ "$reference_spp" -gt 0 ]; then
    echo "== $scene: photon reference (path tracing), $reference_spp samples per pixel"
    ref_name=$scene-reference-$reference_spp
    timed_render "$ref_name" "$photon" render "$pov" --mode reference --spp "$reference_spp" --width "$width" \
      --height "$height" -o "$work/$ref_name.exr"
    details+=$'\n'"Against photon's path-traced reference ($reference_spp samples per pixel, $seconds s):"$'\n\n'
    for run in "$photon_name:photon pm" "$pov_name:POV-Ray"; do
      details+="$("$compare" "$pov" "$work/${run%%:*}.exr" "$work/$ref_name.exr" "${region_args[@]}" \
        --labels "${run#*:},reference")"$'\n\n'
    done
  fi
done

cpu=$(sed -n 's/^model name[[:space:]]*: //p' /proc/cpuinfo | head -1)
block=$(
  echo "<!-- compare-povray: begin (written by scripts/compare-povray.sh) -->"
  echo
  echo "${width}x$height; photon \`pm\` with the scene files' settings; POV-Ray $(povray --version 2>&1 | sed -n 's/^POV-Ray \([0-9.]*[0-9]\).*/\1/p' | head -1)" \
    "with \`$pov_header\`; $cores cores ($cpu), $(date -u +%Y-%m-%d)." \
    "Wall times include parsing and photon tracing; both renderers use all cores."
  echo
  echo "| scene | photon | POV-Ray | POV-Ray / photon (time) | RMSE | PSNR (peak 1) | mean photon | mean POV-Ray | photon / POV-Ray (mean) |"
  echo "|---|---:|---:|---:|---:|---:|---:|---:|---:|"
  printf '%s\n' "${summary_rows[@]}"
  echo "$details"
  echo "<!-- compare-povray: end -->"
)
source "$root/scripts/doc-block.sh"
replace_doc_block "$doc" compare-povray "$block"
echo "== wrote $doc and $images/*.jpg; renders and logs in $work"
