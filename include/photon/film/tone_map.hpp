// SPDX-License-Identifier: MIT
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>

namespace photon {

/// sRGB transfer function (IEC 61966-2-1) of a linear value in [0, 1].
[[nodiscard]] inline float srgb_encode(float linear) noexcept {
    linear = std::clamp(linear, 0.0f, 1.0f);
    return linear <= 0.0031308f ? 12.92f * linear : 1.055f * std::pow(linear, 1.0f / 2.4f) - 0.055f;
}
[[nodiscard]] inline float srgb_decode(float encoded) noexcept {
    return encoded <= 0.04045f ? encoded / 12.92f : std::pow((encoded + 0.055f) / 1.055f, 2.4f);
}

/// Display value of a linear radiance: times `exposure`, sRGB encoded, clamped, 8 bits. NaN
/// (never produced by the renderer) maps to 0.
[[nodiscard]] inline std::uint8_t to_display_8bit(float radiance, float exposure) noexcept {
    const float v = radiance * exposure;
    if (!(v > 0.0f)) return 0;
    return static_cast<std::uint8_t>(std::lround(srgb_encode(v) * 255.0f));
}

}  // namespace photon
