// SPDX-License-Identifier: MIT
#pragma once
// Orthonormal frame around a unit vector.

#include <cmath>

#include "vec.hpp"

namespace photon {

/// Right-handed orthonormal basis (tangent, bitangent, normal) with `normal` as the z axis.
/// Built without branches on near-parallel axes (Duff et al. 2017, "Building an Orthonormal
/// Basis, Revisited").
template <Scalar S> struct Frame {
    Vec3<S> tangent, bitangent, normal;

    [[nodiscard]] static Frame from_normal(const Vec3<S>& n) noexcept {
        const S sign = std::copysign(S(1), n.z);
        const S a = S(-1) / (sign + n.z);
        const S b = n.x * n.y * a;
        return {{S(1) + sign * n.x * n.x * a, sign * b, -sign * n.x},
                {b, sign + n.y * n.y * a, -n.y},
                n};
    }
    /// Local coordinates (x along tangent, z along normal) to world.
    [[nodiscard]] Vec3<S> to_world(const Vec3<S>& v) const noexcept {
        return v.x * tangent + v.y * bitangent + v.z * normal;
    }
    [[nodiscard]] Vec3<S> to_local(const Vec3<S>& v) const noexcept {
        return {glm::dot(v, tangent), glm::dot(v, bitangent), glm::dot(v, normal)};
    }
};

}  // namespace photon
