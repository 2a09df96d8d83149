#!/bin/sh
# SPDX-License-Identifier: MIT
# `mpirun -n N photon render` writes the image one process writes, pixel for pixel exactly (the
# files differ only in the DateTime OpenImageIO stamps; oiiotool --diff with threshold 0), for N = 1, 2, 3
# (same seed), in one mode; the scene and settings make the mode run every phase it shares
# (pm: both photon passes, the precomputed irradiance and the irradiance cache). Each rank runs
# one thread, the one-process render two: the image depends on neither.
#   mpi_same_image_test.sh PHOTON MPIRUN|none SCENES_DIR MODE WORKDIR
photon=$1 mpirun=$2 scenes=$3 mode=$4 work=$5
if [ "$mpirun" = none ]; then
    echo "SKIP: photon was built without MPI (configure with -DPHOTON_MPI=ON; scripts/install-deps.sh test installs Open MPI)"
    exit 77
fi
rm -rf "$work" && mkdir -p "$work" || exit 1
failures=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }

case $mode in
  pm) scene=cornell args="--width 48 --height 36 --global-photons 20000 --caustic-photons 20000"
      phases="photons precompute irradiance.cache image" ;;
  rt) scene=cornell args="--width 48 --height 36 --spp 4" phases="image" ;;
  # Progress lines per pass: every pass's image is judged from every rank's pixels.
  sppm) scene=cornell args="--width 48 --height 36 --passes 5 --photons-per-pass 5000" phases="sppm.photons sppm.pixels" ;;
  # A budget: rounds until the estimated error is at most 50%, judged from every rank's rows.
  reference) scene=cornell args="--width 48 --height 36 --spp 4 --target-error 50%" phases="reference.sums" ;;
  *) echo "unknown mode $mode"; exit 1 ;;
esac

# shellcheck disable=SC2086  # $args is a list of options
"$photon" render "$scenes/$scene.pov" -o "$work/one.exr" --mode "$mode" --threads 2 $args >"$work/one.log" 2>&1 ||
    { fail "one-process render failed"; cat "$work/one.log"; exit 1; }
for n in 1 2 3; do
    # shellcheck disable=SC2086
    "$mpirun" --oversubscribe --allow-run-as-root -n $n "$photon" render "$scenes/$scene.pov" -o "$work/ranks$n.exr" \
        --mode "$mode" --threads 1 $args >"$work/ranks$n.log" 2>&1 ||
        { fail "mpirun -n $n failed"; cat "$work/ranks$n.log"; continue; }
    oiiotool -q "$work/one.exr" "$work/ranks$n.exr" --fail 0 --failpercent 0 --warn 0 --diff >"$work/diff$n.txt" 2>&1 ||
        { fail "$mode: mpirun -n $n wrote a different image than one process"; cat "$work/diff$n.txt"; }
    [ $n -eq 1 ] && continue
    grep -q "exchanges ($n ranks" "$work/ranks$n.log" || fail "$mode: no exchange statistics from mpirun -n $n"
    for phase in $phases; do
        grep -q "^  $phase  *[0-9]* calls" "$work/ranks$n.log" || fail "$mode: no exchange of phase '$phase' with $n ranks"
    done
done
[ $failures -eq 0 ] && echo "mpirun -n 1, 2, 3: the one-process image ($mode), pixel for pixel"
[ $failures -eq 0 ]
