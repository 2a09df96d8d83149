// SPDX-License-Identifier: MIT
#pragma once
// Avoiding self-intersection. A computed hit point lies off the true surface by a rounding error
// proportional to the magnitudes involved (the hit point and the ray origin it was computed from),
// not by a fixed distance. New rays therefore start at the hit point pushed along the normal by a
// bound on that error: scale-invariant, so a scene at 1e-4 or 1e5 units behaves like one at 1.

#include <algorithm>
#include <cmath>
#include <limits>

#include "../math/vec.hpp"

namespace photon {

/// Bound on the distance between a computed hit point `p` and the true surface, for a hit found
/// from a ray starting at `origin`. 64 machine epsilons covers the operations of every intersector
/// here (solving, transforming, re-evaluating o + t d) with a margin.
template <Scalar S>
[[nodiscard]] inline S intersection_error(const Vec3<S>& p, const Vec3<S>& origin) noexcept {
    const S magnitude = max_component(glm::abs(p)) + max_component(glm::abs(origin));
    return S(64) * std::numeric_limits<S>::epsilon() * magnitude + std::numeric_limits<S>::min();
}

/// Bound for a point stored in single precision (photon positions) used in a scene of scalar S:
/// the larger of S's intersection error and float's rounding of the point.
template <Scalar S>
[[nodiscard]] inline S stored_point_error(const Vec3<S>& p, const Vec3<S>& origin) noexcept {
    const float stored = intersection_error(Vec3<float>(p), Vec3<float>(origin));
    return std::max(intersection_error(p, origin), S(stored));
}

/// The length of a shadow ray from `origin` to a light's point `distance` away along unit
/// `direction`: short of the point by the rounding bound of a hit there, so that the surface a
/// light sits on (POV-Ray's lamps placed on a ceiling) does not shadow it at random.
template <Scalar S>
[[nodiscard]] inline S shadow_ray_length(const Vec3<S>& origin, const Vec3<S>& direction, S distance) noexcept {
    if (!std::isfinite(distance)) return distance;
    return std::max(S(0), distance - S(2) * intersection_error(origin + direction * distance, origin));
}

/// A photon's origin on a light, moved along unit `direction` by the rounding bound of a hit
/// there: the surface a light sits on does not catch the photons leaving it.
template <Scalar S> [[nodiscard]] inline Vec3<S> leaving_light(const Vec3<S>& origin, const Vec3<S>& direction) noexcept {
    return origin + direction * (S(2) * intersection_error(origin, origin));
}

/// Origin for a ray leaving `p` on the side of `side_normal` (a unit normal oriented towards
/// where the new ray goes).
template <Scalar S>
[[nodiscard]] inline Vec3<S> offset_origin(const Vec3<S>& p, const Vec3<S>& side_normal, S error) noexcept {
    return p + side_normal * error;
}

}  // namespace photon
