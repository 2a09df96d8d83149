#!/usr/bin/env bash
# How good is the error every pm, sppm and reference render reports? For each scene, renders a
# judge (sppm, JUDGE_PASSES passes, two seeds: its own noise is the estimate of their mean), then
# each mode at three budgets, and compares the reported normalised MSE with the true one against
# the judge (the judge's own estimated error subtracted). pm's budgets are global photon counts
# (PM_PHOTONS), its estimate against its own short sppm run (integrator/pm_error.hpp), whose
# passes the budget column adds. Prints a Markdown table (docs/accuracy.md).
#   scripts/error-estimate-study.sh [build-dir]       (default build/; needs photon and /usr/bin/python3
#                                                      with python3-numpy, and python3-openimageio or oiiotool)
# Every render follows camera paths to depth 64, as the path tracer ignores max_trace_level.
# Environment: SIZE (default 80x60), JUDGE_PASSES (1024), PHOTONS (20000 per sppm pass), SCENES,
# MODES (default "pm sppm reference"), PM_PHOTONS (default "10000 40000 160000"), OUT, KEEP_JUDGE.
set -euo pipefail
cd "$(dirname "$0")/.."
build=${1:-build}
photon=$build/photon
size=${SIZE:-80x60}
width=${size%x*} height=${size#*x}
judge_passes=${JUDGE_PASSES:-1024}
photons=${PHOTONS:-20000}
scenes=${SCENES:-"examples/scenes/cornell.pov examples/scenes/room1.pov examples/scenes/classes/diffuse-ball.pov"}
modes=${MODES:-"pm sppm reference"}
pm_photons=${PM_PHOTONS:-"10000 40000 160000"}
out=${OUT:-$build/error-estimate-study}
mkdir -p "$out"

render() {  # NAME SCENE ARGS...: renders NAME.exr, prints the reported normalised MSE
    local name=$1 scene=$2
    shift 2
    "$photon" render "$scene" -o "$out/$name.exr" --width "$width" --height "$height" --threads 0 --ray-depth 64 "$@" \
        >"$out/$name.txt" 2>"$out/$name.log"
    sed -n 's/.*estimated error .*normalised MSE \([0-9.e+-]*\)).*/\1/p' "$out/$name.txt"
}

# Reads an image as float RGB: with OpenImageIO's Python module, or a channel at a time through
# oiiotool and a 32-bit float TIFF, which PIL reads.
read_image_py='
import os, subprocess, sys, tempfile, numpy as np
def read_image(path):
    try:
        import OpenImageIO as oiio
        return oiio.ImageBuf(path).get_pixels(oiio.FLOAT)[..., :3].astype(np.float64)
    except ImportError:
        from PIL import Image
        channels = []
        with tempfile.TemporaryDirectory() as d:
            for c in "RGB":
                tif = os.path.join(d, c + ".tif")
                subprocess.run(["oiiotool", path, "--ch", c, "-d", "float", "-o", tif], check=True)
                channels.append(np.asarray(Image.open(tif), dtype=np.float64))
        return np.stack(channels, axis=-1)
'

nmse() {  # A JUDGE: the normalised MSE of A against JUDGE (a .npy: the judges' mean)
    /usr/bin/python3 - "$1" "$2" <<EOF
$read_image_py
a = read_image(sys.argv[1])
j = np.load(sys.argv[2]) if sys.argv[2].endswith(".npy") else read_image(sys.argv[2])
print(f"{((a - j) ** 2).sum() / (j ** 2).sum():.4g}")
EOF
}

echo "| scene | mode | budget | estimated | true (judge noise subtracted) | estimated / true | render time |"
echo "|---|---|---|---:|---:|---:|---:|"
for scene in $scenes; do
    base=$(basename "$scene" .pov)
    judge_args=(--mode sppm --passes "$judge_passes" --photons-per-pass "$photons" --photon-depth 100)
    for seed in 101 102; do  # KEEP_JUDGE=1: the judges already in $out are kept
        [ -n "${KEEP_JUDGE:-}" ] && [ -s "$out/$base-judge$((seed - 100)).exr" ] ||
            render "$base-judge$((seed - 100))" "$scene" "${judge_args[@]}" --seed $seed >/dev/null
    done
    # The judge is the mean of the two runs; its noise, from their difference, is subtracted.
    /usr/bin/python3 - "$out/$base-judge1.exr" "$out/$base-judge2.exr" "$out/$base-judge.npy" <<EOF
$read_image_py
np.save(sys.argv[3], (read_image(sys.argv[1]) + read_image(sys.argv[2])) / 2)
EOF
    judge_noise=$(nmse "$out/$base-judge1.exr" "$out/$base-judge2.exr")
    judge_noise=$(echo "$judge_noise" | awk '{printf "%.6g", $1 / 4}')  # ((a-b)/2)^2 / judge^2
    for mode in $modes; do
        budgets="4 16 64"
        [ "$mode" = pm ] && budgets=$pm_photons
        for budget in $budgets; do
            case $mode in
            sppm) args=(--mode sppm --passes "$budget" --photons-per-pass "$photons" --photon-depth 100) unit=passes ;;
            reference) args=(--mode reference --spp "$budget") unit=spp ;;
            pm) args=(--mode pm --global-photons "$budget" --photons-per-pass "$photons" --photon-depth 100) unit="global photons" ;;
            esac
            estimated=$(render "$base-$mode-$budget" "$scene" "${args[@]}" --seed 1)
            truth=$(nmse "$out/$base-$mode-$budget.exr" "$out/$base-judge.npy")
            net=$(awk -v t="$truth" -v j="$judge_noise" 'BEGIN {printf "%.4g", t - j}')
            ratio=$(awk -v e="$estimated" -v t="$net" 'BEGIN {if (t > 0) printf "%.2f", e / t; else print "-"}')
            if [ "$mode" = pm ]; then  # pm's image, then its judge's passes and the whole time
                unit="$unit, judge $(sed -n 's/.*short sppm run of \([0-9]*\) passes.*/\1/p' "$out/$base-$mode-$budget.txt") passes"
                seconds=$(sed -n 's/.*, total \([0-9.]*\) s.*/\1/p' "$out/$base-$mode-$budget.txt")
            else
                seconds=$(sed -n 's/.*render \([0-9.]*\) s, total.*/\1/p' "$out/$base-$mode-$budget.txt")
            fi
            echo "| $base | $mode | $budget $unit | $estimated | $net (judge $judge_noise) | $ratio | ${seconds} s |"
        done
    done
done
