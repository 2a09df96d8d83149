#!/bin/sh
# Prints POV-Ray 3.7's own pattern values at the points of tests/texture/pov_reference.pov, as the
# C++ initialiser list tests/texture/pov_reference_values.inc holds (regenerate it with this).
# Needs `povray` (Debian's povray package, 3.7).
set -e
cd "$(dirname "$0")/../tests/texture"
povray +W1 +H1 -D +GD pov_reference.pov 2>&1 | tr -d '\n' | grep -o '{"[^}]*}}' | sed 's/$/,/'
