// SPDX-License-Identifier: MIT
#pragma once

#include <cmath>
#include <cstddef>
#include <stdexcept>
#include <vector>

#include "../math/vec.hpp"

namespace photon {

/// HDR image: linear RGB radiance (W m^-2 sr^-1) per pixel, float, row-major from the top-left.
class Film {
public:
    Film() = default;
    Film(unsigned width, unsigned height) : width_(width), height_(height), pixels_(std::size_t(width) * height) {}

    [[nodiscard]] unsigned width() const noexcept { return width_; }
    [[nodiscard]] unsigned height() const noexcept { return height_; }
    [[nodiscard]] Rgb<float>& at(unsigned x, unsigned y) noexcept { return pixels_[std::size_t(y) * width_ + x]; }
    [[nodiscard]] const Rgb<float>& at(unsigned x, unsigned y) const noexcept {
        return pixels_[std::size_t(y) * width_ + x];
    }
    [[nodiscard]] std::vector<Rgb<float>>& pixels() noexcept { return pixels_; }
    [[nodiscard]] const std::vector<Rgb<float>>& pixels() const noexcept { return pixels_; }

    /// True when every channel of every pixel is finite and >= 0.
    [[nodiscard]] bool all_finite_nonnegative() const noexcept {
        for (const auto& p : pixels_)
            if (!is_finite(p) || min_component(p) < 0.0f) return false;
        return true;
    }
    /// Mean radiance over the whole image, per channel.
    [[nodiscard]] Rgb<double> mean() const noexcept {
        Rgb<double> sum(0.0);
        for (const auto& p : pixels_) sum += Rgb<double>(p);
        return pixels_.empty() ? sum : sum / double(pixels_.size());
    }

private:
    unsigned width_ = 0, height_ = 0;
    std::vector<Rgb<float>> pixels_;
};

}  // namespace photon
