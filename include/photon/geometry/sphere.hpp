// SPDX-License-Identifier: MIT
#pragma once

#include <cmath>
#include <optional>
#include <stdexcept>

#include "primitive.hpp"

namespace photon {

/// Sphere given by centre and radius; the normal points outward.
template <Scalar S> class Sphere {
public:
    using scalar_type = S;

    /// Throws std::invalid_argument unless the radius is positive and finite.
    Sphere(const Vec3<S>& center, S radius) : center_(center), radius_(radius) {
        if (!(radius > S(0)) || !std::isfinite(radius) || !is_finite(center))
            throw std::invalid_argument("sphere: radius must be positive and finite, centre finite");
    }

    [[nodiscard]] const Vec3<S>& center() const noexcept { return center_; }
    [[nodiscard]] S radius() const noexcept { return radius_; }
    [[nodiscard]] BBox<S> bounds() const noexcept { return {center_ - radius_, center_ + radius_}; }

    /// Solid: the closed ball.
    [[nodiscard]] bool contains(const Vec3<S>& p) const noexcept {
        return length_squared(p - center_) <= radius_ * radius_;
    }

    /// Roots of |o + t d - c|^2 = r^2, computed without cancellation: the discriminant from the
    /// distance between the centre and the ray's closest point (Hearn and Baker), the small root
    /// from c / q (Press et al.). See Haines et al., "Precision Improvements for Ray/Sphere
    /// Intersection", Ray Tracing Gems (2019), chapter 7.
    [[nodiscard]] std::optional<Hit<S>> intersect(const Ray<S>& ray) const noexcept {
        const Vec3<S> f = ray.origin - center_;
        const S a = glm::dot(ray.direction, ray.direction);
        const S b = glm::dot(f, ray.direction);  // half the linear coefficient
        const S c = glm::dot(f, f) - radius_ * radius_;
        const Vec3<S> closest = f - (b / a) * ray.direction;
        const S discriminant = a * (radius_ * radius_ - glm::dot(closest, closest));
        if (!(discriminant >= S(0))) return std::nullopt;
        const S q = -(b + std::copysign(std::sqrt(discriminant), b));
        S t0 = c / q, t1 = q / a;
        if (q == S(0)) t0 = t1 = S(0);  // grazing ray from the centre's plane; both roots at 0
        if (t0 > t1) std::swap(t0, t1);
        S t = t0;
        if (!(t > S(0))) t = t1;
        if (!(t > S(0)) || !(t < ray.t_max)) return std::nullopt;
        Hit<S> hit;
        hit.t = t;
        hit.point = ray.at(t);
        hit.normal = (hit.point - center_) / radius_;
        hit.normal = glm::normalize(hit.normal);
        return hit;
    }

private:
    Vec3<S> center_;
    S radius_;
};

}  // namespace photon
