// SPDX-License-Identifier: MIT
#pragma once

#include "../math/vec.hpp"

namespace photon {

/// Where a ray meets a surface. `normal` is the unit geometric normal: outward for closed shapes
/// (sphere, box), by winding for triangles (counter-clockwise seen from the front), as given for
/// planes. It is not flipped towards the ray; integrators decide which side they are on.
template <Scalar S> struct Hit {
    S t{};
    Vec3<S> point{};
    Vec3<S> normal{};
};

}  // namespace photon
