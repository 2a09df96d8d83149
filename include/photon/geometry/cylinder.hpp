// SPDX-License-Identifier: MIT
#pragma once

#include <cmath>
#include <stdexcept>

#include "frustum.hpp"
#include "primitive.hpp"

namespace photon {

/// Cylinder between a base point and a cap point with a radius, closed by its two end discs
/// unless `open` (then a tube with no inside), as POV-Ray's `cylinder { B, C, r [open] }`.
/// Normals point outward, also for a ray that starts inside.
template <Scalar S> class Cylinder : public detail::FrustumShape<S> {
public:
    /// Throws std::invalid_argument unless the radius is positive, the points distinct and all finite.
    Cylinder(const Vec3<S>& base, const Vec3<S>& cap, S radius, bool open = false)
        : detail::FrustumShape<S>("cylinder", base, cap, checked_radius(radius), radius, open) {}

    [[nodiscard]] S radius() const noexcept { return this->f_.r_base; }

private:
    static S checked_radius(S radius) {
        if (!std::isfinite(radius) || !(radius > S(0)))
            throw std::invalid_argument("cylinder: radius must be positive and finite");
        return radius;
    }
};

}  // namespace photon
