#!/bin/sh
# SPDX-License-Identifier: MIT
# photon-compare end to end on a small Cornell box: an image against itself (RMSE 0), against a
# copy scaled by 0.8 (every ratio 1.25, the walls found and non-empty), and bad input (different
# sizes, malformed regions) rejected with a message and exit status 1.
#   compare_test.sh PHOTON PHOTON_COMPARE SCENES_DIR WORKDIR
photon=$1 compare=$2 scenes=$3 work=$4
rm -rf "$work" && mkdir -p "$work" || exit 1
failures=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }
scene=$scenes/cornell.pov
walls="--region floor=-1.2,-0.001,-1.2,1.2,0.001,1.2,+y --region ceiling=-1.2,1.799,-1.2,1.2,1.801,1.2,-y
       --region back=-1.2,0,1.199,1.2,1.8,1.201,-z --region left=-1.201,0,-1.2,-1.199,1.8,1.2,+x
       --region right=1.199,0,-1.2,1.201,1.8,1.2,-x"

"$photon" render "$scene" --mode rt --width 80 --height 60 --spp 1 --shadow-samples 4 -q -o "$work/a.exr" || exit 1
"$photon" render "$scene" --mode rt --width 40 --height 30 --spp 1 --shadow-samples 1 -q -o "$work/small.exr" || exit 1
oiiotool "$work/a.exr" --mulc 0.8 -o "$work/b.exr" || exit 1

# shellcheck disable=SC2086
"$compare" "$scene" "$work/a.exr" "$work/a.exr" $walls --summary "$work/same.tsv" >"$work/same.md" 2>"$work/err" ||
    fail "same image: exit status $?"
cut -f1 "$work/same.tsv" | grep -qx "0.0000" || fail "same image: RMSE $(cut -f1 "$work/same.tsv")"

# shellcheck disable=SC2086
"$compare" "$scene" "$work/a.exr" "$work/b.exr" $walls --side-by-side "$work/sbs.jpg" --mask "$work/mask.png" \
    >"$work/scaled.md" 2>"$work/err" || fail "scaled image: exit status $?"
for wall in "whole image" floor ceiling back left right; do
    row=$(grep "^| $wall |" "$work/scaled.md")
    [ -n "$row" ] || { fail "no row for $wall"; continue; }
    pixels=$(echo "$row" | cut -d'|' -f3 | tr -d ' ')
    ratio=$(echo "$row" | cut -d'|' -f6 | tr -d ' ')
    [ "$pixels" -gt 100 ] || fail "$wall: only $pixels pixels"
    # 25% apart: outside the 10% target, so marked **.
    [ "$ratio" = "1.250**" ] || fail "$wall: ratio $ratio, expected 1.250**"
done
# The walls cover most of the picture but not the spheres, the edges or the open front.
total=$(grep "^| [a-z]" "$work/scaled.md" | grep -v "whole image" | cut -d'|' -f3 | awk '{ s += $1 } END { print s }')
[ "$total" -gt 2400 ] && [ "$total" -lt 4200 ] || fail "walls cover $total of 4800 pixels"
[ -s "$work/sbs.jpg" ] && [ -s "$work/mask.png" ] || fail "pictures not written"

"$compare" "$scene" "$work/a.exr" "$work/small.exr" >"$work/out" 2>"$work/err" && fail "different sizes accepted"
grep -q "80x60 but .*40x30" "$work/err" || { fail "different sizes: message"; cat "$work/err"; }
for bad in "floor=1,2,3" "=0,0,0,1,1,1,+y" "floor=0,0,0,1,1,1,y" "floor=0,0,zero,1,1,1,+y"; do
    "$compare" "$scene" "$work/a.exr" "$work/b.exr" --region "$bad" >"$work/out" 2>"$work/err" && fail "region $bad accepted"
    grep -q "^photon-compare: error: --region" "$work/err" || { fail "region $bad: message"; cat "$work/err"; }
done

[ $failures -eq 0 ] && echo "photon-compare: all checks passed"
exit $((failures > 0))
