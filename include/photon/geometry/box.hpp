// SPDX-License-Identifier: MIT
#pragma once

#include <algorithm>
#include <cmath>
#include <optional>
#include <stdexcept>

#include "primitive.hpp"

namespace photon {

/// Axis-aligned solid box between two corners; normals point outward. Rotated boxes are
/// `Transformed<Box>`.
template <Scalar S> class Box {
public:
    using scalar_type = S;

    /// Corners in any order. Throws std::invalid_argument on non-finite corners. A box with zero
    /// thickness along an axis is allowed (a rectangle).
    Box(const Vec3<S>& corner_a, const Vec3<S>& corner_b)
        : box_{glm::min(corner_a, corner_b), glm::max(corner_a, corner_b)} {
        if (!is_finite(corner_a) || !is_finite(corner_b))
            throw std::invalid_argument("box: corners must be finite");
    }

    [[nodiscard]] const Vec3<S>& min() const noexcept { return box_.min; }
    [[nodiscard]] const Vec3<S>& max() const noexcept { return box_.max; }
    [[nodiscard]] BBox<S> bounds() const noexcept { return box_; }

    /// Solid: the closed box.
    [[nodiscard]] bool contains(const Vec3<S>& p) const noexcept { return box_.contains(p); }

    /// Slab test (Kay and Kajiya). Returns the entry point, or the exit point for a ray that
    /// starts inside; the normal is that of the slab that decided t.
    [[nodiscard]] std::optional<Hit<S>> intersect(const Ray<S>& ray) const noexcept {
        S t_near = -std::numeric_limits<S>::infinity(), t_far = std::numeric_limits<S>::infinity();
        int axis_near = -1, axis_far = -1;
        for (int a = 0; a < 3; ++a) {
            const S d = ray.direction[a];
            if (d == S(0)) {
                if (ray.origin[a] < box_.min[a] || ray.origin[a] > box_.max[a]) return std::nullopt;
                continue;
            }
            const S inv = S(1) / d;
            S t0 = (box_.min[a] - ray.origin[a]) * inv, t1 = (box_.max[a] - ray.origin[a]) * inv;
            if (t0 > t1) std::swap(t0, t1);
            if (t0 > t_near) t_near = t0, axis_near = a;
            if (t1 < t_far) t_far = t1, axis_far = a;
        }
        if (!(t_near <= t_far)) return std::nullopt;
        const bool entering = t_near > S(0);
        const S t = entering ? t_near : t_far;
        const int axis = entering ? axis_near : axis_far;
        if (!(t > S(0)) || !(t < ray.t_max) || axis < 0) return std::nullopt;
        Hit<S> hit;
        hit.t = t;
        hit.point = ray.at(t);
        hit.normal = Vec3<S>(S(0));
        // Entering through a slab faces against the ray; leaving faces along it.
        const S sign = entering ? -std::copysign(S(1), ray.direction[axis])
                                : std::copysign(S(1), ray.direction[axis]);
        hit.normal[axis] = sign;
        return hit;
    }

private:
    BBox<S> box_;
};

}  // namespace photon
