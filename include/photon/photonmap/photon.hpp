// SPDX-License-Identifier: MIT
#pragma once
// The photon record. Positions live in the kd-tree's own arrays; what each photon keeps beside
// them is one 8-byte word: power in a shared-exponent format, the kind of path that brought it,
// and its incident direction (Jensen 2001, section 5.1, with a finer power encoding).

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <type_traits>

#include "../math/octahedral.hpp"
#include "../math/vec.hpp"
#include "point_traits.hpp"

namespace photon {

/// Which light path left the photon where it is stored (Heckbert's notation).
enum class PathKind : std::uint8_t {
    direct = 0,    ///< L D: straight from the light
    caustic = 1,   ///< L S+ D: through mirrors or glass only
    indirect = 2,  ///< L (S|D)* D (S|D)* D: at least one diffuse bounce before
};

/// Power, path kind and incident direction packed in 64 bits:
/// bits 0-35 three 12-bit mantissas (r, g, b), bits 36-43 a shared exponent (biased by 128),
/// bits 44-45 the PathKind, bits 48-63 the incident direction (octahedral, math/octahedral.hpp).
/// Relative power error <= 2^-13 of the largest channel; direction error under 1 degree.
class PackedPhoton {
public:
    PackedPhoton() = default;
    PackedPhoton(const Rgb<float>& power, const Vec3<float>& incident_dir, PathKind kind) noexcept {
        bits_ = encode_power(power) | (std::uint64_t(kind) << 44) | (std::uint64_t(encode_octahedral(incident_dir)) << 48);
    }

    /// Power in watts per channel.
    [[nodiscard]] Rgb<float> power() const noexcept {
        const int exponent = int((bits_ >> 36) & 0xffu) - 128;
        // 2^(exponent - 12) built from its bits when it is a normal float (always, in practice).
        const int biased = exponent - mantissa_bits + 127;
        const float scale = biased > 0 ? std::bit_cast<float>(std::uint32_t(biased) << 23)
                                       : std::ldexp(1.0f, exponent - mantissa_bits);
        return {float(bits_ & mask) * scale, float((bits_ >> 12) & mask) * scale, float((bits_ >> 24) & mask) * scale};
    }
    [[nodiscard]] PathKind kind() const noexcept { return PathKind((bits_ >> 44) & 0x3u); }
    /// Unit direction pointing into the surface on the side the photon arrived from. The photon
    /// tracer stores the reversed surface normal of that side (not the travel direction, which
    /// misjudges the side on curved surfaces; only Lambertian surfaces store photons).
    [[nodiscard]] Vec3<float> incident_direction() const noexcept {
        return decode_octahedral(std::uint16_t(bits_ >> 48));
    }
    /// Whether the photon arrived travelling against `n` (onto the side `n` faces), on a surface
    /// facing within about 84 degrees of `n`. The margin matters at an edge: a photon on the
    /// perpendicular face has a stored normal at 90 degrees, whose 16-bit encoding gives a dot
    /// product of either sign, so with a bare sign test half of the photons on a box's outer
    /// faces lit the inside of its edges (a camera inside a solid box saw light). No
    /// normalisation: the decoded vector's length is 0.58 to 1, so the bound is a cosine of 0.1 to 0.17.
    [[nodiscard]] bool arrived_against(const Vec3<float>& n) const noexcept {
        return glm::dot(decode_octahedral_unnormalized(std::uint16_t(bits_ >> 48)), n) < -0.1f;
    }
    [[nodiscard]] std::uint64_t bits() const noexcept { return bits_; }

private:
    static constexpr int mantissa_bits = 12;
    static constexpr std::uint64_t mask = (1u << mantissa_bits) - 1;

    static std::uint64_t encode_power(const Rgb<float>& c) noexcept {
        const float r = std::max(c.x, 0.0f), g = std::max(c.y, 0.0f), b = std::max(c.z, 0.0f);
        const float m = std::max(r, std::max(g, b));
        if (!(m > 0.0f) || !std::isfinite(m)) return 0;  // black; non-finite never reaches here
        int exponent = 0;
        std::frexp(m, &exponent);  // m = f * 2^exponent, f in [0.5, 1)
        exponent = std::clamp(exponent, -127, 127);
        auto quantise = [&](float v) {
            return std::uint64_t(std::lround(std::ldexp(v, mantissa_bits - exponent)));
        };
        if (quantise(m) > mask) ++exponent;  // rounding carried into the next power of two
        return std::min(quantise(r), mask) | (std::min(quantise(g), mask) << 12) |
               (std::min(quantise(b), mask) << 24) | (std::uint64_t(exponent + 128) << 36);
    }
    std::uint64_t bits_ = 0;
};
static_assert(sizeof(PackedPhoton) == 8 && std::is_trivially_copyable_v<PackedPhoton>);

/// A photon as photon tracing emits it: position plus the packed rest. The kd-tree keeps the
/// position in its own arrays and only the PackedPhoton beside it (20 bytes per photon).
struct Photon {
    Vec3<float> position;
    PackedPhoton packed;
};

template <> struct point_traits<Photon> {
    using payload_type = PackedPhoton;
    [[nodiscard]] static Vec3<float> position(const Photon& p) noexcept { return p.position; }
    [[nodiscard]] static PackedPhoton payload(const Photon& p) noexcept { return p.packed; }
};
static_assert(SpatialPoint<Photon>);

}  // namespace photon
