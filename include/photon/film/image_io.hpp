// SPDX-License-Identifier: MIT
#pragma once
// Writing and reading films as image files (OpenImageIO): EXR, HDR, PFM and float TIFF receive
// linear radiance, PNG, JPEG and the other 8-bit formats exposure * radiance, sRGB encoded. A
// write goes to a temporary file renamed into place, so a failed or interrupted write never
// leaves a truncated image or clobbers an old one.
//
// Header-only use defines the functions here (film/image_io_oiio.hpp). A program that links
// photon::compiled (PHOTON_SEPARATE_COMPILATION) sees only their declarations and links the
// definitions from src/image_io.cpp: OpenImageIO's headers, half of a small program's compile
// time, stay out of its units.

#if defined(PHOTON_SEPARATE_COMPILATION) && PHOTON_SEPARATE_COMPILATION && !defined(PHOTON_IMAGE_IO_INLINE)
#include <filesystem>

#include "film.hpp"
#include "image_write_options.hpp"

namespace photon {

/// Throws ImageError if `path` cannot be written as an image: unknown format, missing directory,
/// or a directory without write permission. Call it before a long render.
void check_writable_image_path(const std::filesystem::path& path);

/// Writes `film` to `path` (format from the extension). Throws ImageError; on failure the file
/// at `path`, if any, is untouched.
void write_image(const std::filesystem::path& path, const Film& film, const ImageWriteOptions& options = {});

/// Reads an image as linear RGB (8-bit sRGB files are decoded). Throws ImageError.
[[nodiscard]] Film read_image(const std::filesystem::path& path);

}  // namespace photon
#else
#include "image_io_oiio.hpp"
#endif
