// SPDX-License-Identifier: MIT
#pragma once
// Reading a PNG file as a PixelGrid through libpng alone (PHOTON_HAS_PNG), the same grid
// io/image_file.hpp's OpenImageIO reader gives: a program that reads only PNG images (most of
// POV-Ray's scenes) then never loads OpenImageIO, which costs a third of a CPU-second. Palette,
// grey below 8 bits and tRNS transparency are expanded (1 to 4 channels: grey, grey and alpha,
// RGB, RGBA), 8- and 16-bit samples scaled to [0, 1], colour decoded as POV-Ray 3.7 decodes
// the file by default (its sRGB chunk, else its gAMA, else sRGB), alpha left unassociated.

#if defined(PHOTON_HAS_PNG) && PHOTON_HAS_PNG

#include <png.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <csetjmp>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "../film/image_write_options.hpp"  // ImageError
#include "../texture/pixel_grid.hpp"

namespace photon {

/// The decoding a PNG's chunks ask for, as OpenImageIO reports them to io/image_file.hpp: the
/// sRGB chunk; else a gAMA chunk's gamma (1 / its value, rounded to hundredths), linear at 1;
/// else sRGB.
[[nodiscard]] inline ImageGamma png_file_decoding(bool srgb_chunk, std::optional<double> gama) {
    if (srgb_chunk || !gama || !(*gama > 0.0)) return {ImageGamma::Kind::srgb};
    const double g = std::round(100.0 / *gama) / 100.0;
    if (g == 1.0) return {ImageGamma::Kind::none};
    return {ImageGamma::Kind::power, g};
}

/// The PNG image at `path`, decoded by `gamma` as read_pixel_grid does, or nothing when the file
/// is not a PNG (its signature says so). Throws ImageError when it cannot be read, or declares
/// more than `max_pixels` pixels (the check made before any pixel is allocated).
[[nodiscard]] inline std::optional<PixelGrid> read_png_pixel_grid(const std::filesystem::path& path, ImageGamma gamma,
                                                                  std::uint64_t max_pixels) {
    std::FILE* file = std::fopen(path.c_str(), "rb");
    if (!file) throw ImageError(path.string() + ": cannot open the file");
    png_byte signature[8] = {};
    if (std::fread(signature, 1, 8, file) != 8 || png_sig_cmp(signature, 0, 8) != 0) {
        std::fclose(file);
        return std::nullopt;
    }
    // Everything with a destructor is made before setjmp: libpng reports errors by longjmp.
    std::vector<std::uint16_t> samples;
    std::vector<std::uint8_t> indices;
    std::vector<png_bytep> rows;
    std::string error;
    png_uint_32 width = 0, height = 0;
    int channels = 0, depth = 0;
    bool srgb_chunk = false, too_big = false;
    double gama_value = 0;
    bool has_gama = false;
    png_structp png = png_create_read_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
    png_infop info = png ? png_create_info_struct(png) : nullptr;
    volatile bool ok = png && info;
    if (ok && setjmp(png_jmpbuf(png)) == 0) {
        png_init_io(png, file);
        png_set_sig_bytes(png, 8);
        png_read_info(png, info);
        width = png_get_image_width(png, info), height = png_get_image_height(png, info);
        if (std::uint64_t(width) * height > max_pixels) {
            too_big = true;
        } else {
            const int type = png_get_color_type(png, info);
            srgb_chunk = png_get_valid(png, info, PNG_INFO_sRGB) != 0;
            has_gama = png_get_gAMA(png, info, &gama_value) != 0;
            if (type == PNG_COLOR_TYPE_PALETTE) {  // its indices first, as a height field reads them
                png_set_packing(png);
                png_read_update_info(png, info);
                indices.resize(std::size_t(width) * height);
                rows.resize(height);
                for (png_uint_32 y = 0; y < height; ++y) rows[y] = indices.data() + std::size_t(y) * width;
                png_read_image(png, rows.data());
            }
            if (type != PNG_COLOR_TYPE_PALETTE) {
                png_set_expand(png);  // grey below 8 bits to 8, tRNS to alpha
                png_read_update_info(png, info);
                channels = png_get_channels(png, info);
                depth = png_get_bit_depth(png, info);
                std::vector<std::uint8_t> raw(png_get_rowbytes(png, info) * height);
                rows.resize(height);
                for (png_uint_32 y = 0; y < height; ++y) rows[y] = raw.data() + std::size_t(y) * png_get_rowbytes(png, info);
                png_read_image(png, rows.data());
                samples.resize(std::size_t(width) * height * channels);
                for (std::size_t i = 0; i < samples.size(); ++i)  // 16-bit samples are big-endian in the file
                    samples[i] = depth == 16 ? std::uint16_t(raw[2 * i] << 8 | raw[2 * i + 1]) : raw[i];
            }
        }
    } else {
        ok = false;
    }
    // A palette image: its colours from the palette (and tRNS), 8-bit.
    if (ok && !too_big && !indices.empty()) {
        png_colorp palette = nullptr;
        int entries = 0;
        png_get_PLTE(png, info, &palette, &entries);
        png_bytep alpha = nullptr;
        int alphas = 0;
        png_get_tRNS(png, info, &alpha, &alphas, nullptr);
        channels = alphas > 0 ? 4 : 3, depth = 8;
        samples.resize(std::size_t(width) * height * channels);
        for (std::size_t i = 0; i < indices.size(); ++i) {
            const int k = indices[i];
            const png_color c = k < entries ? palette[k] : png_color{0, 0, 0};
            std::uint16_t* s = &samples[i * channels];
            s[0] = c.red, s[1] = c.green, s[2] = c.blue;
            if (channels == 4) s[3] = k < alphas ? alpha[k] : 255;
        }
    }
    png_destroy_read_struct(png ? &png : nullptr, info ? &info : nullptr, nullptr);
    std::fclose(file);
    if (too_big)
        throw ImageError(path.string() + ": the file declares " + std::to_string(width) + " x " + std::to_string(height) +
                         " pixels; photon reads images of at most " + std::to_string(max_pixels) + " pixels");
    if (!ok || width == 0 || height == 0 || channels < 1) throw ImageError(path.string() + ": libpng cannot read the image");
    const ImageGamma decoding = gamma.kind == ImageGamma::Kind::file
                                    ? png_file_decoding(srgb_chunk, has_gama ? std::optional<double>(gama_value) : std::nullopt)
                                    : gamma;
    const float scale = depth == 16 ? 1.0f / 65535.0f : 1.0f / 255.0f;
    const bool grey = channels <= 2;
    const int alpha_channel = channels == 2 || channels == 4 ? channels - 1 : -1;
    std::vector<PixelGrid::Pixel> pixels(std::size_t(width) * height);
    for (std::size_t i = 0; i < pixels.size(); ++i) {
        const std::uint16_t* s = &samples[i * channels];
        for (int c = 0; c < 3; ++c) {
            float v = float(s[grey ? 0 : c]) * scale;
            switch (decoding.kind) {
            case ImageGamma::Kind::srgb: v = v <= 0.04045f ? v / 12.92f : std::pow((v + 0.055f) / 1.055f, 2.4f); break;
            case ImageGamma::Kind::power: v = std::pow(std::max(v, 0.0f), float(decoding.gamma)); break;
            default: break;
            }
            pixels[i][std::size_t(c)] = v;
        }
        pixels[i][3] = alpha_channel >= 0 ? float(s[alpha_channel]) * scale : 1.0f;
    }
    PixelGrid grid(unsigned(width), unsigned(height), std::move(pixels));
    grid.has_alpha = alpha_channel >= 0;
    grid.grayscale = grey;
    grid.max_value = depth == 16 ? 65535u : 255u;
    grid.indices = std::move(indices);
    return grid;
}

}  // namespace photon

#endif
