#!/usr/bin/env bash
# Error against CPU time, photon against POV-Ray 3.7: renders each scene with photon's pm mode at a
# few settings of its knobs (photons, final-gather rays, irradiance-cache error), with sppm and the
# path tracer (reference) at several budgets, and with POV-Ray's radiosity presets Normal and
# IndoorHQ (plus its photons where the scene has mirrors or glass) at max_trace_level 4 and 10.
# Every image is judged by the relative MSE (sum of squared error over pixels and channels / sum
# of the judge's squared radiance, photon-compare --relative-mse) against a converged consistent
# judge made by photon: the mean of two renders of different seeds (sppm, or the path tracer where
# every light is seen by it), cached. Half the relative MSE of the two seeds against each other is
# the judge's own noise floor (what it adds to every measured error); it is printed beside the
# numbers and subtracted in the "net" column. Time is the CPU time (user + sys) of the whole
# command (parsing, photon tracing, rendering, writing), both programs on the same machine in the
# same run, so that the machine's load changes it little.
# Writes docs/accuracy-vs-povray/<scene>-<W>x<H>.csv, a log-log plot docs/images/accuracy/<scene>-<W>x<H>-vs-povray.png
# per scene and the tables into docs/accuracy-vs-povray.md (a marked block per scene and size, so
# that runs of a few scenes add up).
#
# Usage: scripts/povray-accuracy-study.sh [--size WxH] [--scenes a,b,...] [--judge-spp N]
#            [--judge-passes N] [--sweep pm,sppm,reference,povray] [--budgets small|full]
#            [--threads N] [--build DIR] [--doc FILE] [--reuse-judges yes]
#   --size          image size of every scene (default 128x128); SCENE=WxH entries in --scenes
#                   override it for one scene, e.g. --scenes cornell,white_box=512x512
#   --scenes        default cornell,room1,white_box,two_balls (examples/scenes/<name>.pov)
#   --judge-spp     samples per pixel of each of the judge's two path-traced renders (default 4096)
#   --judge-passes  passes of each of the judge's two sppm renders (default 1024, 100k photons each)
#                   The judge is the path tracer for scenes without mirrors and glass (it converges
#                   faster there), sppm for the others (the path tracer cannot see a point light's
#                   caustics and finds a small light's ones by chance).
#   --sweep         which curves (default all four); the others keep their rows from an earlier run
#   --budgets       small: fewer pm settings and budgets (a quick look); full (default)
#   --threads       threads of every render, photon's and POV-Ray's (default 2)
#   --reuse-judges  yes: take a cached judge made by any earlier build (the binary leaves the key);
#                   for a change that cannot move the judge's mode (sppm, reference)
# The judges are cached under DIR/povray-accuracy/judges, keyed by scene file, size, judge settings
# and the photon binary (its SHA-256); renders and logs stay in DIR/povray-accuracy (DIR default
# build, reused when configured).
set -euo pipefail
cd "$(dirname "$0")/.."
root=$PWD

size=128x128
scenes=cornell,room1,white_box,two_balls
judge_spp=4096
judge_passes=1024
judge_photons=100000
sweep=pm,sppm,reference,povray
budgets=full
threads=2
build=build
doc=docs/accuracy-vs-povray.md
reuse_judges=no
usage() { sed -n '/^# Usage:/,/^# The judges/p' "$0" | sed 's/^# \{0,1\}//' >&2; exit 2; }
while [ $# -gt 0 ]; do
  [ $# -ge 2 ] || usage
  case "$1" in
    --size) size=$2 ;;
    --scenes) scenes=$2 ;;
    --judge-spp) judge_spp=$2 ;;
    --judge-passes) judge_passes=$2 ;;
    --sweep) sweep=$2 ;;
    --budgets) budgets=$2 ;;
    --threads) threads=$2 ;;
    --build) build=$2 ;;
    --doc) doc=$2 ;;
    --reuse-judges) reuse_judges=$2 ;;
    *) usage ;;
  esac
  shift 2
done
is_size() { [[ $1 =~ ^[1-9][0-9]*x[1-9][0-9]*$ ]]; }
is_size "$size" || { echo "povray-accuracy-study: --size must be WxH, e.g. 128x128" >&2; exit 2; }
for n in "$judge_spp" "$judge_passes" "$threads"; do
  [[ $n =~ ^[1-9][0-9]*$ ]] || { echo "povray-accuracy-study: '$n' is not a positive number" >&2; exit 2; }
done
case "$budgets" in small | full) ;; *) echo "povray-accuracy-study: --budgets is small or full" >&2; exit 2 ;; esac
IFS=, read -r -a scene_list <<<"$scenes"
for entry in "${scene_list[@]}"; do
  [ -f "examples/scenes/${entry%%=*}.pov" ] || { echo "povray-accuracy-study: no scene examples/scenes/${entry%%=*}.pov" >&2; exit 2; }
  [[ $entry != *=* ]] || is_size "${entry#*=}" || { echo "povray-accuracy-study: bad size in '$entry'" >&2; exit 2; }
done
sweeps() { [[ ",$sweep," == *",$1,"* ]]; }

scripts/install-deps.sh compare  # POV-Ray, and matplotlib for the plots
[ -f "$build/CMakeCache.txt" ] ||
  cmake -S . -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release -DPHOTON_BUILD_TESTS=OFF -DPHOTON_BUILD_EXAMPLES=OFF >/dev/null
cmake --build "$build" --target photon_cli photon_compare
photon=$root/$build/photon
compare=$root/$build/photon-compare
work=$root/$build/povray-accuracy
mkdir -p "$work/judges" docs/accuracy-vs-povray docs/images/accuracy
photon_key=$(sha256sum "$photon" | cut -c1-16)
[ "$reuse_judges" = yes ] && photon_key=any
pov_version=$(povray --version 2>&1 | sed -n 's/^POV-Ray \([0-9.]*[0-9]\).*/\1/p' | head -1)

# Runs the command after NAME, output and log in $work/NAME.log, and sets `cpu` to its CPU time
# (user + sys of the command and its threads, from GNU time).
timed() {
  local name=$1
  shift
  /usr/bin/time -f "%U %S" -o "$work/$name.cpu" "$@" >"$work/$name.log" 2>&1 ||
    { tail -20 "$work/$name.log" >&2; echo "povray-accuracy-study: $name failed" >&2; exit 1; }
  cpu=$(awk '{ printf "%.2f", $1 + $2 }' "$work/$name.cpu")
}
# The relative MSE of image A against judge B.
relative_mse() {
  "$compare" "$scene_file" "$1" "$2" --relative-mse "$work/$tag.rel" >/dev/null 2>&1 ||
    { echo "povray-accuracy-study: photon-compare $1 $2 failed" >&2; exit 1; }
  cat "$work/$tag.rel"
}

# The judge of the current scene: $judge (the mean image) and $judge_floor, cached.
make_judge() {
  local args key dir
  if grep -q "photons *{ *target" "$scene_file"; then
    args=(--mode sppm --passes "$judge_passes" --photons-per-pass "$judge_photons")
  else
    args=(--mode reference --spp "$judge_spp")
  fi
  args+=(--ray-depth 64 --photon-depth 100 --width "$width" --height "$height" --threads "$threads")
  key=$( (sha256sum "$scene_file" | cut -c1-64; echo "$photon_key ${args[*]}") | sha256sum | cut -c1-12)
  dir=$work/judges/$scene-${width}x$height-$key
  judge=$dir/judge.exr
  judge_what="photon ${args[1]} ${args[2]} ${args[3]}"
  [ "${args[1]}" = sppm ] && judge_what+=" x ${args[5]} photons"
  judge_what+=", seeds 1 and 2, camera paths to depth 64"
  if [ ! -f "$dir/floor.txt" ]; then
    mkdir -p "$dir"
    for seed in 1 2; do
      echo "   judge seed $seed: ${args[*]}"
      timed "judge-$tag-$seed" "$photon" render "$scene_file" "${args[@]}" --seed "$seed" -o "$dir/seed$seed.exr"
      echo "$cpu" >"$dir/seed$seed.cpu"
    done
    oiiotool "$dir/seed1.exr" "$dir/seed2.exr" --add --mulc 0.5 -o "$judge"
    # The seeds' difference is twice the noise of their mean: a quarter of their relative MSE.
    relative_mse "$dir/seed1.exr" "$dir/seed2.exr" | awk '{ printf "%.3g\n", $1 / 4 }' >"$dir/floor.txt"
  fi
  judge_floor=$(cat "$dir/floor.txt")
  judge_cpu=$(cat "$dir/seed1.cpu" "$dir/seed2.cpu" | awk '{ s += $1 } END { printf "%.0f", s }')
}

# The runs: series | label | arguments (photon) or preset:trace level (POV-Ray).
pm_runs() {
  if [ "$budgets" = small ]; then
    printf '%s\n' "fg64 50k|--final-gather 64 --global-photons 50000 --irradiance-cache 0.4" \
      "fg128 100k|--final-gather 128 --global-photons 100000" "default|" \
      "fg1024 1M|--final-gather 1024 --global-photons 1000000" "default spp16|--spp 16"
    return
  fi
  printf '%s\n' \
    "fg64 50k ic0.4|--final-gather 64 --global-photons 50000 --irradiance-cache 0.4" \
    "fg64 200k|--final-gather 64" \
    "fg128 100k|--final-gather 128 --global-photons 100000" \
    "fg64 100k spp36|--final-gather 64 --global-photons 100000 --spp 36" \
    "default (fg256 200k ic0.2)|" \
    "fg256 1M|--global-photons 1000000" \
    "fg256 ic0.1|--irradiance-cache 0.1" \
    "fg1024 1M|--final-gather 1024 --global-photons 1000000" \
    "fg1024 1M ic0.1|--final-gather 1024 --global-photons 1000000 --irradiance-cache 0.1" \
    "fg128 100k spp16|--final-gather 128 --global-photons 100000 --spp 16" \
    "default spp16|--spp 16" \
    "fg256 ic0.1 spp36|--irradiance-cache 0.1 --spp 36"
}
sppm_runs() { if [ "$budgets" = small ]; then echo "4 16"; else echo "4 16 64 256 1024 2048"; fi; }
reference_runs() { if [ "$budgets" = small ]; then echo "16 64"; else echo "16 64 256 1024"; fi; }
pov_runs() { if [ "$budgets" = small ]; then echo "normal:10 hq:10"; else echo "normal:4 normal:10 hq:4 hq:10"; fi; }

# Appends one row to the scene's CSV and prints it.
record() {  # SERIES LABEL CPU IMAGE
  local rel net
  rel=$(relative_mse "$4" "$judge")
  net=$(awk -v r="$rel" -v f="$judge_floor" 'BEGIN { printf "%.4g", r - f }')
  printf '%s,%s,%s,%s,%s,%s\n' "$scene" "$1" "\"$2\"" "$3" "$rel" "$net" >>"$csv"
  printf '   %-10s %-28s %8s CPU-s  relative MSE %s (net %s)\n' "$1" "$2" "$3" "$rel" "$net"
}

source "$root/scripts/doc-block.sh"
cpu_model=$(sed -n 's/^model name[[:space:]]*: //p' /proc/cpuinfo | head -1)
for entry in "${scene_list[@]}"; do
  scene=${entry%%=*}
  scene_size=$size
  [[ $entry == *=* ]] && scene_size=${entry#*=}
  width=${scene_size%x*} height=${scene_size#*x}
  scene_file=$root/examples/scenes/$scene.pov
  tag=$scene-$scene_size
  csv=docs/accuracy-vs-povray/$tag.csv
  echo "== $scene, ${width}x$height"
  make_judge
  echo "   judge: $judge_what, $judge_cpu CPU-s; noise floor (relative MSE) $judge_floor"
  # A series not swept this time keeps its rows from an earlier run (same judge: same floor).
  kept=""
  [ -f "$csv" ] && kept=$(awk -F, -v s=",$sweep," 'NR > 1 && index(s, "," $2 ",") == 0' "$csv")
  echo "scene,series,setting,cpu_s,relative_mse,net_relative_mse" >"$csv"
  [ -z "$kept" ] || echo "$kept" >>"$csv"
  base=(render "$scene_file" --width "$width" --height "$height" --threads "$threads" --seed 7)  # not a judge's seed
  if sweeps pm; then
    while IFS='|' read -r label options; do
      name=$tag-pm-${label%% (*}; name=${name// /-}
      # --no-error-estimate: the image alone, as POV-Ray renders it (photon render's pm also runs a
      # short sppm run to estimate its error, about a tenth of pm's time again; docs/accuracy.md).
      # shellcheck disable=SC2086  # options are words
      timed "$name" "$photon" "${base[@]}" --mode pm --no-error-estimate --ray-depth 10 $options -o "$work/$name.exr"
      record pm "$label" "$cpu" "$work/$name.exr"
    done < <(pm_runs)
  fi
  if sweeps sppm; then
    for passes in $(sppm_runs); do
      name=$tag-sppm-$passes
      timed "$name" "$photon" "${base[@]}" --mode sppm --ray-depth 64 --passes "$passes" \
        --photons-per-pass "$judge_photons" -o "$work/$name.exr"
      record sppm "$passes passes" "$cpu" "$work/$name.exr"
    done
  fi
  if sweeps reference; then
    for spp in $(reference_runs); do
      name=$tag-reference-$spp
      timed "$name" "$photon" "${base[@]}" --mode reference --ray-depth 64 --spp "$spp" -o "$work/$name.exr"
      record reference "$spp spp" "$cpu" "$work/$name.exr"
    done
  fi
  if sweeps povray; then
    # POV-Ray reads the preset (examples/scenes/povray/, recursion_limit 10 as in
    # docs/povray-comparison.md), then the scene, then the trace level that overrides the scene's.
    photons=""
    grep -q "photons *{ *target" "$scene_file" && photons=phot
    for run in $(pov_runs); do
      preset=${run%%:*} level=${run#*:}
      inc=$root/examples/scenes/povray/rad${photons}${preset/normal/}.inc
      inc=${inc/radhq/rad_hq} inc=${inc/radphothq/radphot_hq}
      name=$tag-povray-$preset-$level
      printf '#version 3.7;\n#include "%s"\n#include "%s"\nglobal_settings { max_trace_level %s }\n' \
        "$inc" "$scene_file" "$level" >"$work/$name.pov"
      timed "$name" povray -D +W"$width" +H"$height" +A0.3 +AM2 +R3 +WT"$threads" +FE \
        +I"$work/$name.pov" +O"$work/$name.exr"
      label="$([ "$preset" = hq ] && echo IndoorHQ || echo Normal)${photons:+ + photons}, trace $level"
      record povray "$label" "$cpu" "$work/$name.exr"
    done
  fi
  /usr/bin/python3 scripts/povray-accuracy-plot.py "$csv" "docs/images/accuracy/$tag-vs-povray.png" \
    "$scene ${width}x$height" "$judge_floor" >"$work/$tag-summary.md"
  # Each scene and size has its own block in the document, so that runs of a few scenes add up.
  text=$(
    echo "<!-- povray-accuracy $tag: begin (written by scripts/povray-accuracy-study.sh) -->"
    echo
    echo "### $scene (${width}x$height)"
    echo
    echo "photon $(git rev-parse --short HEAD)$(git diff --quiet HEAD -- include dsl src tools || echo ' (modified)')," \
      "POV-Ray $pov_version, $threads threads each on $(nproc) cores ($cpu_model), $(date -u '+%Y-%m-%d %H:%M') UTC;" \
      "load average when the scene was done: $(uptime | sed 's/.*load average: //') (the machine is shared; CPU time is what is compared)." \
      "Judge: $judge_what ($judge_cpu CPU-s); its noise floor, a relative MSE of $judge_floor, is part of every measured error" \
      "(subtracted in the plot and the first table: the net column). Data: [accuracy-vs-povray/$tag.csv](accuracy-vs-povray/$tag.csv)."
    echo
    echo "![$scene: relative MSE against CPU time](images/accuracy/$tag-vs-povray.png)"
    echo
    cat "$work/$tag-summary.md"
    echo
    echo "<!-- povray-accuracy $tag: end -->"
  )
  (flock 9; replace_doc_block "$doc" "povray-accuracy $tag" "$text") 9>"$work/doc.lock"  # runs side by side
  echo "   wrote $csv, docs/images/accuracy/$tag-vs-povray.png and its block in $doc"
done
echo "== done; renders and logs in $work"
