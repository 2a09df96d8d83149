// SPDX-License-Identifier: MIT
#pragma once

#include <cmath>
#include <optional>
#include <stdexcept>

#include "frustum.hpp"
#include "primitive.hpp"

namespace photon {

/// Cylinder between a base point and a cap point with a radius, closed by its two end discs
/// unless `open` (then a tube with no inside), as POV-Ray's `cylinder { B, C, r [open] }`.
/// Normals point outward, also for a ray that starts inside.
template <Scalar S> class Cylinder {
public:
    using scalar_type = S;

    /// Throws std::invalid_argument unless the radius is positive, the points distinct and all finite.
    Cylinder(const Vec3<S>& base, const Vec3<S>& cap, S radius, bool open = false) {
        if (!is_finite(base) || !is_finite(cap) || !std::isfinite(radius) || !(radius > S(0)))
            throw std::invalid_argument("cylinder: radius must be positive and finite, points finite");
        const S length = glm::length(cap - base);
        if (!(length > S(0)) || !std::isfinite(length))
            throw std::invalid_argument("cylinder: base and cap points must differ");
        f_ = {base, (cap - base) / length, length, radius, radius, open};
    }

    [[nodiscard]] const Vec3<S>& base() const noexcept { return f_.base; }
    [[nodiscard]] Vec3<S> cap() const noexcept { return f_.base + f_.axis * f_.length; }
    [[nodiscard]] const Vec3<S>& axis() const noexcept { return f_.axis; }
    [[nodiscard]] S length() const noexcept { return f_.length; }
    [[nodiscard]] S radius() const noexcept { return f_.r_base; }
    [[nodiscard]] bool open() const noexcept { return f_.open; }
    [[nodiscard]] BBox<S> bounds() const noexcept { return f_.bounds(); }
    [[nodiscard]] std::optional<Hit<S>> intersect(const Ray<S>& ray) const noexcept { return f_.intersect(ray); }

private:
    detail::Frustum<S> f_;
};

}  // namespace photon
