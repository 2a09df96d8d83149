// SPDX-License-Identifier: MIT
#pragma once
// Reading an image file as a PixelGrid (texture/pixel_grid.hpp) through OpenImageIO, for image
// maps, bump maps and height fields. Its samples are decoded to linear values as POV-Ray 3.7
// decodes an input image (source/parser/parser_materials.cpp, Parse_Image): by the gamma the file
// declares (a PNG's gAMA or sRGB chunk), else by sRGB for 8- and 16-bit files (PNG, JPEG, GIF,
// TGA, TIFF, ...), not at all for floating-point files (EXR, HDR) and, in POV-Ray 3.7, not for
// Netpbm files (PPM, PGM); or by the gamma the scene writes for the image. OpenImageIO lives only
// here and in film/image_io_oiio.hpp: include this header only where files are read.

#include <OpenImageIO/imageio.h>

#if defined(PHOTON_HAS_PNG) && PHOTON_HAS_PNG  // libpng, for a palette PNG's indices (OpenImageIO expands them)
#include <png.h>
#include <csetjmp>
#include <cstdio>
#endif

#include <algorithm>
#include <cstdint>
#include <cmath>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <vector>

#include "../film/image_write_options.hpp"  // ImageError
#include "../texture/pixel_grid.hpp"

namespace photon {

namespace image_file_detail {

inline float decode_srgb(float v) noexcept {
    return v <= 0.04045f ? v / 12.92f : std::pow((v + 0.055f) / 1.055f, 2.4f);
}

/// The decoding the file asks for, under `wanted`.
inline ImageGamma file_decoding(const OIIO::ImageSpec& spec, const std::string& format, ImageGamma wanted) {
    if (wanted.kind != ImageGamma::Kind::file) return wanted;
    const bool integer = spec.format == OIIO::TypeDesc::UINT8 || spec.format == OIIO::TypeDesc::UINT16 ||
                         spec.format == OIIO::TypeDesc::UINT32;
    if (!integer || format == "pnm") return {ImageGamma::Kind::none};
    const std::string space = spec.get_string_attribute("oiio:ColorSpace");
    if (space == "Linear" || space == "linear") return {ImageGamma::Kind::none};
    const float g = spec.get_float_attribute("oiio:Gamma", 0.0f);
    // OpenImageIO 2.4 names a gAMA chunk's space "Gamma2.2", earlier versions "GammaCorrected2.2".
    if (space.rfind("Gamma", 0) == 0 && g > 0.0f) return {ImageGamma::Kind::power, double(g)};
    return {ImageGamma::Kind::srgb};
}

/// A palette PNG's indices, row by row from the top; empty when the file is no palette PNG (or
/// photon was built without libpng).
inline std::vector<std::uint8_t> png_palette_indices([[maybe_unused]] const std::filesystem::path& path) {
    std::vector<std::uint8_t> out;
#if defined(PHOTON_HAS_PNG) && PHOTON_HAS_PNG
    std::FILE* file = std::fopen(path.c_str(), "rb");
    if (!file) return out;
    png_structp png = png_create_read_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
    png_infop info = png ? png_create_info_struct(png) : nullptr;
    if (png && info && setjmp(png_jmpbuf(png)) == 0) {
        png_init_io(png, file);
        png_read_info(png, info);
        if (png_get_color_type(png, info) == PNG_COLOR_TYPE_PALETTE) {
            png_set_packing(png);  // 1, 2 and 4 bits per index: one byte each
            png_read_update_info(png, info);
            const png_uint_32 w = png_get_image_width(png, info), h = png_get_image_height(png, info);
            out.resize(std::size_t(w) * h);
            std::vector<png_bytep> rows(h);
            for (png_uint_32 y = 0; y < h; ++y) rows[y] = out.data() + std::size_t(y) * w;
            png_read_image(png, rows.data());
        }
    } else {
        out.clear();
    }
    png_destroy_read_struct(png ? &png : nullptr, info ? &info : nullptr, nullptr);
    std::fclose(file);
#endif
    return out;
}

}  // namespace image_file_detail

/// The image at `path`, its colour decoded to linear values by `gamma` (alpha is never decoded).
/// One or two channels read as grey (and alpha); three or four as RGB (and alpha). A palette PNG
/// also gives its indices (with libpng: PHOTON_HAS_PNG). Throws
/// ImageError when the file cannot be read, or declares more than `max_pixels` pixels.
[[nodiscard]] inline PixelGrid read_pixel_grid(const std::filesystem::path& path, ImageGamma gamma = {},
                                               std::uint64_t max_pixels = max_image_file_pixels) {
    // PNG and TGA store colour unassociated with alpha, as POV-Ray reads it: keep it so.
    OIIO::ImageSpec config;
    config.attribute("oiio:UnassociatedAlpha", 1);
    auto in = OIIO::ImageInput::open(path.string(), &config);
    if (!in) throw ImageError(path.string() + ": " + OIIO::geterror());
    const OIIO::ImageSpec spec = in->spec();
    const int n = spec.nchannels;
    if (n < 1 || spec.width < 1 || spec.height < 1) throw ImageError(path.string() + ": the image has no pixels");
    if (spec.depth > 1) throw ImageError(path.string() + ": a volume image (depth " + std::to_string(spec.depth) + "): photon reads flat images");
    if (std::uint64_t(spec.width) * std::uint64_t(spec.height) > max_pixels || n > 64)
        throw ImageError(path.string() + ": the file declares " + std::to_string(spec.width) + " x " +
                         std::to_string(spec.height) + " pixels of " + std::to_string(n) + " channels; photon reads images of at most " +
                         std::to_string(max_pixels) + " pixels and 64 channels");
    std::vector<float> data(std::size_t(spec.width) * std::size_t(spec.height) * std::size_t(n));
    if (!in->read_image(0, 0, 0, n, OIIO::TypeDesc::FLOAT, data.data()))
        throw ImageError(path.string() + ": " + in->geterror());
    const ImageGamma decoding = image_file_detail::file_decoding(spec, in->format_name(), gamma);
    const bool grey = n <= 2;
    const int alpha = spec.alpha_channel >= 0 ? spec.alpha_channel : (n == 2 || n == 4 ? n - 1 : -1);
    std::vector<PixelGrid::Pixel> pixels(std::size_t(spec.width) * std::size_t(spec.height));
    for (std::size_t i = 0; i < pixels.size(); ++i) {
        const float* s = &data[i * std::size_t(n)];
        PixelGrid::Pixel& p = pixels[i];
        for (int c = 0; c < 3; ++c) {
            float v = s[grey ? 0 : c];
            switch (decoding.kind) {
            case ImageGamma::Kind::srgb: v = image_file_detail::decode_srgb(v); break;
            case ImageGamma::Kind::power: v = std::pow(std::max(v, 0.0f), float(decoding.gamma)); break;
            default: break;
            }
            p[std::size_t(c)] = v;
        }
        p[3] = alpha >= 0 ? s[alpha] : 1.0f;
    }
    PixelGrid grid(unsigned(spec.width), unsigned(spec.height), std::move(pixels));
    grid.has_alpha = alpha >= 0;
    grid.grayscale = grey;
    grid.max_value = spec.format == OIIO::TypeDesc::UINT8 ? 255u : spec.format == OIIO::TypeDesc::UINT16 ? 65535u : 0u;
    if (std::string(in->format_name()) == "png") {
        grid.indices = image_file_detail::png_palette_indices(path);
        if (grid.indices.size() != grid.pixels().size()) grid.indices.clear();
    }
    return grid;
}

}  // namespace photon
