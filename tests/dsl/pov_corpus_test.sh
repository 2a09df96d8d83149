#!/bin/sh
# POV-Ray 3.7's sample scenes that photon reads (tests/dsl/pov_corpus_subset.txt, written by
# scripts/pov-corpus.py) still pass `photon check`: the scene language keeps what it reads.
# The scenes are checked $(nproc) at a time (PHOTON_TEST_JOBS overrides): one after another
# they took about 5 minutes, the suite's longest test.
# Skipped (exit 77) when Debian's povray-examples is not installed.
# Usage: pov_corpus_test.sh PHOTON SUBSET_LIST
set -u
if [ "${1:-}" = "--one" ]; then  # one scene: --one PHOTON EXAMPLES OUTDIR SCENE [OPTIONS...]
  photon=$2 examples=$3 out=$4 scene=$5
  shift 5
  log="$out/$(echo "$scene" | tr '/' '_')"
  # At 160 x 120 rather than check's 800 x 600: the size changes only the values of image_width
  # and image_height, and the mesh-camera scenes loop once per pixel (the whole list: 62 CPU-s
  # against 103, 2026-12-04; 44 since -q prints errors only).
  if ! (cd "$(dirname "$examples/$scene")" &&
        "$photon" check -q "$(basename "$scene")" --width 160 --height 120 "$@" >/dev/null 2>"$log.err"); then
    { echo "FAIL: $scene"; cat "$log.err"; } >"$log.fail"
  fi
  rm -f "$log.err"
  exit 0
fi
photon=$1
list=$2
examples=$(dpkg -L povray-examples 2>/dev/null | grep -m1 '/examples$')
[ -n "$examples" ] || examples=/usr/share/doc/povray/examples
if [ ! -d "$examples" ]; then
  echo "povray-examples is not installed: skipping the POV-Ray sample scenes"
  exit 77
fi
jobs=${PHOTON_TEST_JOBS:-$(nproc 2>/dev/null || echo 2)}
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
# Each line: the scene, then the animation options of its .ini's first frame (--frames ...).
grep -v -e '^#' -e '^[[:space:]]*$' "$list" >"$out/list"
count=$(wc -l <"$out/list")
if [ "$count" -eq 0 ]; then echo "the list $list is empty: run scripts/pov-corpus.py"; exit 1; fi
xargs -P "$jobs" -L 1 sh "$0" --one "$photon" "$examples" "$out" <"$out/list"
failed=0
for f in "$out"/*.fail; do
  [ -e "$f" ] || continue
  cat "$f"
  failed=$((failed + 1))
done
echo "$count sample scenes checked ($jobs at a time), $failed failed"
[ "$failed" -eq 0 ]
