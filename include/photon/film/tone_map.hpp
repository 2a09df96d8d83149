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

/// The space the numbers a render forms live in, as POV-Ray 3.7 defines it for a scene: a power
/// law (`assumed_gamma G`: colours, and every sum formed from them, are numbers of gamma G; 1 is
/// linear), or the display's sRGB curve (a scene older than 3.7 without assumed_gamma, whose
/// numbers POV-Ray writes to the file as they are). An image written from the film is first
/// converted to linear radiance (decode_working_space).
struct WorkingSpace {
    enum class Curve { power, srgb };
    Curve curve = Curve::power;
    float gamma = 1.0f;  ///< for Curve::power
    [[nodiscard]] bool linear() const noexcept { return curve == Curve::power && gamma == 1.0f; }
    friend bool operator==(const WorkingSpace&, const WorkingSpace&) = default;
};

/// Linear value of `v` from working space `space` (v^G, or the sRGB curve with values above 1
/// continued as a power law). Negative values (never produced by the renderer) map to 0.
[[nodiscard]] inline float working_to_linear(float v, WorkingSpace space) noexcept {
    if (!(v > 0.0f)) return 0.0f;
    if (space.curve == WorkingSpace::Curve::power) return std::pow(v, space.gamma);
    return v <= 1.0f ? srgb_decode(v) : std::pow(v, 2.4f);
}

/// Every pixel of `film`, rendered in working space `space`, converted to linear radiance (the
/// identity, bit for bit, for a linear space).
inline void decode_working_space(Film& film, WorkingSpace space) noexcept {
    if (space.linear()) return;
    for (Rgb<float>& p : film.pixels())
        for (int c = 0; c < 3; ++c) p[c] = working_to_linear(p[c], space);
}

/// Display value of a linear radiance: times `exposure`, sRGB encoded, clamped, 8 bits. NaN
/// (never produced by the renderer) maps to 0.
[[nodiscard]] inline std::uint8_t to_display_8bit(float radiance, float exposure) noexcept {
    const float v = radiance * exposure;
    if (!(v > 0.0f)) return 0;
    return static_cast<std::uint8_t>(std::lround(srgb_encode(v) * 255.0f));
}

}  // namespace photon
