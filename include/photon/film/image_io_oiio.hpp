// SPDX-License-Identifier: MIT
#pragma once
// The definitions behind film/image_io.hpp (include that one): writing and reading films through
// OpenImageIO. Floating-point formats (EXR, HDR, PFM, float
// TIFF) receive linear radiance; 8-bit formats (PNG, JPEG, ...) receive exposure * radiance,
// sRGB encoded. Files are written to a temporary name in the target directory and renamed into
// place, so a failed or interrupted write never leaves a truncated image or clobbers an old one.

#include <OpenImageIO/imageio.h>

#include <cerrno>
#include <filesystem>
#include <string>
#include <system_error>
#include <fcntl.h>
#include <unistd.h>
#include <vector>

#include "film.hpp"
#include "image_write_options.hpp"
#include "tone_map.hpp"

// Inline in header-only use; src/image_io.cpp (photon::compiled) defines them once, out of line.
#ifndef PHOTON_IMAGE_IO_INLINE
#define PHOTON_IMAGE_IO_INLINE inline
#endif

namespace photon {

/// Throws ImageError if `path` cannot be written as an image: unknown format, missing directory,
/// or a directory without write permission. Call it before a long render.
PHOTON_IMAGE_IO_INLINE void check_writable_image_path(const std::filesystem::path& path) {
    if (path.empty()) throw ImageError("output path is empty");
    auto probe = OIIO::ImageOutput::create(path.string());
    if (!probe)
        throw ImageError(path.string() + ": no image format for extension '" + path.extension().string() +
                         "' (use .png, .exr, .jpg, .tif, .hdr, ...)");
    detail::check_writable_location(path);
}

/// Writes `film` to `path` (format from the extension). Throws ImageError; on failure the file
/// at `path`, if any, is untouched.
PHOTON_IMAGE_IO_INLINE void write_image(const std::filesystem::path& path, const Film& film, const ImageWriteOptions& options = {}) {
    check_writable_image_path(path);
    const std::filesystem::path tmp = detail::temporary_sibling(path);
    auto out = OIIO::ImageOutput::create(path.string());
    const bool linear = detail::is_float_format(out->format_name());
    OIIO::ImageSpec spec(int(film.width()), int(film.height()), 3, linear ? OIIO::TypeDesc::FLOAT : OIIO::TypeDesc::UINT8);
    spec.attribute("oiio:ColorSpace", linear ? "Linear" : "sRGB");
    spec.attribute("Software", "photon");
    for (const auto& [key, value] : options.metadata) spec.attribute(key, value);
    const std::size_t n = std::size_t(film.width()) * film.height();
    std::vector<float> linear_data;
    std::vector<unsigned char> display_data;
    if (linear) {
        linear_data.resize(3 * n);
        for (std::size_t i = 0; i < n; ++i)
            for (int c = 0; c < 3; ++c) linear_data[3 * i + c] = film.pixels()[i][c];
    } else {
        display_data.resize(3 * n);
        for (std::size_t i = 0; i < n; ++i)
            for (int c = 0; c < 3; ++c) display_data[3 * i + c] = to_display_8bit(film.pixels()[i][c], options.exposure);
    }
    auto fail = [&](const std::string& why) {
        std::error_code ec;
        std::filesystem::remove(tmp, ec);
        throw ImageError(path.string() + ": " + why);
    };
    if (!out->open(tmp.string(), spec)) fail(out->geterror());
    const bool ok = linear ? out->write_image(OIIO::TypeDesc::FLOAT, linear_data.data())
                           : out->write_image(OIIO::TypeDesc::UINT8, display_data.data());
    if (!ok) fail(out->geterror());
    if (!out->close()) fail(out->geterror());
    std::error_code ec;
    std::filesystem::rename(tmp, path, ec);
    if (ec) fail("cannot move the finished image into place: " + ec.message());
}

/// Reads an image as linear RGB (8-bit sRGB files are decoded). Throws ImageError.
PHOTON_IMAGE_IO_INLINE Film read_image(const std::filesystem::path& path) {
    auto in = OIIO::ImageInput::open(path.string());
    if (!in) throw ImageError(path.string() + ": " + OIIO::geterror());
    const OIIO::ImageSpec& spec = in->spec();
    if (spec.nchannels < 3) throw ImageError(path.string() + ": needs at least 3 channels");
    std::vector<float> data(std::size_t(spec.width) * spec.height * spec.nchannels);
    if (!in->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::FLOAT, data.data()))
        throw ImageError(path.string() + ": " + in->geterror());
    const bool srgb = spec.format == OIIO::TypeDesc::UINT8 || spec.format == OIIO::TypeDesc::UINT16;
    Film film(unsigned(spec.width), unsigned(spec.height));
    for (std::size_t i = 0; i < film.pixels().size(); ++i)
        for (int c = 0; c < 3; ++c) {
            const float v = data[i * spec.nchannels + c];
            film.pixels()[i][c] = srgb ? srgb_decode(v) : v;
        }
    return film;
}

}  // namespace photon
