#!/usr/bin/env bash
# How good is the error every sppm and reference render reports? For each scene, renders a judge
# (sppm, JUDGE_PASSES passes, two seeds: its own noise is the estimate of their mean), then each
# mode at three budgets, and compares the reported normalised MSE with the true one against the
# judge (the judge's own estimated error subtracted). Prints a Markdown table (docs/accuracy.md).
#   scripts/error-estimate-study.sh [build-dir]       (default build/; needs photon and /usr/bin/python3
#                                                      with python3-numpy and python3-openimageio)
# Every render follows camera paths to depth 64, as the path tracer ignores max_trace_level.
# Environment: SIZE (default 80x60), JUDGE_PASSES (1024), PHOTONS (20000 per sppm pass), SCENES.
set -euo pipefail
cd "$(dirname "$0")/.."
build=${1:-build}
photon=$build/photon
size=${SIZE:-80x60}
width=${size%x*} height=${size#*x}
judge_passes=${JUDGE_PASSES:-1024}
photons=${PHOTONS:-20000}
scenes=${SCENES:-"examples/scenes/cornell.pov examples/scenes/room1.pov examples/scenes/classes/diffuse-ball.pov"}
out=${OUT:-$build/error-estimate-study}
mkdir -p "$out"

render() {  # NAME SCENE ARGS...: renders NAME.exr, prints the reported normalised MSE
    local name=$1 scene=$2
    shift 2
    "$photon" render "$scene" -o "$out/$name.exr" --width "$width" --height "$height" --threads 0 --ray-depth 64 "$@" \
        >"$out/$name.txt" 2>"$out/$name.log"
    sed -n 's/.*estimated error .*normalised MSE \([0-9.e+-]*\)).*/\1/p' "$out/$name.txt"
}

nmse() {  # A JUDGE: the normalised MSE of A against JUDGE
    /usr/bin/python3 - "$1" "$2" <<'EOF'
import sys, numpy as np, OpenImageIO as oiio
a, j = (oiio.ImageBuf(p).get_pixels(oiio.FLOAT)[..., :3].astype(np.float64) for p in sys.argv[1:3])
print(f"{((a - j) ** 2).sum() / (j ** 2).sum():.4g}")
EOF
}

echo "| scene | mode | budget | estimated | true (judge noise subtracted) | estimated / true | render time |"
echo "|---|---|---|---:|---:|---:|---:|"
for scene in $scenes; do
    base=$(basename "$scene" .pov)
    judge_args=(--mode sppm --passes "$judge_passes" --photons-per-pass "$photons" --photon-depth 100)
    render "$base-judge1" "$scene" "${judge_args[@]}" --seed 101 >/dev/null
    render "$base-judge2" "$scene" "${judge_args[@]}" --seed 102 >/dev/null
    # The judge is the mean of the two runs; its noise, from their difference, is subtracted.
    /usr/bin/python3 - "$out/$base-judge1.exr" "$out/$base-judge2.exr" "$out/$base-judge.exr" <<'EOF'
import sys, numpy as np, OpenImageIO as oiio
a, b = (oiio.ImageBuf(p).get_pixels(oiio.FLOAT) for p in sys.argv[1:3])
oiio.ImageBuf(((a + b) / 2).astype(np.float32)).write(sys.argv[3])
EOF
    judge_noise=$(nmse "$out/$base-judge1.exr" "$out/$base-judge2.exr")
    judge_noise=$(echo "$judge_noise" | awk '{printf "%.6g", $1 / 4}')  # ((a-b)/2)^2 / judge^2
    for mode in sppm reference; do
        for budget in 4 16 64; do
            if [ "$mode" = sppm ]; then args=(--mode sppm --passes "$budget" --photons-per-pass "$photons" --photon-depth 100)
            else args=(--mode reference --spp "$budget"); fi
            estimated=$(render "$base-$mode-$budget" "$scene" "${args[@]}" --seed 1)
            truth=$(nmse "$out/$base-$mode-$budget.exr" "$out/$base-judge.exr")
            net=$(awk -v t="$truth" -v j="$judge_noise" 'BEGIN {printf "%.4g", t - j}')
            ratio=$(awk -v e="$estimated" -v t="$net" 'BEGIN {if (t > 0) printf "%.2f", e / t; else print "-"}')
            seconds=$(sed -n 's/.*render \([0-9.]*\) s, total.*/\1/p' "$out/$base-$mode-$budget.txt")
            echo "| $base | $mode | $budget $([ "$mode" = sppm ] && echo passes || echo spp) | $estimated | $net (judge $judge_noise) | $ratio | ${seconds} s |"
        done
    done
done
