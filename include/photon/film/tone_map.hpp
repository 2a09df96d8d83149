// SPDX-License-Identifier: MIT
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "film.hpp"

namespace photon {

/// sRGB transfer function (IEC 61966-2-1) of a linear value in [0, 1].
[[nodiscard]] inline float srgb_encode(float linear) noexcept {
    linear = std::clamp(linear, 0.0f, 1.0f);
    return linear <= 0.0031308f ? 12.92f * linear : 1.055f * std::pow(linear, 1.0f / 2.4f) - 0.055f;
}
[[nodiscard]] inline float srgb_decode(float encoded) noexcept {
    return encoded <= 0.04045f ? encoded / 12.92f : std::pow((encoded + 0.055f) / 1.055f, 2.4f);
}

/// Linear value of `v` from a working space of gamma `gamma`. POV-Ray's `assumed_gamma G`
/// declares that the scene's colours, and so every sum the renderer forms from them, are numbers
/// in a space of gamma G; its output converts them to linear as v^G before encoding the file.
/// Negative values (never produced by the renderer) map to 0.
[[nodiscard]] inline float working_to_linear(float v, float gamma) noexcept {
    return v > 0.0f ? std::pow(v, gamma) : 0.0f;
}

/// Every pixel of `film`, rendered in a working space of gamma `gamma`, converted to linear
/// radiance (the identity for gamma 1).
inline void decode_working_gamma(Film& film, float gamma) noexcept {
    if (gamma == 1.0f) return;
    for (Rgb<float>& p : film.pixels())
        for (int c = 0; c < 3; ++c) p[c] = working_to_linear(p[c], gamma);
}

/// Display value of a linear radiance: times `exposure`, sRGB encoded, clamped, 8 bits. NaN
/// (never produced by the renderer) maps to 0.
[[nodiscard]] inline std::uint8_t to_display_8bit(float radiance, float exposure) noexcept {
    const float v = radiance * exposure;
    if (!(v > 0.0f)) return 0;
    return static_cast<std::uint8_t>(std::lround(srgb_encode(v) * 255.0f));
}

}  // namespace photon
