// SPDX-License-Identifier: MIT
#pragma once
// An image as textures and height fields read it: a grid of RGBA pixels, top row first, with
// what POV-Ray's rules need to know of the file (its bit depth, whether it is grey, whether it
// has an alpha channel). Made by photon/io/image_file.hpp from a file (through OpenImageIO), or
// by hand; this header needs no image library.

#include <array>
#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <utility>
#include <vector>

namespace photon {

/// How an image file's samples are decoded to linear values.
struct ImageGamma {
    enum class Kind {
        file,   ///< as POV-Ray 3.7 decodes the file by default (io/image_file.hpp)
        none,   ///< the samples as stored (POV-Ray's height fields and bump maps, `gamma 1.0`)
        power,  ///< value^gamma (`gamma G`)
        srgb    ///< the sRGB curve (`gamma srgb`)
    };
    Kind kind = Kind::file;
    double gamma = 1.0;  ///< for Kind::power
};

/// The most pixels an image file may declare to be read (8192 x 8192; io/image_file.hpp,
/// io/png_file.hpp): a file's header may declare any size, and a small hostile file (a PNG
/// declaring 100,000 x 100,000) must not make the reader allocate what it declares. Decoded,
/// such an image takes about 3 GB.
inline constexpr std::uint64_t max_image_file_pixels = std::uint64_t(1) << 26;

struct PixelGrid {
    using Pixel = std::array<float, 4>;  ///< red, green, blue, alpha (1: opaque)

    PixelGrid() = default;
    /// `pixels`: width * height of them, row by row from the top. Throws std::invalid_argument
    /// when empty or of the wrong size.
    PixelGrid(unsigned width, unsigned height, std::vector<Pixel> pixels)
        : width_(width), height_(height), pixels_(std::move(pixels)) {
        if (width == 0 || height == 0 || pixels_.size() != std::size_t(width) * height)
            throw std::invalid_argument("pixel grid: width * height pixels are needed, and at least one");
    }

    [[nodiscard]] unsigned width() const noexcept { return width_; }
    [[nodiscard]] unsigned height() const noexcept { return height_; }
    /// Column x (from the left), row y (from the top).
    [[nodiscard]] const Pixel& at(unsigned x, unsigned y) const noexcept { return pixels_[std::size_t(y) * width_ + x]; }
    [[nodiscard]] const std::vector<Pixel>& pixels() const noexcept { return pixels_; }
    [[nodiscard]] std::vector<Pixel>& pixels() noexcept { return pixels_; }

    /// The file had an alpha channel (POV-Ray then reads 1 - alpha as the pixel's transmit).
    bool has_alpha = false;
    /// The file had one grey channel (red = green = blue here).
    bool grayscale = false;
    /// The largest integer value of the file's samples: 255 for 8 bits, 65535 for 16; 0 for a
    /// floating-point file. POV-Ray's height fields read 8-bit colour files differently.
    unsigned max_value = 255;
    /// A palette image's palette index of each pixel, row by row from the top; empty for other
    /// images. POV-Ray's height fields read the index, not the colour, of a palette image.
    std::vector<std::uint8_t> indices;

private:
    unsigned width_ = 0, height_ = 0;
    std::vector<Pixel> pixels_;
};

}  // namespace photon
