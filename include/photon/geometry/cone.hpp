// SPDX-License-Identifier: MIT
#pragma once

#include <cmath>
#include <optional>
#include <stdexcept>

#include "frustum.hpp"
#include "primitive.hpp"

namespace photon {

/// Cone, named TruncatedCone (light/cone.hpp's Cone is a cone of directions): from a base point
/// with its radius to a cap point with its radius, either radius possibly 0 (a pointed cone), closed by its end discs unless `open`, as
/// POV-Ray's `cone { B, rb, C, rc [open] }`. Normals point outward, also from inside.
template <Scalar S> class TruncatedCone {
public:
    using scalar_type = S;

    /// Throws std::invalid_argument on a negative radius, both radii 0, equal points or non-finite input.
    TruncatedCone(const Vec3<S>& base, S base_radius, const Vec3<S>& cap, S cap_radius, bool open = false) {
        if (!is_finite(base) || !is_finite(cap) || !std::isfinite(base_radius) || !std::isfinite(cap_radius) ||
            !(base_radius >= S(0)) || !(cap_radius >= S(0)))
            throw std::invalid_argument("cone: radii must be finite and not negative, points finite");
        if (!(base_radius > S(0) || cap_radius > S(0)))
            throw std::invalid_argument("cone: at least one radius must be positive");
        const S length = glm::length(cap - base);
        if (!(length > S(0)) || !std::isfinite(length))
            throw std::invalid_argument("cone: base and cap points must differ");
        f_ = {base, (cap - base) / length, length, base_radius, cap_radius, open};
    }

    [[nodiscard]] const Vec3<S>& base() const noexcept { return f_.base; }
    [[nodiscard]] Vec3<S> cap() const noexcept { return f_.base + f_.axis * f_.length; }
    [[nodiscard]] const Vec3<S>& axis() const noexcept { return f_.axis; }
    [[nodiscard]] S length() const noexcept { return f_.length; }
    [[nodiscard]] S base_radius() const noexcept { return f_.r_base; }
    [[nodiscard]] S cap_radius() const noexcept { return f_.r_cap; }
    [[nodiscard]] bool open() const noexcept { return f_.open; }
    [[nodiscard]] BBox<S> bounds() const noexcept { return f_.bounds(); }
    [[nodiscard]] std::optional<Hit<S>> intersect(const Ray<S>& ray) const noexcept { return f_.intersect(ray); }

private:
    detail::Frustum<S> f_;
};

}  // namespace photon
