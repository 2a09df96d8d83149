#!/usr/bin/env bash
# Installs the Debian packages photon needs for a purpose, and nothing else:
#   install-deps.sh render   compiler, CMake, GLM, OpenImageIO, CLI11 (enough to render)
#   install-deps.sh test     render + Catch2, Open MPI (the mpi: tests of -DPHOTON_MPI=ON), POV-Ray and its sample scenes (scene files are checked
#                            in it; photon reads its samples and compares its images with POV-Ray's, with
#                            NumPy and Pillow for Debian's /usr/bin/python3), clang for
#                            the sanitizer build and the fuzzer
#   install-deps.sh bench    test + Google Benchmark, nanoflann, Embree, OpenImageIO tools
#   install-deps.sh compare  render + POV-Ray and its sample scenes (scripts/compare-povray.sh,
#                            scripts/pov-corpus.py), matplotlib, NumPy, Pillow and OpenImageIO's
#                            bindings for Debian's /usr/bin/python3 (the plots, the corpus's image
#                            comparison, scripts/contact-study.sh's EXR images)
# Uses sudo only when not already root. Packages already present are not reinstalled.
set -euo pipefail

purpose=${1:-render}
# openimageio-tools is needed to build: Debian's OpenImageIO CMake config checks that its tools exist.
render=(build-essential cmake ninja-build pkg-config libglm-dev libopenimageio-dev openimageio-tools libcli11-dev libtinyobjloader-dev libfreetype-dev libpng-dev)
test=("${render[@]}" catch2 povray povray-examples python3-numpy python3-pil clang libclang-rt-14-dev libopenmpi-dev openmpi-bin)
bench=("${test[@]}" libbenchmark-dev libnanoflann-dev libembree-dev hyperfine bc)
compare=("${render[@]}" povray povray-examples python3-matplotlib python3-numpy python3-pil python3-openimageio)
case "$purpose" in
  render) packages=("${render[@]}") ;;
  test) packages=("${test[@]}") ;;
  bench) packages=("${bench[@]}") ;;
  compare) packages=("${compare[@]}") ;;
  *) echo "usage: $0 render|test|bench|compare" >&2; exit 2 ;;
esac

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
[ ${#missing[@]} -eq 0 ] && exit 0

sudo=()
[ "$(id -u)" -eq 0 ] || sudo=(sudo)
echo "install-deps: installing ${missing[*]}"
"${sudo[@]}" env DEBIAN_FRONTEND=noninteractive apt-get update -qq
"${sudo[@]}" env DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
