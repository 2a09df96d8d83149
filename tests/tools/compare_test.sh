#!/bin/sh
# SPDX-License-Identifier: MIT
# photon-compare end to end on a small Cornell box: an image against itself (RMSE 0), against a
# copy scaled by 0.8 (every ratio 1.25, the walls found and non-empty), --block separating noise
# (two seeds: block RMSE far below pixel RMSE) from bias (the scaled copy: about equal), and bad
# input (different sizes, malformed regions, a block larger than the image) rejected with a
# message and exit status 1.
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
"$photon" render "$scene" --mode rt --width 80 --height 60 --spp 1 --shadow-samples 4 --seed 9 -q -o "$work/seed.exr" || exit 1
oiiotool "$work/a.exr" --mulc 0.8 -o "$work/b.exr" || exit 1

# shellcheck disable=SC2086
"$compare" "$scene" "$work/a.exr" "$work/a.exr" $walls --summary "$work/same.tsv" >"$work/same.md" 2>"$work/err" ||
    fail "same image: exit status $?"
cut -f1 "$work/same.tsv" | grep -qx "0.0000" || fail "same image: RMSE $(cut -f1 "$work/same.tsv")"
[ "$(awk -F'\t' '{ print NF }' "$work/same.tsv")" = 4 ] || fail "summary without --block: not 4 fields"

# --block: the summary gains block RMSE, the worst region's A / B - 1 and its name.
# shellcheck disable=SC2086
"$compare" "$scene" "$work/a.exr" "$work/a.exr" $walls --block 8 --summary "$work/same8.tsv" >/dev/null 2>&1 ||
    fail "same image, --block: exit status $?"
IFS='	' read -r _ _ _ _ block bias region <"$work/same8.tsv"
[ "$block" = 0.0000 ] && [ "$bias" = 0.0000 ] && [ -n "$region" ] || fail "same image, --block: $(cat "$work/same8.tsv")"
# shellcheck disable=SC2086
"$compare" "$scene" "$work/a.exr" "$work/b.exr" $walls --block 8 --summary "$work/scaled8.tsv" >/dev/null 2>&1 ||
    fail "scaled image, --block: exit status $?"
IFS='	' read -r rmse _ _ _ block bias region <"$work/scaled8.tsv"
[ "$bias" = 0.2500 ] || fail "scaled image: worst bias $bias, expected 0.2500"
# A 25% bias survives block averaging (less its sharp edges); differing noise (another seed) mostly
# does not.
awk -v r="$rmse" -v b="$block" 'BEGIN { exit !(b > 0.6 * r && b <= r) }' || fail "scaled image: block RMSE $block, RMSE $rmse"
# shellcheck disable=SC2086
"$compare" "$scene" "$work/a.exr" "$work/seed.exr" $walls --block 8 --summary "$work/seed8.tsv" >/dev/null 2>&1 ||
    fail "other seed, --block: exit status $?"
IFS='	' read -r rmse _ _ _ block bias region <"$work/seed8.tsv"
awk -v r="$rmse" -v b="$block" 'BEGIN { exit !(r > 0 && b < 0.4 * r) }' || fail "other seed: block RMSE $block, RMSE $rmse"
"$compare" "$scene" "$work/a.exr" "$work/b.exr" --block 61 >"$work/out" 2>"$work/err" && fail "block 61 accepted"
grep -q "block 61 is larger than the 80x60" "$work/err" || { fail "block 61: message"; cat "$work/err"; }

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
