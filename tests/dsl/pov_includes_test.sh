#!/bin/sh
# POV-Ray's standard includes (colors.inc, textures.inc, ... consts.inc), found where Debian's
# povray-includes installs them, read by photon with their declarations in use
# (tests/data/pov_standard_includes.pov). Skipped (exit 77) when they are not installed.
# Usage: pov_includes_test.sh PHOTON SCENE
set -u
if [ ! -f /usr/share/povray-3.7/include/colors.inc ]; then
  echo "povray-includes is not installed: skipping POV-Ray's standard includes"
  exit 77
fi
exec "$1" check "$2"
