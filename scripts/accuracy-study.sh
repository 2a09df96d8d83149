#!/usr/bin/env bash
# What accuracy costs in time: renders the Cornell box (examples/scenes/cornell.pov) with a ladder
# of photon settings, times each render (wall clock) and measures its error against photon's own
# unbiased path tracer (--mode reference) with tools/compare_renders.cpp: whole-image RMSE, RMSE of
# 8x8 block means (per-pixel noise averages away there, bias and blotches do not) and the worst
# relative bias of a wall's mean radiance. The reference is the mean of two path-traced images
# with different seeds; their difference measures the reference's own noise, reported in the
# first row. Writes the table into docs/accuracy.md (between its accuracy-study markers), a few
# render | reference | difference pictures to docs/images/accuracy/ and, when /usr/bin/python3 has
# matplotlib, an error-against-time plot docs/images/accuracy/error-vs-time.png. Each ladder row is
# rendered 3 times and its shortest time kept; the errors do not depend on the load.
#
# Usage: scripts/accuracy-study.sh [--size WxH] [--reference-spp N] [--threads N] [--build DIR]
#            [--doc FILE] [--images DIR]
#   --size           image size (default 200x150)
#   --reference-spp  samples per pixel of each of the two reference images (default 8192)
#   --threads        worker threads of every render (default 2)
# The renders, logs and statistics stay in DIR/accuracy (DIR default build-accuracy).
set -euo pipefail
cd "$(dirname "$0")/.."
root=$PWD

size=200x150
reference_spp=8192
threads=2
build="build-accuracy"
doc=docs/accuracy.md
images=docs/images/accuracy
usage() { sed -n '/^# Usage:/,/^# The renders/p' "$0" | sed 's/^# \{0,1\}//' >&2; exit 2; }
while [ $# -gt 0 ]; do
  [ $# -ge 2 ] || usage
  case "$1" in
    --size) size=$2 ;;
    --reference-spp) reference_spp=$2 ;;
    --threads) threads=$2 ;;
    --build) build=$2 ;;
    --doc) doc=$2 ;;
    --images) images=$2 ;;
    *) usage ;;
  esac
  shift 2
done
[[ $size =~ ^([0-9]+)x([0-9]+)$ ]] || { echo "accuracy-study: --size must be WxH, e.g. 200x150" >&2; exit 2; }
width=${BASH_REMATCH[1]} height=${BASH_REMATCH[2]}
[[ $reference_spp =~ ^[1-9][0-9]*$ ]] || { echo "accuracy-study: --reference-spp takes a positive number" >&2; exit 2; }
[[ $threads =~ ^[0-9]+$ ]] || { echo "accuracy-study: --threads takes a number" >&2; exit 2; }

scripts/install-deps.sh compare  # + python3-matplotlib for the plot
cmake -S . -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release -DPHOTON_BUILD_TESTS=OFF -DPHOTON_BUILD_EXAMPLES=OFF >/dev/null
cmake --build "$build" --target photon_cli photon_compare
photon=$root/$build/photon
compare=$root/$build/photon-compare
scene=$root/examples/scenes/cornell.pov
work=$root/$build/accuracy
mkdir -p "$work" "$images"
block=8
# The Cornell walls' inner faces, shared with scripts/compare-povray.sh.
source "$root/scripts/scene-regions.sh"
set_regions cornell
regions=("${region_args[@]}")

now() { date +%s.%N; }
# Renders $work/NAME.exr with the scene's settings overridden by the remaining arguments, `runs`
# times (the image is the same each time: fixed seed), and sets `seconds` to the shortest wall
# time of the whole command (parsing, photon tracing and rendering): the least disturbed by load.
runs=3
timed_render() {
  local name=$1 t0 t run
  shift
  seconds=
  for ((run = 0; run < runs; ++run)); do
    t0=$(now)
    # --no-error-estimate: the cost of the settings alone, without pm's short sppm run (other modes ignore it)
    "$photon" render "$scene" --width "$width" --height "$height" --threads "$threads" --no-error-estimate "$@" -o "$work/$name.exr" \
      >"$work/$name.log" 2>&1 || { tail -20 "$work/$name.log" >&2; echo "accuracy-study: $name failed" >&2; exit 1; }
    t=$(awk -v a="$t0" -v b="$(now)" 'BEGIN { printf "%.2f", b - a }')
    seconds=$(awk -v s="${seconds:-$t}" -v t="$t" 'BEGIN { printf "%.2f", t < s ? t : s }')
  done
}
# Compares $work/NAME.exr with the reference; sets rmse, block_rmse, bias (percent) and wall.
measure() {
  local name=$1 reference=$2
  shift 2
  "$compare" "$scene" "$work/$name.exr" "$reference" "${regions[@]}" --block "$block" --summary "$work/$name.tsv" \
    --labels "$name,reference" "$@" >"$work/$name.md" 2>/dev/null
  IFS=$'\t' read -r rmse _ _ _ block_rmse bias wall <"$work/$name.tsv"
  bias=$(awk -v b="$bias" 'BEGIN { printf "%+.1f", 100 * b }')
}

echo "== reference: 2 x $reference_spp samples per pixel, ${width}x$height"
runs=1  # the reference is only timed for the record
timed_render reference-a --mode reference --spp "$reference_spp" --seed 1
reference_s=$seconds
timed_render reference-b --mode reference --spp "$reference_spp" --seed 2
reference_s=$(awk -v a="$reference_s" -v b="$seconds" 'BEGIN { printf "%.0f", a + b }')
runs=3
oiiotool "$work/reference-a.exr" "$work/reference-b.exr" --add --mulc 0.5 -o "$work/reference.exr"
# The two halves differ by twice the noise of their mean (independent, equal variance): halve the
# RMSE and the block RMSE; a wall mean's bias between the halves is likewise twice its own noise.
measure reference-a "$work/reference-b.exr"
noise_rmse=$(awk -v r="$rmse" 'BEGIN { printf "%.4f", r / 2 }')
noise_block=$(awk -v r="$block_rmse" 'BEGIN { printf "%.4f", r / 2 }')
noise_bias=$(awk -v b="$bias" 'BEGIN { printf "%.1f", (b < 0 ? -b : b) / 2 }')
echo "   $reference_s s; its noise: RMSE $noise_rmse, block RMSE $noise_block, worst wall $noise_bias%"

# The ladder: name | what it shows | photon options. Every pm run starts from the scene file's
# settings (200k + 200k photons, k 100 / 60, final gather 256 rays, cache error 0.2, stride 4,
# 16 shadow samples, 4 samples per pixel) and changes only what the row says.
ladder=(
  "rt|direct light only (no indirect)|--mode rt"
  "pm-direct|everything read from the photon maps|--mode pm-direct"
  "fg0-k100|no final gather: global map read directly, k 100|--mode pm --final-gather 0"
  "fg0-paper|no final gather, the paper's k 2000, 250k photons, 400 shadow rays, 1 spp|--mode pm --final-gather 0 --global-photons 250000 --global-k 2000 --global-radius 1 --shadow-samples 400 --spp 1"
  "fg64|final gather 64 rays|--mode pm --final-gather 64"
  "default|scene default: final gather 256 rays, cache 0.2|--mode pm"
  "fg1024|final gather 1024 rays|--mode pm --final-gather 1024"
  "ic0.4|irradiance cache error 0.4|--mode pm --irradiance-cache 0.4"
  "ic0.1|irradiance cache error 0.1|--mode pm --irradiance-cache 0.1"
  "ic0|no irradiance cache (a final gather at every sample)|--mode pm --irradiance-cache 0"
  "stride0|no precomputed irradiance (a density estimate per gather ray)|--mode pm --irradiance-stride 0"
  "photons50k|50k global photons|--mode pm --global-photons 50000"
  "photons1M|1M global photons|--mode pm --global-photons 1000000"
  "depth30|photon paths of up to 30 bounces, not 10|--mode pm --photon-depth 30"
  "depth30-ic0|30 bounces and no irradiance cache|--mode pm --photon-depth 30 --irradiance-cache 0"
)
# Rows shown as render | reference | difference pictures in the document.
pictured=" fg0-k100 fg0-paper default ic0.4 ic0 "

rows=()
printf 'name\tseconds\trmse\tblock_rmse\tbias\n' >"$work/ladder.tsv"
for entry in "${ladder[@]}"; do
  IFS='|' read -r name what options <<<"$entry"
  echo "== $name: $what"
  # shellcheck disable=SC2086  # options are words
  timed_render "$name" $options
  picture=()
  [[ $pictured == *" $name "* ]] && picture=(--side-by-side "$root/$images/$name.jpg")
  measure "$name" "$work/reference.exr" "${picture[@]}"
  echo "   $seconds s, RMSE $rmse, block RMSE $block_rmse, worst wall $wall $bias%"
  rows+=("| $what | \`$options\` | $seconds | $rmse | $block_rmse | $bias% ($wall) |")
  printf '%s\t%s\t%s\t%s\t%s\n' "$name" "$seconds" "$rmse" "$block_rmse" "$bias" >>"$work/ladder.tsv"
done

plot=""
if /usr/bin/python3 -c "import matplotlib" 2>/dev/null; then
  /usr/bin/python3 - "$work/ladder.tsv" "$images/error-vs-time.png" "$noise_rmse" "$noise_block" <<'EOF'
import csv, sys
import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt
rows = list(csv.DictReader(open(sys.argv[1]), delimiter="\t"))
fig, ax = plt.subplots(figsize=(7, 4.2), dpi=100)
t = [float(r["seconds"]) for r in rows]
ax.scatter(t, [float(r["rmse"]) for r in rows], marker="o", label="RMSE (pixels)")
ax.scatter(t, [float(r["block_rmse"]) for r in rows], marker="s", label="RMSE (8x8 block means)")
for r, x in zip(rows, t):
    ax.annotate(r["name"], (x, float(r["block_rmse"])), fontsize=7, xytext=(3, 3), textcoords="offset points")
ax.axhline(float(sys.argv[3]), color="C0", lw=0.8, ls=":", label="reference noise (pixels)")
ax.axhline(float(sys.argv[4]), color="C1", lw=0.8, ls=":", label="reference noise (blocks)")
ax.set_xscale("log"); ax.set_yscale("log")
ax.set_xlabel("wall time (s)"); ax.set_ylabel("error against the reference (W m$^{-2}$ sr$^{-1}$)")
ax.set_title("Cornell box: error against time")
ax.legend(fontsize=7); ax.grid(True, which="both", lw=0.3)
fig.tight_layout(); fig.savefig(sys.argv[2])
EOF
  plot="![Error against wall time for every row, pixels and 8x8 blocks](images/accuracy/error-vs-time.png)"
else
  echo "accuracy-study: /usr/bin/python3 has no matplotlib (scripts/install-deps.sh compare installs it); no plot"
fi

cpu=$(sed -n 's/^model name[[:space:]]*: //p' /proc/cpuinfo | head -1)
table=$(
  echo "<!-- accuracy-study: begin (written by scripts/accuracy-study.sh) -->"
  echo
  echo "${width}x$height, $threads threads on $(nproc) cores ($cpu), $(date -u +%Y-%m-%d)." \
    "Reference: the mean of two path-traced images of $reference_spp samples per pixel (seeds 1 and 2, $reference_s s together)." \
    "Times are the shortest wall clock of 3 runs of the whole \`photon render\` command."
  echo
  echo "| setting | options | time (s) | RMSE | RMSE of ${block}x$block blocks | worst wall bias |"
  echo "|---|---|---:|---:|---:|---:|"
  echo "| reference's own noise (half the difference of its two halves) | \`--mode reference --spp $reference_spp\` x 2 | $reference_s | $noise_rmse | $noise_block | $noise_bias% |"
  printf '%s\n' "${rows[@]}"
  echo
  echo "$plot"
  echo
  echo "<!-- accuracy-study: end -->"
)
source "$root/scripts/doc-block.sh"
replace_doc_block "$doc" accuracy-study "$table"
echo "== wrote $doc and $images/; renders and logs in $work"
