// SPDX-License-Identifier: MIT
#pragma once
// Mirror reflection, Snell refraction and the Fresnel reflectance of a dielectric interface.

#include <algorithm>
#include <cmath>
#include <optional>

#include "../math/vec.hpp"

namespace photon {

/// Mirror direction of `d` (pointing at the surface) about the unit normal `n` (either side).
template <Scalar S> [[nodiscard]] Vec3<S> reflect(const Vec3<S>& d, const Vec3<S>& n) noexcept {
    return d - S(2) * glm::dot(d, n) * n;
}

/// Refracted direction of the unit `d` entering through the unit normal `n` that faces the
/// incoming side (dot(d, n) < 0), with eta = ior_incident / ior_transmitted. Nothing on total
/// internal reflection.
template <Scalar S>
[[nodiscard]] std::optional<Vec3<S>> refract(const Vec3<S>& d, const Vec3<S>& n, S eta) noexcept {
    const S cos_i = -glm::dot(d, n);
    const S sin2_t = eta * eta * std::max(S(0), S(1) - cos_i * cos_i);
    if (sin2_t >= S(1)) return std::nullopt;
    const S cos_t = std::sqrt(S(1) - sin2_t);
    return glm::normalize(eta * d + (eta * cos_i - cos_t) * n);
}

/// Unpolarised Fresnel reflectance of a dielectric interface for light arriving at cos_i (> 0)
/// from a medium of index ior_i into one of index ior_t. 1 under total internal reflection.
template <Scalar S> [[nodiscard]] S fresnel_dielectric(S cos_i, S ior_i, S ior_t) noexcept {
    cos_i = std::clamp(cos_i, S(0), S(1));
    const S eta = ior_i / ior_t;
    const S sin2_t = eta * eta * (S(1) - cos_i * cos_i);
    if (sin2_t >= S(1)) return S(1);
    const S cos_t = std::sqrt(S(1) - sin2_t);
    const S r_parallel = (ior_t * cos_i - ior_i * cos_t) / (ior_t * cos_i + ior_i * cos_t);
    const S r_perpendicular = (ior_i * cos_i - ior_t * cos_t) / (ior_i * cos_i + ior_t * cos_t);
    return std::clamp((r_parallel * r_parallel + r_perpendicular * r_perpendicular) / S(2), S(0), S(1));
}

}  // namespace photon
