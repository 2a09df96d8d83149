#!/bin/sh
# SPDX-License-Identifier: MIT
# The `photon` program end to end: help and usage errors, check, render, export-pov, errors with
# exit status 1, the output path and the memory needed checked before rendering, limits, --strict.
# (Ctrl-C is cli_interrupt_test.sh.)
#   cli_test.sh PHOTON SCENES_DIR WORKDIR
photon=$1 scenes=$2 work=$3
rm -rf "$work" && mkdir -p "$work" || exit 1
failures=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }
expect() {  # expect STATUS COMMAND...: run and compare the exit status
    want=$1; shift
    "$@" >"$work/out" 2>"$work/err"; got=$?
    [ "$got" -eq "$want" ] || { fail "exit status $got, expected $want: $*"; cat "$work/err"; }
}
tiny="--width 40 --height 30 --global-photons 2000 --caustic-photons 1000 --spp 1 --shadow-samples 1 --final-gather 4"

expect 0 "$photon" --help
grep -q "render" "$work/out" || fail "--help does not mention render"
expect 0 "$photon" render --help
grep -q -- "--global-photons" "$work/out" || fail "render --help does not list --global-photons"
expect 2 "$photon"
expect 2 "$photon" render "$scenes/cornell.pov"
expect 2 "$photon" render "$scenes/cornell.pov" -o "$work/x.png" --mode fast

for s in cornell recursive room1 room2; do
    expect 0 "$photon" check "$scenes/$s.pov"
    grep -q "^warnings   0" "$work/out" || fail "check $s: warnings"
done
grep -q "sphere light at <2.5, 4, 5>, radius 0.2, power 12566.4 W, intensity 1000 W/sr" "$work/out" || fail "check room2: light"
expect 0 "$photon" check -q "$scenes/room2.pov"
[ -s "$work/out" ] || [ -s "$work/err" ] && fail "check -q printed more than errors"
# The plan names what it drops by where the file writes it.
expect 0 "$photon" check "$scenes/plan/boxed-light.pov"
grep -q "dropped  *photons from light 1 (point light at <1.6, 0.35, 1>, [^)]*boxed-light.pov:39:1): inside object 2 (box, [^)]*boxed-light.pov:46:1)" "$work/out" ||
    { fail "check boxed-light: the dropped lamp and its crate not named by their places"; grep dropped "$work/out"; }

expect 0 "$photon" render "$scenes/cornell.pov" -o "$work/cornell.png" $tiny
[ -s "$work/cornell.png" ] || fail "no cornell.png"
grep -q "global map" "$work/out" || fail "no statistics table"
# Anti-aliasing by contrast is on in rt and pm unless told: more samples than --spp in some pixels
# (rounds of --aa-samples), never more than --aa-max-spp; --aa-contrast 0 --aa-threshold 0 takes
# --spp everywhere.
grep -q "^  samples per pixel  *mean [0-9.]*, most 10$" "$work/out" || { fail "pm: not anti-aliased by default"; grep "samples per pixel" "$work/out"; }
expect 0 "$photon" render "$scenes/cornell.pov" -o "$work/rt.exr" $tiny --mode rt --aa-max-spp 8
grep -q "^  samples per pixel  *mean [0-9.]*, most 8$" "$work/out" || { fail "rt: --aa-max-spp 8"; grep "samples per pixel" "$work/out"; }
expect 0 "$photon" render "$scenes/cornell.pov" -o "$work/rt.exr" $tiny --mode rt --aa-contrast 0 --aa-threshold 0
grep -q "^  samples per pixel  *mean 1.00, most 1$" "$work/out" || { fail "rt: --aa-contrast 0 --aa-threshold 0"; grep "samples per pixel" "$work/out"; }
expect 0 "$photon" render "$scenes/cornell.pov" -o "$work/rt.exr" $tiny --mode rt --aa-contrast 0
grep -q "^  samples per pixel  *mean [0-9.]*, most 16$" "$work/out" || { fail "rt: --aa-contrast 0 keeps the noise rounds"; grep "samples per pixel" "$work/out"; }
expect 1 "$photon" render "$scenes/cornell.pov" -o "$work/w.png" --aa-threshold -0.1
grep -q "photon: error: --aa-threshold: aa threshold must be >= 0, found -0.1" "$work/err" || { fail "aa threshold bound"; cat "$work/err"; }
expect 0 "$photon" render "$scenes/room1.pov" -o "$work/room1.exr" $tiny --mode rt -q
[ -s "$work/room1.exr" ] || fail "no room1.exr"
[ -s "$work/out" ] && fail "-q printed something"
expect 0 "$photon" render "$scenes/cornell.pov" -o "$work/reference.exr" $tiny --mode reference
grep -q "mode reference" "$work/out" || fail "--mode reference: not a reference render"
grep -q "photon: warning:" "$work/err" && fail "--mode reference: a warning for a scene with a sphere light only"

# Budgets and the error estimate (sppm and reference; pm below).
expect 0 "$photon" render "$scenes/cornell.pov" -o "$work/budget.exr" --width 24 --height 18 --mode sppm \
    --photons-per-pass 500 --target-error 20% --error-image "$work/budget-error.exr"
grep -q "stopped by  *target error" "$work/out" || fail "--target-error 20%: not stopped by the target"
grep -q "photon: sppm pass 2 (.*estimated error" "$work/err" || fail "--target-error: no pass line with the estimate"
[ -s "$work/budget-error.exr" ] || fail "--error-image: not written"
expect 0 "$photon" render "$scenes/cornell.pov" -o "$work/budget.exr" --width 24 --height 18 --mode reference \
    --spp 4 --time 1s
grep -q "stopped by  *time limit" "$work/out" || fail "--time 1s: not stopped by the time limit"
grep -q "estimated error  *relative RMSE" "$work/out" || fail "--time: no estimated error"
expect 2 "$photon" render "$scenes/cornell.pov" -o "$work/budget.exr" --time soon
expect 2 "$photon" render "$scenes/cornell.pov" -o "$work/budget.exr" --target-error x%
expect 1 "$photon" render "$scenes/cornell.pov" -o "$work/budget.exr" --target-error -1
expect 1 "$photon" render "$scenes/cornell.pov" -o "$work/nope.exr" $tiny --mode rt --error-image "$work/nope-error.exr"
grep -q "error-image: only the pm, sppm and reference modes" "$work/err" || fail "--error-image in rt: no clear error"
[ -e "$work/nope.exr" ] && fail "--error-image in rt: an image was written before the error"
# pm: its error against a short sppm run, and a budget of doubled photons written as it goes.
expect 0 "$photon" render "$scenes/cornell.pov" -o "$work/pm.exr" $tiny --photons-per-pass 2000 \
    --target-error 30% --error-image "$work/pm-error.exr"
grep -q "estimated error  *relative RMSE.*against a short sppm run of [0-9]* passes" "$work/out" || fail "pm: no estimated error"
grep -q "stopped by  *target error" "$work/out" || { fail "pm --target-error 30%: not stopped by the target"; cat "$work/out"; }
grep -q "photon: pm render 1 (.*estimated error" "$work/err" || fail "pm: no render line with the estimate"
[ -s "$work/pm.exr" ] && [ -s "$work/pm-error.exr" ] || fail "pm: image or error image not written"
# A target below what a 4-pass judge of 2,000 photons resolves ends when the estimate stalls (or,
# by chance, meets it), not after ever more doublings.
expect 0 "$photon" render "$scenes/cornell.pov" -o "$work/pm.exr" $tiny --photons-per-pass 2000 --target-error 5%
grep -q "stopped by  *\(estimate stalled\|target error\)" "$work/out" || { fail "pm --target-error 5%: did not stop on the estimate"; cat "$work/out"; }
expect 1 "$photon" render "$scenes/cornell.pov" -o "$work/nope.exr" $tiny --target-error 30% --no-error-estimate
grep -q "target-error: pm measures its error only with its estimate" "$work/err" || fail "pm --target-error without an estimate: no clear error"
expect 0 "$photon" render "$scenes/cornell.pov" -o "$work/pm.exr" $tiny --no-error-estimate
grep -q "estimated error" "$work/out" && fail "--no-error-estimate: an estimate all the same"
# A point light over glass: the reference cannot see its caustic and says so.
printf 'camera { location <0,1,-2> look_at <0,0,0> }\nlight_source { <0,2,0>, rgb 1 }\nplane { y, 0 pigment { rgb 0.5 } }\nsphere { <0,0.5,0>, 0.3 pigment { rgbf 1 } finish { reflection { 0, 1 fresnel on } } interior { ior 1.5 } }\n' >"$work/point.pov"
expect 0 "$photon" render "$work/point.pov" -o "$work/point.exr" $tiny --mode reference --no-mis
grep -q "photon: warning: mode reference cannot see light from point and area lights through mirrors or glass" "$work/err" ||
    fail "--mode reference: no warning for a point light over glass"
grep -q "no MIS" "$work/err" || fail "--no-mis: not in the settings line"

printf 'sphere { <0,0,0>, -1 }\n' >"$work/bad.pov"
expect 1 "$photon" render "$work/bad.pov" -o "$work/bad.png"
grep -q "bad.pov:1:19: error: sphere radius must be positive, found -1" "$work/err" || fail "error message"
[ -e "$work/bad.png" ] && fail "an image was written for a bad scene"

expect 1 "$photon" render "$scenes/cornell.pov" -o "$work/no/such/dir/x.png" $tiny
grep -q "does not exist" "$work/err" || fail "unwritable output not reported"
grep -q "rendering" "$work/err" && fail "rendered before checking the output path"
expect 1 "$photon" render "$scenes/cornell.pov" -o "$work/x.unknownformat" $tiny
if [ -d /proc ]; then  # accepts no new file, even from root
    expect 1 "$photon" render "$scenes/cornell.pov" -o /proc/photon-cli-test.png $tiny
    grep -q "cannot create a file in '/proc'" "$work/err" || fail "unwritable directory not reported"
    grep -q "rendering" "$work/err" && fail "rendered before checking the output directory"
fi

# Limits: the memory a render needs is checked before anything is allocated; samples and depths
# are bounded where they are written.
expect 1 "$photon" render "$scenes/cornell.pov" -o "$work/huge.png" --width 65536 --height 65536 \
    --global-photons 1000000000000
grep -q "photon: error: not enough memory: the render needs up to .* (film 96.0 GiB, photon maps" "$work/err" ||
    { fail "memory limit not reported"; cat "$work/err"; }
grep -v "photon: plan:" "$work/err" | grep -q "rendering\|global photons" && fail "started rendering before the memory check"
[ -e "$work/huge.png" ] && fail "an image was written for a render too large"
expect 1 "$photon" render "$scenes/cornell.pov" -o "$work/deep.png" $tiny --ray-depth 100000
grep -q "max ray depth must be from 1 to 256, found 100000" "$work/err" || { fail "ray depth limit"; cat "$work/err"; }
expect 1 "$photon" render "$scenes/cornell.pov" -o "$work/spp.png" --width 40 --height 30 --spp 4294967295
grep -q "samples per pixel must be from 1 to 1000000" "$work/err" || { fail "samples limit"; cat "$work/err"; }
# Every setting's bounds come from the settings table, named by the option, negative values included.
expect 1 "$photon" render "$scenes/cornell.pov" -o "$work/w.png" --width 0
grep -q "photon: error: --width: image width must be from 1 to 65536, found 0" "$work/err" || { fail "width bound"; cat "$work/err"; }
expect 1 "$photon" render "$scenes/cornell.pov" -o "$work/w.png" --spp -1
grep -q "photon: error: --spp: samples per pixel must be from 1 to 1000000, found -1" "$work/err" || { fail "negative spp"; cat "$work/err"; }
expect 1 "$photon" render "$scenes/cornell.pov" -o "$work/w.png" --global-radius -1
grep -q "photon: error: --global-radius: the estimate radius must be >= 0, found -1" "$work/err" || { fail "radius bound"; cat "$work/err"; }
expect 2 "$photon" render "$scenes/cornell.pov" -o "$work/w.png" --spp many

printf 'light_source { <0, 5, 0>, rgb 1 }\nsphere { 0, 1 normal { facets 0.5 } }\n' >"$work/warn.pov"
expect 0 "$photon" check "$work/warn.pov"
grep -q "warn.pov:2:24: warning: \`normal { facets }\` is ignored" "$work/err" || fail "warning not printed"
expect 1 "$photon" check --strict "$work/warn.pov"

# What photon reads but cannot render: warnings, a summary by kind, and errors under --strict.
printf 'camera { location -5 look_at 0 }\nlight_source { <0, 5, -5>, 1 fade_distance 1 fade_power 2 }\nrainbow { distance 5 }\novus { 1, 0.5 }\nlemon { <0, 0, 0>, <0, 1, 0>, 1, 2, 3 }\nsphere { 0, 1 pigment { square rgb 1, rgb 0, rgb 0.5, rgb 0.5 } finish { ambient 0 } }\nsphere { 0, 1 pigment { checker rgb 1, rgb 0 } finish { ambient 0 } }\n' >"$work/degraded.pov"
expect 0 "$photon" check "$work/degraded.pov"
grep -q "degraded.pov:4:1: warning: \`ovus\` is skipped: photon has no ovus yet" "$work/err" || fail "skipped ovus not reported"
grep -q "^           2 skipped object: 1 lemon, 1 ovus" "$work/out" || { fail "no summary of skipped objects"; cat "$work/out"; }
grep -q "^           1 approximated pigment: 1 square" "$work/out" || fail "no summary of approximated pigments (checker is evaluated)"
grep -q "^           1 ignored effect: 1 rainbow" "$work/out" || fail "no summary of ignored effects"
expect 1 "$photon" check --strict "$work/degraded.pov"
grep -q "photon: 4 warnings (--strict)" "$work/err" || { fail "--strict on degraded constructs"; cat "$work/err"; }

# The round shapes are objects, not skipped: `photon check` counts them by name.
printf 'camera { location -5 look_at 0 }\nlight_source { <0, 5, -5>, 1 fade_distance 1 fade_power 2 }\n#default { finish { ambient 0 } }\ncylinder { 0, y, 1 open }\ncone { 0, 1, y, 0 scale <1, 2, 1> }\ndisc { 0, y, 2, 1 }\ntorus { 2, 0.5 rotate 90*x }\n' >"$work/round.pov"
expect 0 "$photon" check --strict "$work/round.pov"
grep -q "^objects    4: 1 disc, 1 open cylinder, 1 transformed cone, 1 transformed torus;" "$work/out" || { fail "round shapes not built"; cat "$work/out"; }

printf '#if (Size > 1) sphere { 0, Size } #end\ncamera { location -5 look_at 0 }\n' >"$work/define.pov"
expect 0 "$photon" check "$work/define.pov" -D Size=2
expect 0 "$photon" check -D Size=2 -D Other=1 "$work/define.pov"
expect 1 "$photon" check "$work/define.pov"
grep -q "undefined identifier \`Size\`" "$work/err" || fail "-D missing not reported"

# check reads the scene at the size render would (image_width, image_height) and reports the
# settings render's options give.
printf '#if (image_width != 160 | image_height != 120) #error "not 160 x 120" #end\ncamera { location -5 look_at 0 }\n' >"$work/size.pov"
expect 1 "$photon" check "$work/size.pov"
expect 0 "$photon" check "$work/size.pov" --width 160 --height 120 --mode sppm
grep -q "^settings   160 x 120, mode sppm" "$work/out" || { fail "check --width --height --mode: not in the settings"; cat "$work/out"; }
expect 2 "$photon" check "$work/size.pov" --width many

# POV-Ray's animation options: an animation scene indexes its arrays by frame_number.
printf '#declare R = array[3] { 1, 2, 3 }\ncamera { location -9 look_at 0 }\nlight_source { <0, 5, -5>, 1 fade_distance 1 fade_power 2 }\nsphere { 0, R[frame_number - 1] }\n#if (clock = 0.5) box { 0, 1 } #end\n' >"$work/frames.pov"
expect 1 "$photon" check "$work/frames.pov"
grep -q "index -1 is out of the bounds of \`R\`" "$work/err" || fail "a still image's frame_number is not 0"
expect 0 "$photon" check "$work/frames.pov" --frames 1:3
grep -q "1: 1 sphere" "$work/out" || { fail "--frames: not one sphere"; cat "$work/out"; }
expect 0 "$photon" check "$work/frames.pov" --frames 1:3 --frame 2
grep -q "2: 1 box, 1 sphere" "$work/out" || { fail "--frame 2 of 1:3 is not clock 0.5"; cat "$work/out"; }
expect 1 "$photon" check "$work/frames.pov" --frames 1:3 --frame 4
grep -q "frame 4 is outside the frames 1 to 3" "$work/err" || fail "a frame outside the range not reported"
expect 1 "$photon" check "$work/frames.pov" --frames 1:3 --clock 1
expect 1 "$photon" check "$work/frames.pov" --frames 1-3
grep -q "expected two numbers A:B" "$work/err" || fail "a bad --frames not reported"
expect 0 "$photon" render "$work/frames.pov" -o "$work/frame3.png" $tiny --mode rt --frame 3 --frames 1:3 --clock-range 0:2

expect 0 "$photon" export-pov "$scenes/recursive.pov" -o "$work/flat.pov"
expect 0 "$photon" check "$work/flat.pov"
grep -q "10: 7 box, 2 sphere, 1 transformed box" "$work/out" || fail "exported scene differs"
if command -v povray >/dev/null 2>&1; then
    (cd "$work" && povray -D +W16 +H12 +O"$work/flat.png" "$work/flat.pov" >"$work/povray.log" 2>&1) ||
        { fail "povray cannot read the exported file"; tail -5 "$work/povray.log"; }
    grep -q "Parse Warning" "$work/povray.log" && fail "povray warns on the exported file"
fi

# mesh { obj "file" }: read relative to the scene, rendered, exported as triangles POV-Ray reads.
mkdir -p "$work/objscene/meshes"
printf 'v 1 1 1\nv 1 -1 -1\nv -1 1 -1\nv -1 -1 1\nf 1 2 3\nf 1 4 2\nf 1 3 4\nf 2 4 3\n' >"$work/objscene/meshes/tet.obj"
printf 'camera { location <0, 0, -5> look_at 0 }\nlight_source { <0, 5, -5>, rgb 1 fade_distance 1 fade_power 2 }\nmesh { obj "meshes/tet.obj" pigment { rgb 0.7 } finish { ambient 0 diffuse 1 } }\n' >"$work/objscene/tet.pov"
expect 0 "$photon" check "$work/objscene/tet.pov"
grep -q "1: 1 mesh" "$work/out" || fail "check does not list the OBJ mesh"
expect 0 "$photon" render "$work/objscene/tet.pov" -o "$work/tet.png" $tiny --mode rt
expect 0 "$photon" export-pov "$work/objscene/tet.pov" -o "$work/tet_flat.pov"
[ "$(grep -c 'triangle {' "$work/tet_flat.pov")" -eq 4 ] || fail "export-pov did not write the OBJ's 4 triangles"
if command -v povray >/dev/null 2>&1; then
    (cd "$work" && povray -D +W16 +H12 +O"$work/tet_flat.png" "$work/tet_flat.pov" >"$work/povray.log" 2>&1) ||
        { fail "povray cannot read the exported OBJ mesh"; tail -5 "$work/povray.log"; }
fi
printf 'mesh { obj "none.obj" }\n' >"$work/objscene/missing.pov"
expect 1 "$photon" check "$work/objscene/missing.pov"
grep -q 'missing.pov:1:12: error: cannot find the mesh file "none.obj"' "$work/err" || fail "missing OBJ file not reported"

[ $failures -eq 0 ] && echo "all photon command-line checks passed"
exit $failures
