#!/bin/sh
# POV-Ray 3.7's sample scenes that photon reads (tests/dsl/pov_corpus_subset.txt, written by
# scripts/pov-corpus.py) still pass `photon check`: the scene language keeps what it reads.
# Skipped (exit 77) when Debian's povray-examples is not installed.
# Usage: pov_corpus_test.sh PHOTON SUBSET_LIST
set -u
photon=$1
list=$2
examples=$(dpkg -L povray-examples 2>/dev/null | grep -m1 '/examples$')
[ -n "$examples" ] || examples=/usr/share/doc/povray/examples
if [ ! -d "$examples" ]; then
  echo "povray-examples is not installed: skipping the POV-Ray sample scenes"
  exit 77
fi
failed=0
count=0
# Each line: the scene, then the animation options of its .ini's first frame (--frames ...).
while read -r scene options; do
  case "$scene" in ''|'#'*) continue ;; esac
  count=$((count + 1))
  dir=$(dirname "$examples/$scene")
  # shellcheck disable=SC2086 # the options are words
  if ! (cd "$dir" && "$photon" check -q "$(basename "$scene")" $options >/dev/null 2>"/tmp/pov_corpus_test.$$"); then
    echo "FAIL: $scene"
    cat "/tmp/pov_corpus_test.$$"
    failed=$((failed + 1))
  fi
done < "$list"
rm -f "/tmp/pov_corpus_test.$$"
echo "$count sample scenes checked, $failed failed"
if [ "$count" -eq 0 ]; then echo "the list $list is empty: run scripts/pov-corpus.py"; exit 1; fi
[ "$failed" -eq 0 ]
