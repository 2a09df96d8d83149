// SPDX-License-Identifier: MIT
#pragma once
// Vocabulary types: photon uses GLM vectors, templated on the scalar type.

#include <glm/geometric.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <algorithm>
#include <cmath>
#include <concepts>
#include <type_traits>

namespace photon {

/// A floating-point scalar photon computes with (float or double).
template <class S>
concept Scalar = std::floating_point<S>;

template <Scalar S> using Vec2 = glm::vec<2, S, glm::defaultp>;
template <Scalar S> using Vec3 = glm::vec<3, S, glm::defaultp>;

/// Linear RGB triple: radiance, power (watts per channel) or reflectance, depending on context.
template <Scalar S> using Rgb = glm::vec<3, S, glm::defaultp>;

template <Scalar S> constexpr S pi = S(3.14159265358979323846264338327950288);
template <Scalar S> constexpr S inv_pi = S(0.31830988618379067153776752674502872);

template <Scalar S> [[nodiscard]] constexpr S max_component(const Vec3<S>& v) noexcept {
    return std::max(v.x, std::max(v.y, v.z));
}
template <Scalar S> [[nodiscard]] constexpr S min_component(const Vec3<S>& v) noexcept {
    return std::min(v.x, std::min(v.y, v.z));
}
/// Channel average, the paper's rho_avg used by Russian roulette.
template <Scalar S> [[nodiscard]] constexpr S average(const Rgb<S>& c) noexcept {
    return (c.x + c.y + c.z) / S(3);
}
/// Rec. 709 luminance: the noise the eye sees, one number per sample.
template <Scalar S> [[nodiscard]] constexpr double luminance(const Rgb<S>& c) noexcept {
    return 0.2126 * double(c.x) + 0.7152 * double(c.y) + 0.0722 * double(c.z);
}
template <Scalar S> [[nodiscard]] constexpr bool is_black(const Rgb<S>& c) noexcept {
    return c.x == S(0) && c.y == S(0) && c.z == S(0);
}
template <Scalar S> [[nodiscard]] inline bool is_finite(const Vec3<S>& v) noexcept {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}
template <Scalar S> [[nodiscard]] constexpr S squared(S x) noexcept { return x * x; }
template <Scalar S> [[nodiscard]] constexpr S length_squared(const Vec3<S>& v) noexcept {
    return glm::dot(v, v);
}

/// Index of the largest component (0, 1 or 2).
template <Scalar S> [[nodiscard]] constexpr int max_dimension(const Vec3<S>& v) noexcept {
    return v.x > v.y ? (v.x > v.z ? 0 : 2) : (v.y > v.z ? 1 : 2);
}

}  // namespace photon
