#!/bin/sh
# SPDX-License-Identifier: MIT
# A rank killed in the middle of `mpirun -n 2 photon render`: the run exits non-zero, says which
# rank died, and the image already at the output path is left as it was (rank 0 alone writes,
# to a temporary sibling renamed when complete, and it never gets that far).
#   mpi_rank_dies_test.sh PHOTON MPIRUN|none SCENES_DIR WORKDIR
photon=$1 mpirun=$2 scenes=$3 work=$4
if [ "$mpirun" = none ]; then
    echo "SKIP: photon was built without MPI (configure with -DPHOTON_MPI=ON; scripts/install-deps.sh test installs Open MPI)"
    exit 77
fi
rm -rf "$work" && mkdir -p "$work" || exit 1
failures=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }

"$photon" render "$scenes/cornell.pov" -o "$work/out.exr" --mode rt --width 40 --height 30 --spp 1 -q ||
    fail "small render failed"
cp "$work/out.exr" "$work/keep.exr"

# A render of minutes, so that the kill lands in it.
"$mpirun" --oversubscribe --allow-run-as-root -n 2 "$photon" render "$scenes/cornell.pov" -o "$work/out.exr" \
    --mode reference --width 400 --height 300 --spp 256 --threads 1 >"$work/log" 2>&1 &
launcher=$!
victim=
tries=0
while [ -z "$victim" ]; do  # rank 1: the child of the launcher whose environment says so
    tries=$((tries + 1))
    [ $tries -gt 300 ] && break
    sleep 0.1
    for pid in $(pgrep -P $launcher); do
        tr '\0' '\n' <"/proc/$pid/environ" 2>/dev/null | grep -qx "OMPI_COMM_WORLD_RANK=1" && victim=$pid
    done
done
if [ -z "$victim" ]; then
    fail "rank 1 never started"; kill $launcher 2>/dev/null
else
    sleep 1  # inside the render: the scene is parsed in well under a second
    kill -KILL "$victim"
fi
wait $launcher
status=$?
[ $status -ne 0 ] || fail "mpirun exited 0 though rank 1 was killed"
grep -qi "rank 1" "$work/log" || { fail "no message naming the dead rank"; cat "$work/log"; }
cmp -s "$work/out.exr" "$work/keep.exr" || fail "the existing image was replaced"
leftover=$(ls "$work" | grep -v -x -e out.exr -e keep.exr -e log)
[ -z "$leftover" ] || fail "files left behind: $leftover"
[ $failures -eq 0 ] && { echo "killed rank 1: mpirun exit status $status, and:"; grep -i "rank 1" "$work/log" | head -3; }
[ $failures -eq 0 ]
