// SPDX-License-Identifier: MIT
#pragma once

#include <cmath>
#include <stdexcept>

#include "frustum.hpp"
#include "primitive.hpp"

namespace photon {

/// Cone, named TruncatedCone (light/cone.hpp's Cone is a cone of directions): from a base point
/// with its radius to a cap point with its radius, either radius possibly 0 (a pointed cone),
/// closed by its end discs unless `open`, as POV-Ray's `cone { B, rb, C, rc [open] }`. Normals
/// point outward, also from inside.
template <Scalar S> class TruncatedCone : public detail::FrustumShape<S> {
public:
    /// Throws std::invalid_argument on a negative radius, both radii 0, equal points or non-finite input.
    TruncatedCone(const Vec3<S>& base, S base_radius, const Vec3<S>& cap, S cap_radius, bool open = false)
        : detail::FrustumShape<S>("cone", base, cap, checked_radii(base_radius, cap_radius), cap_radius, open) {}

    [[nodiscard]] S base_radius() const noexcept { return this->f_.r_base; }
    [[nodiscard]] S cap_radius() const noexcept { return this->f_.r_cap; }

private:
    /// The base radius, after checking both.
    static S checked_radii(S base_radius, S cap_radius) {
        if (!std::isfinite(base_radius) || !std::isfinite(cap_radius) || !(base_radius >= S(0)) ||
            !(cap_radius >= S(0)))
            throw std::invalid_argument("cone: radii must be finite and not negative");
        if (!(base_radius > S(0) || cap_radius > S(0)))
            throw std::invalid_argument("cone: at least one radius must be positive");
        return base_radius;
    }
};

}  // namespace photon
