// SPDX-License-Identifier: MIT
#pragma once
// Warping uniform numbers in [0,1)^2 into directions and points. Every sampler states its pdf.

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "frame.hpp"
#include "rng.hpp"
#include "vec.hpp"

namespace photon {

/// n for an n x n grid with at least `samples` cells.
[[nodiscard]] inline unsigned strata_per_axis(unsigned samples) noexcept {
    const auto n = static_cast<unsigned>(std::ceil(std::sqrt(double(samples)) - 1e-9));
    return n == 0 ? 1 : n;
}

/// Uniform direction on the unit sphere by inversion (z uniform in [-1,1], phi uniform).
/// pdf = 1 / (4 pi) per steradian.
template <Scalar S> [[nodiscard]] Vec3<S> uniform_sphere(Vec2<S> u) noexcept {
    const S z = S(1) - S(2) * u.x;
    const S r = std::sqrt(std::max(S(0), S(1) - z * z));
    const S phi = S(2) * pi<S> * u.y;
    return {r * std::cos(phi), r * std::sin(phi), z};
}

/// Uniform direction on the unit sphere by rejection, as in the paper (section 3.1): draw points
/// in the cube [-1,1]^3 until one falls inside the unit ball, then normalise. Accepts with
/// probability pi/6; the expected number of draws is 6/pi = 1.91.
template <Scalar S> [[nodiscard]] Vec3<S> rejection_sphere(Pcg32& rng) noexcept {
    for (;;) {
        const Vec3<S> p{S(2) * rng.uniform<S>() - S(1), S(2) * rng.uniform<S>() - S(1),
                        S(2) * rng.uniform<S>() - S(1)};
        const S r2 = glm::dot(p, p);
        // Reject the centre too: a direction needs a length to normalise.
        if (r2 <= S(1) && r2 > S(1e-12)) return p / std::sqrt(r2);
    }
}

/// Uniform direction within the cone around +z whose half-angle theta has 1 - cos(theta) =
/// `one_minus_cos` (in [0, 2]). Taking 1 - cos rather than cos keeps narrow cones exact: at 0.01
/// degrees cos rounds to 1 in float, while 1 - cos = 1.5e-8 is still held to full precision.
/// pdf = 1 / (2 pi one_minus_cos).
template <Scalar S> [[nodiscard]] Vec3<S> uniform_cone_1mc(Vec2<S> u, S one_minus_cos) noexcept {
    const S t = u.x * one_minus_cos;                          // 1 - cos of the sampled direction
    const S sin_t = std::sqrt(std::max(S(0), t * (S(2) - t)));  // sin^2 = (1 - cos)(1 + cos)
    const S phi = S(2) * pi<S> * u.y;
    return {sin_t * std::cos(phi), sin_t * std::sin(phi), S(1) - t};
}

/// Uniform direction within the cone of half-angle acos(cos_max) around +z (uniform_cone_1mc
/// for cones wide enough that cos_max is exact). pdf = 1 / (2 pi (1 - cos_max)).
template <Scalar S> [[nodiscard]] Vec3<S> uniform_cone(Vec2<S> u, S cos_max) noexcept {
    return uniform_cone_1mc(u, S(1) - cos_max);
}

/// 1 - cos(theta) for a half-angle theta in radians, without the cancellation of 1 - cos:
/// 2 sin^2(theta / 2).
template <Scalar S> [[nodiscard]] S one_minus_cos(S theta) noexcept {
    const S s = std::sin(theta / S(2));
    return S(2) * s * s;
}

/// 1 - cos of the angle between unit vectors a and b, accurate for nearly parallel ones:
/// |a - b|^2 = 2 - 2 cos.
template <Scalar S> [[nodiscard]] S one_minus_cos_between(const Vec3<S>& a, const Vec3<S>& b) noexcept {
    const Vec3<S> d = a - b;
    return glm::dot(d, d) / S(2);
}

/// Solid angle of a cone whose half-angle has 1 - cos = `one_minus_cos`, in steradians.
template <Scalar S> [[nodiscard]] constexpr S cone_solid_angle_1mc(S one_minus_cos) noexcept {
    return S(2) * pi<S> * one_minus_cos;
}

/// Solid angle of a cone with half-angle acos(cos_max), in steradians.
template <Scalar S> [[nodiscard]] constexpr S cone_solid_angle(S cos_max) noexcept {
    return cone_solid_angle_1mc(S(1) - cos_max);
}

/// Concentric map of the unit square onto the unit disc (Shirley and Chiu 1997): area preserving,
/// keeps strata compact. pdf = 1 / pi per unit area.
template <Scalar S> [[nodiscard]] Vec2<S> concentric_disc(Vec2<S> u) noexcept {
    const S a = S(2) * u.x - S(1), b = S(2) * u.y - S(1);
    if (a == S(0) && b == S(0)) return {S(0), S(0)};
    S r, phi;
    if (std::abs(a) > std::abs(b)) {
        r = a;
        phi = (pi<S> / S(4)) * (b / a);
    } else {
        r = b;
        phi = pi<S> / S(2) - (pi<S> / S(4)) * (a / b);
    }
    return {r * std::cos(phi), r * std::sin(phi)};
}

/// Cosine-weighted direction on the hemisphere around +z (Malley's method).
/// pdf = cos(theta) / pi.
template <Scalar S> [[nodiscard]] Vec3<S> cosine_hemisphere(Vec2<S> u) noexcept {
    const Vec2<S> d = concentric_disc(u);
    const S z = std::sqrt(std::max(S(0), S(1) - d.x * d.x - d.y * d.y));
    return {d.x, d.y, z};
}

/// Sample `index` of an n x n jittered grid over [0,1)^2 (stratified sampling).
template <Scalar S>
[[nodiscard]] Vec2<S> stratified(unsigned index, unsigned n, Vec2<S> jitter) noexcept {
    const unsigned i = index % n, j = index / n;
    const S inv = S(1) / S(n);
    const S below_one = std::nextafter(S(1), S(0));
    return {std::min((S(i) + jitter.x) * inv, below_one), std::min((S(j) + jitter.y) * inv, below_one)};
}
/// Sample `index` of a columns x rows jittered grid over [0,1)^2.
template <Scalar S>
[[nodiscard]] Vec2<S> stratified(unsigned index, unsigned columns, unsigned rows, Vec2<S> jitter) noexcept {
    const unsigned i = index % columns, j = index / columns;
    const S below_one = std::nextafter(S(1), S(0));
    return {std::min((S(i) + jitter.x) / S(columns), below_one), std::min((S(j) + jitter.y) / S(rows), below_one)};
}

/// Point `index` of the Sobol (0,2)-sequence over [0,1)^2, its 32 bits per axis XOR-scrambled
/// by `scramble` (random digit scrambling: each point is uniform, and every prefix of 2^m points
/// keeps one point per elementary interval of area 2^-m). Any prefix is a well-spread sample set,
/// so the sequence can be extended a round at a time (adaptive anti-aliasing).
template <Scalar S>
[[nodiscard]] Vec2<S> scrambled_sobol02(std::uint32_t index, std::uint32_t scramble_x, std::uint32_t scramble_y) noexcept {
    std::uint32_t x = scramble_x, y = scramble_y;
    for (std::uint32_t v = 1u << 31, w = 1u << 31, n = index; n != 0; n >>= 1, v >>= 1, w ^= w >> 1)
        if (n & 1u) x ^= v, y ^= w;
    const S below_one = std::nextafter(S(1), S(0));
    return {std::min(S(x) * S(0x1p-32), below_one), std::min(S(y) * S(0x1p-32), below_one)};
}

}  // namespace photon
