// SPDX-License-Identifier: MIT
#pragma once

#include <cmath>
#include <limits>
#include <optional>
#include <stdexcept>

#include "primitive.hpp"

namespace photon {

/// The infinite plane dot(p, normal) = offset. Its normal is the unit `normal` given; POV-Ray's
/// `plane { n, d }` is the solid half-space below it.
template <Scalar S> class Plane {
public:
    using scalar_type = S;

    /// Throws std::invalid_argument on a zero or non-finite normal.
    Plane(const Vec3<S>& normal, S offset) : offset_(offset) {
        const S len = glm::length(normal);
        if (!(len > S(0)) || !std::isfinite(len) || !std::isfinite(offset))
            throw std::invalid_argument("plane: normal must be non-zero and finite");
        normal_ = normal / len;
        offset_ = offset;
    }

    [[nodiscard]] const Vec3<S>& normal() const noexcept { return normal_; }
    [[nodiscard]] S offset() const noexcept { return offset_; }
    [[nodiscard]] BBox<S> bounds() const noexcept { return BBox<S>::infinite(); }

    /// Solid: the half-space below the plane (dot(p, normal) <= offset), as POV-Ray's; the
    /// normal points out of it.
    [[nodiscard]] bool contains(const Vec3<S>& p) const noexcept { return glm::dot(p, normal_) <= offset_; }

    [[nodiscard]] std::optional<Hit<S>> intersect(const Ray<S>& ray) const noexcept {
        const S denom = glm::dot(ray.direction, normal_);
        if (denom == S(0)) return std::nullopt;  // parallel: never hits, even when on the plane
        const S t = (offset_ - glm::dot(ray.origin, normal_)) / denom;
        if (!(t > S(0)) || !(t < ray.t_max)) return std::nullopt;
        return Hit<S>{t, ray.at(t), normal_};
    }

private:
    Vec3<S> normal_;
    S offset_;
};

}  // namespace photon
