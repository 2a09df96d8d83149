// SPDX-License-Identifier: MIT
#pragma once
// Unit vectors in 16 bits: octahedral mapping (Cigolle et al. 2014, "A Survey of Efficient
// Representations for Independent Unit Vectors"), 8 bits per coordinate, error under 1 degree.

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "vec.hpp"

namespace photon {

[[nodiscard]] inline std::uint16_t encode_octahedral(Vec3<float> d) noexcept {
    d /= std::abs(d.x) + std::abs(d.y) + std::abs(d.z);
    float u = d.x, v = d.y;
    if (d.z < 0.0f) {
        u = (1.0f - std::abs(d.y)) * std::copysign(1.0f, d.x);
        v = (1.0f - std::abs(d.x)) * std::copysign(1.0f, d.y);
    }
    auto quantise = [](float x) {
        return static_cast<std::uint16_t>(std::lround((std::clamp(x, -1.0f, 1.0f) * 0.5f + 0.5f) * 255.0f));
    };
    return static_cast<std::uint16_t>(quantise(u) | (quantise(v) << 8));
}

/// The decoded direction before normalisation (length in [1/sqrt(3), 1]): enough for sign tests.
[[nodiscard]] inline Vec3<float> decode_octahedral_unnormalized(std::uint16_t bits) noexcept {
    const float u = float(bits & 0xffu) / 255.0f * 2.0f - 1.0f, v = float(bits >> 8) / 255.0f * 2.0f - 1.0f;
    Vec3<float> d{u, v, 1.0f - std::abs(u) - std::abs(v)};
    if (d.z < 0.0f) {
        const float x = d.x;
        d.x = (1.0f - std::abs(d.y)) * std::copysign(1.0f, x);
        d.y = (1.0f - std::abs(x)) * std::copysign(1.0f, d.y);
    }
    return d;
}

[[nodiscard]] inline Vec3<float> decode_octahedral(std::uint16_t bits) noexcept {
    return glm::normalize(decode_octahedral_unnormalized(bits));
}

}  // namespace photon
