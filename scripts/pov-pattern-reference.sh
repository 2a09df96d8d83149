#!/bin/sh
# Prints POV-Ray 3.7's own pattern values for tests/texture/texture_test.cpp, as the C++
# initialiser lists it includes (regenerate them with this):
#   scripts/pov-pattern-reference.sh > tests/texture/pov_reference_values.inc
#   scripts/pov-pattern-reference.sh hexagon > tests/texture/pov_hexagon_values.inc
# Needs `povray` (Debian's povray package, 3.7).
set -e
cd "$(dirname "$0")/../tests/texture"
if [ "${1:-}" = hexagon ]; then
    povray +W1 +H1 -D +GD pov_hexagon.pov 2>&1 | grep -E '^\{'
else
    povray +W1 +H1 -D +GD pov_reference.pov 2>&1 | tr -d '\n' | grep -o '{"[^}]*}}' | sed 's/$/,/'
fi
