#!/bin/sh
# SPDX-License-Identifier: MIT
# Renders SCENE with POV-Ray 3.7 at 16 x 12 after the render-mode header HEADER (+HI), and fails on
# any parse error or parse warning: the scene files must be plain POV-Ray that POV-Ray reads as is.
# Exits 77 (ctest: skipped) when povray is not installed.
#   povray_parses.sh SCENE HEADER WORKDIR
scene=$1 header=$2 work=$3
if ! command -v povray >/dev/null 2>&1; then
    echo "povray is not installed: skipping this check (apt-get install povray)"
    exit 77
fi
mkdir -p "$work" || exit 1
name=$(basename "$scene" .pov)-$(basename "$header" .inc)
# Run from the work directory: POV-Ray writes nothing else, and #include must not depend on it.
cd "$work" || exit 1
run() {
    # +L: files the scene names (images) are found beside it, as photon finds them.
    povray -D +W16 +H12 +HI"$header" +L"$(dirname "$scene")" +FE +O"$work/$name.exr" "$scene" >"$work/$name.log" 2>&1
    rc=$?
}
run
# Once in a fresh-Debian run POV-Ray exited 1 before it began to parse (the log was not kept):
# such a failure says nothing of the file, so it is shown and the render tried once more.
if [ $rc -ne 0 ] && ! grep -q "Parsing" "$work/$name.log"; then
    echo "povray exited $rc before parsing $scene; its output:"
    tail -20 "$work/$name.log"
    echo "trying once more"
    run
fi
if [ $rc -ne 0 ] || grep -q "Parse Error\|Parse Warning\|Possible Parse" "$work/$name.log"; then
    if grep -q "Parsing" "$work/$name.log"; then sed -n '/Parsing/,$p' "$work/$name.log" | head -40; else tail -20 "$work/$name.log"; fi
    echo "povray failed on $scene with $header (exit status $rc)"
    exit 1
fi
echo "povray read $scene with $header"
