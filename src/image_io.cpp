// SPDX-License-Identifier: MIT
// photon::compiled's image files: film/image_io.hpp's functions defined once, out of line, so that
// the programs linking photon::compiled do not parse OpenImageIO's headers.

#define PHOTON_IMAGE_IO_INLINE  // empty: external definitions
#include <photon/film/image_io_oiio.hpp>
