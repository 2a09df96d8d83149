// SPDX-License-Identifier: MIT
#pragma once

#include <cstdint>

#include "../math/vec.hpp"

namespace photon {

/// Where a ray meets a surface. `normal` is the unit geometric normal: outward for closed shapes
/// (sphere, box), by winding for triangles (counter-clockwise seen from the front), as given for
/// planes. It is not flipped towards the ray; integrators decide which side they are on.
/// `part` says which part of a composite shape was hit (a CSG node's leaf, csg.hpp), 0 for
/// simple shapes; a Scene gives each part of an object its own material (Scene::add).
template <Scalar S> struct Hit {
    S t{};
    Vec3<S> point{};
    Vec3<S> normal{};
    std::uint32_t part = 0;
};

}  // namespace photon
