#!/usr/bin/env bash
# The scene-class gallery at picture size: renders every class of examples/scenes/classes with pm
# and with a converged judge (sppm, or the path tracer with --judge reference) through
# photon-classes (tools/render_classes.cpp: the same block measurement as the gallery test,
# tests/classes), writes pm | judge | difference pictures to docs/images/classes/<name>.jpg
# (photon-compare; red where pm is brighter, blue where it is darker, full colour at +-50%) and
# the table of worst block biases and times into docs/scene-classes.md (between its
# scene-classes markers).
#
# Usage: scripts/scene-classes.sh [--size WxH] [--judge sppm|reference] [--effort F]
#            [--photons-per-pass N] [--classes a,b] [--reuse] [--build DIR] [--doc FILE] [--images DIR]
#   --size     image size (default 320x240; the blocks are a 4 x 4 grid)
#   --judge    sppm (default: sees every path) or reference (the path tracer, blind to
#              point-light caustics)
#   --effort   the judge's passes or samples, times those the test uses at 48x36 (default 2)
#   --photons-per-pass  sppm photons per pass (default 100000)
#   --reuse    keep the renders and numbers of the last run; only remake the pictures and the table
# The renders stay in DIR/classes (DIR default build-classes).
set -euo pipefail
cd "$(dirname "$0")/.."
root=$PWD

size=320x240
judge=sppm
effort=2
photons=100000
only=""
build=build-classes
doc=docs/scene-classes.md
images=docs/images/classes
usage() { sed -n '/^# Usage:/,/^# The renders/p' "$0" | sed 's/^# \{0,1\}//' >&2; exit 2; }
reuse=0
while [ $# -gt 0 ]; do
  [ "$1" = --reuse ] && { reuse=1; shift; continue; }
  [ $# -ge 2 ] || usage
  case "$1" in
    --size) size=$2 ;;
    --judge) judge=$2 ;;
    --effort) effort=$2 ;;
    --photons-per-pass) photons=$2 ;;
    --classes) only=$2 ;;
    --build) build=$2 ;;
    --doc) doc=$2 ;;
    --images) images=$2 ;;
    *) usage ;;
  esac
  shift 2
done
[[ $size =~ ^[0-9]+x[0-9]+$ ]] || { echo "scene-classes: --size must be WxH, e.g. 320x240" >&2; exit 2; }

scripts/install-deps.sh render
cmake -S . -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release -DPHOTON_BUILD_TESTS=OFF -DPHOTON_BUILD_EXAMPLES=OFF >/dev/null
cmake --build "$build" --target photon_classes photon_compare
work=$root/$build/classes
mkdir -p "$work" "$images"

classes_args=()
[ -n "$only" ] && classes_args=(--classes "$only")
if [ $reuse = 0 ] || [ ! -s "$work/classes.tsv" ]; then
  start=$SECONDS
  "$root/$build/photon-classes" examples/scenes/classes "$work" --size "$size" --judge "$judge" --effort "$effort" \
    --photons-per-pass "$photons" "${classes_args[@]}" | tee "$work/classes.tsv"
  echo $((SECONDS - start)) >"$work/elapsed"
fi
elapsed=$(cat "$work/elapsed" 2>/dev/null || echo "?")

# Exposure of each picture: the rooms are far brighter than the open scenes (numbers do not depend on it).
exposure_of() {
  case "$1" in
    window-room) echo 0.4 ;;
    mirror-plane | mirror-corridor) echo 1 ;;
    many-lights | scale-km | scale-mm) echo 1.5 ;;
    *) echo 2 ;;
  esac
}
pct() { awk -v b="$1" 'BEGIN { printf "%+.1f%%", 100 * b }'; }
rows=()
while IFS=$'\t' read -r name judge_mode noise_rms noise_max judge_s rest; do
  "$root/$build/photon-compare" "examples/scenes/classes/$name.pov" "$work/$name-pm.exr" "$work/$name-judge.exr" \
    --labels "pm,$judge_mode" --exposure "$(exposure_of "$name")" --side-by-side "$images/$name.jpg" >/dev/null 2>&1
  read -r -a f <<<"$rest"
  cells=""
  rt="-"
  for ((i = 0; i < ${#f[@]}; i += 4)); do
    cell="$(pct "${f[i + 1]}") (${f[i + 2]}), $(printf '%.1f' "${f[i + 3]}") s"
    case "${f[i]}" in
      pm) pm=$cell ;;
      pm-direct) pmd=$cell ;;
      rt) rt=$cell ;;
    esac
  done
  noise=$(awk -v r="$noise_rms" -v m="$noise_max" 'BEGIN { printf "%.2f%% / %.2f%%", 100 * r, 100 * m }')
  anchor=$name
  [[ $name == scale-* ]] && anchor=scale-km-and-scale-mm  # one section for the pair
  rows+=("| [$name](#$anchor) | $pm | $pmd | $rt | $noise | $(printf '%.0f' "$judge_s") s |")
done <"$work/classes.tsv"

cpu=$(sed -n 's/^model name[[:space:]]*: //p' /proc/cpuinfo | head -1)
table=$(
  echo "<!-- scene-classes: begin (written by scripts/scene-classes.sh) -->"
  echo
  echo "$size, 4 x 4 blocks, $(nproc) cores ($cpu), $(date -u +%Y-%m-%d), $elapsed s in all." \
    "Judge: $judge, two runs (seeds 1 and 2) of $effort times the test's effort" \
    "$([ "$judge" = sppm ] && echo "($photons photons per pass)"); its noise is the relative difference of" \
    "the two runs' block means (rms / largest over the blocks). Bias: the worst block of the mode against" \
    "the judge's mean, among blocks holding more than 1% of the judge's light (block column,row from the top left)," \
    "then the render's time."
  echo
  echo "| class | pm | pm-direct | rt (direct light only) | judge noise (rms / max) | judge time (2 runs) |"
  echo "|---|---|---|---|---|---:|"
  printf '%s\n' "${rows[@]}"
  echo
  echo "<!-- scene-classes: end -->"
)
source "$root/scripts/doc-block.sh"
replace_doc_block "$doc" scene-classes "$table"
echo "== wrote $doc and $images/; renders in $work"
