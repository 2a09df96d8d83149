// SPDX-License-Identifier: MIT
#pragma once

#include <cmath>
#include <optional>
#include <stdexcept>

#include "primitive.hpp"
#include "quadric_support.hpp"

namespace photon {

/// Flat disc (centre, normal, radius) with an optional central hole, as POV-Ray's
/// `disc { C, N, r [, hole] }`: the points at distance in [hole, radius] from the centre. One
/// surface hit from either side; the normal is the given one (unit), not flipped to the ray.
template <Scalar S> class Disc {
public:
    using scalar_type = S;

    /// Throws std::invalid_argument on a zero normal, a radius not positive, a hole radius
    /// negative or not below the radius, or non-finite input.
    Disc(const Vec3<S>& center, const Vec3<S>& normal, S radius, S hole_radius = S(0)) : center_(center) {
        if (!is_finite(center) || !is_finite(normal) || !std::isfinite(radius) || !std::isfinite(hole_radius))
            throw std::invalid_argument("disc: centre, normal and radii must be finite");
        const S n = glm::length(normal);
        if (!(n > S(0))) throw std::invalid_argument("disc: normal must not be zero");
        if (!(radius > S(0))) throw std::invalid_argument("disc: radius must be positive");
        if (!(hole_radius >= S(0)) || !(hole_radius < radius))
            throw std::invalid_argument("disc: hole radius must be at least 0 and below the radius");
        normal_ = normal / n;
        radius_ = radius;
        hole_ = hole_radius;
    }

    [[nodiscard]] const Vec3<S>& center() const noexcept { return center_; }
    [[nodiscard]] const Vec3<S>& normal() const noexcept { return normal_; }
    [[nodiscard]] S radius() const noexcept { return radius_; }
    [[nodiscard]] S hole_radius() const noexcept { return hole_; }
    [[nodiscard]] BBox<S> bounds() const noexcept { return detail::circle_bounds(center_, normal_, radius_); }

    /// The plane's crossing, measured from the centre (so a far origin cancels no digits of the
    /// offset within the disc), kept when it lies in the ring.
    [[nodiscard]] std::optional<Hit<S>> intersect(const Ray<S>& ray) const noexcept {
        const S denom = glm::dot(ray.direction, normal_);
        if (denom == S(0)) return std::nullopt;  // parallel, also when in the plane: no area seen
        const Vec3<S> to_origin = ray.origin - center_;
        const S t = -glm::dot(to_origin, normal_) / denom;
        if (!(t > S(0)) || !(t < ray.t_max)) return std::nullopt;
        const Vec3<S> q = to_origin + t * ray.direction;
        const Vec3<S> in_plane = q - glm::dot(q, normal_) * normal_;
        const S r2 = glm::dot(in_plane, in_plane);
        if (r2 > radius_ * radius_ || r2 < hole_ * hole_) return std::nullopt;
        return Hit<S>{t, ray.at(t), normal_};
    }

private:
    Vec3<S> center_, normal_;
    S radius_, hole_;
};

}  // namespace photon
