// SPDX-License-Identifier: MIT
#pragma once
// Shared by the cylinder, cone, disc and torus: where a ray crosses a bounding sphere (to reject
// early and to move the ray's origin next to the shape before solving, so that the polynomial's
// coefficients are of the shape's size and not of the origin's distance, which would cancel), a
// quadratic solved without cancellation, and the exact extent of a tilted circle.

#include <algorithm>
#include <cmath>
#include <optional>
#include <utility>

#include "bbox.hpp"
#include "ray.hpp"

namespace photon::detail {

/// The two real roots of a t^2 + 2 b t + c = 0 in ascending order (a != 0), or nothing. The small
/// root comes from c / q, not from a difference of nearly equal numbers (Press et al.).
template <Scalar S> [[nodiscard]] std::optional<std::pair<S, S>> solve_quadratic(S a, S b, S c) noexcept {
    const S discriminant = b * b - a * c;
    if (!(discriminant >= S(0)) || a == S(0)) return std::nullopt;
    const S q = -(b + std::copysign(std::sqrt(discriminant), b));
    if (q == S(0)) return std::pair<S, S>{S(0), S(0)};
    S t0 = c / q, t1 = q / a;
    if (t0 > t1) std::swap(t0, t1);
    return std::pair<S, S>{t0, t1};
}

/// The span of t where the ray is inside the sphere (centre, radius), or nothing when it misses.
/// The discriminant is taken from the ray's closest point to the centre (Hearn and Baker), as in
/// Sphere::intersect, so that it stays accurate for a far origin.
template <Scalar S>
[[nodiscard]] std::optional<std::pair<S, S>> sphere_span(const Ray<S>& ray, const Vec3<S>& center, S radius) noexcept {
    const Vec3<S> f = ray.origin - center;
    const S a = glm::dot(ray.direction, ray.direction);
    const S b = glm::dot(f, ray.direction);
    const S c = glm::dot(f, f) - radius * radius;
    const Vec3<S> closest = f - (b / a) * ray.direction;
    const S discriminant = a * (radius * radius - glm::dot(closest, closest));
    if (!(discriminant >= S(0))) return std::nullopt;
    const S q = -(b + std::copysign(std::sqrt(discriminant), b));
    if (q == S(0)) return std::pair<S, S>{S(0), S(0)};
    S t0 = c / q, t1 = q / a;
    if (t0 > t1) std::swap(t0, t1);
    return std::pair<S, S>{t0, t1};
}

/// How far the origin may move along the ray before solving: to where it enters the bounding
/// sphere (no hit lies before it), not at all when it starts inside.
template <Scalar S> [[nodiscard]] S origin_shift(const std::pair<S, S>& span) noexcept {
    return std::max(span.first, S(0));
}

/// Half-extent along each world axis of a circle of radius `radius` perpendicular to the unit
/// vector `axis`: radius * sin(angle between the world axis and `axis`). Exact.
template <Scalar S> [[nodiscard]] Vec3<S> circle_extent(const Vec3<S>& axis, S radius) noexcept {
    const Vec3<S> one_minus = glm::max(Vec3<S>(S(1)) - axis * axis, Vec3<S>(S(0)));
    return radius * Vec3<S>(std::sqrt(one_minus.x), std::sqrt(one_minus.y), std::sqrt(one_minus.z));
}

/// The box of a circle (centre, unit axis, radius).
template <Scalar S> [[nodiscard]] BBox<S> circle_bounds(const Vec3<S>& center, const Vec3<S>& axis, S radius) noexcept {
    const Vec3<S> e = circle_extent(axis, radius);
    return {center - e, center + e};
}

}  // namespace photon::detail
