#!/bin/sh
# SPDX-License-Identifier: MIT
# Ctrl-C on `photon render`: exit status 130, the image so far written and marked
# photon:partial=true in its metadata; a finished image at the same path is never replaced (the
# partial one goes next to it as NAME.partial.EXT).
#   cli_interrupt_test.sh PHOTON SCENES_DIR WORKDIR
photon=$1 scenes=$2 work=$3
rm -rf "$work" && mkdir -p "$work" || exit 1
failures=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }

# interrupt OUTPUT: starts a long render to OUTPUT, sends SIGINT once the image pass has reported
# progress (so the handler is installed, whatever the build's speed), and returns its exit status.
# (A shell reports death by SIGINT as 130 too: the PARTIAL message tells the two apart.)
interrupt() {
    rm -f "$work/err"  # a fresh file: the previous run's progress must not trigger this one
    : >"$work/err"
    "$photon" render "$scenes/cornell.pov" -o "$1" --mode rt --width 800 --height 600 --spp 64 \
        --shadow-samples 4 --no-stats >"$work/out" 2>"$work/err" &
    pid=$!
    tries=0
    until grep -q "rendering [0-9]*%" "$work/err"; do
        tries=$((tries + 1))
        if [ $tries -gt 1200 ] || ! kill -0 $pid 2>/dev/null; then
            fail "no progress from the render"; cat "$work/err"; kill -KILL $pid 2>/dev/null; return 1
        fi
        sleep 0.1
    done
    kill -INT $pid
    wait $pid
}

has_oiiotool=false
command -v oiiotool >/dev/null 2>&1 && has_oiiotool=true
partial_is() {  # partial_is FILE true|false
    $has_oiiotool || return 0
    oiiotool --info -v "$1" | grep -q "photon:partial: \"$2\"" || fail "$1: not marked photon:partial=$2"
}

# A new path: the partial image is written there.
interrupt "$work/new.png"
status=$?
[ $status -eq 130 ] || { fail "interrupted render: exit status $status, expected 130"; cat "$work/err"; }
[ -s "$work/new.png" ] || fail "no image written on interrupt"
grep -q "PARTIAL" "$work/err" || fail "partial image not reported"
partial_is "$work/new.png" true
ls "$work" | grep -q "tmp" && fail "a temporary file was left behind"

# An existing image: kept byte for byte, the partial image goes next to it.
"$photon" render "$scenes/cornell.pov" -o "$work/done.png" --mode rt --width 40 --height 30 --spp 1 \
    --shadow-samples 1 -q || fail "small render failed"
partial_is "$work/done.png" false
cp "$work/done.png" "$work/keep.png"
interrupt "$work/done.png"
status=$?
[ $status -eq 130 ] || { fail "interrupted render: exit status $status, expected 130"; cat "$work/err"; }
grep -q "PARTIAL" "$work/err" || fail "partial image not reported (killed before the handler was installed?)"
cmp -s "$work/done.png" "$work/keep.png" || fail "the finished image was replaced by a partial one"
[ -s "$work/done.partial.png" ] || fail "no done.partial.png"
partial_is "$work/done.partial.png" true

[ $failures -eq 0 ] && echo "all interrupt checks passed"
exit $failures
