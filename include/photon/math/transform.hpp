// SPDX-License-Identifier: MIT
#pragma once
// Affine transforms (translate, rotate, scale) of points, directions and normals.

#include <glm/mat3x3.hpp>
#include <glm/matrix.hpp>

#include <cmath>

#include "vec.hpp"

namespace photon {

/// x' = linear * x + translation. Composition follows the order written in a scene file:
/// `a.then(b)` applies a first, then b.
template <Scalar S> struct Affine {
    glm::mat<3, 3, S, glm::defaultp> linear{S(1)};
    Vec3<S> translation{S(0)};

    [[nodiscard]] static Affine identity() noexcept { return {}; }
    [[nodiscard]] static Affine translate(const Vec3<S>& t) noexcept {
        Affine a;
        a.translation = t;
        return a;
    }
    [[nodiscard]] static Affine scale(const Vec3<S>& s) noexcept {
        Affine a;
        a.linear = glm::mat<3, 3, S, glm::defaultp>(S(1));
        a.linear[0][0] = s.x;
        a.linear[1][1] = s.y;
        a.linear[2][2] = s.z;
        return a;
    }
    /// Rotation by `degrees` about the unit `axis`, counter-clockwise looking down the axis in a
    /// right-handed frame (rotate_axis(y, 90) takes +x to -z, as POV-Ray's `rotate <0,90,0>`).
    [[nodiscard]] static Affine rotate_axis(const Vec3<S>& axis, S degrees) noexcept {
        const S a = degrees * pi<S> / S(180);
        const S c = std::cos(a), s = std::sin(a), t = S(1) - c;
        const Vec3<S> u = glm::normalize(axis);
        Affine r;  // column-major: linear[column][row]
        r.linear[0] = {t * u.x * u.x + c, t * u.x * u.y + s * u.z, t * u.x * u.z - s * u.y};
        r.linear[1] = {t * u.x * u.y - s * u.z, t * u.y * u.y + c, t * u.y * u.z + s * u.x};
        r.linear[2] = {t * u.x * u.z + s * u.y, t * u.y * u.z - s * u.x, t * u.z * u.z + c};
        return r;
    }
    /// Rotation about x, then y, then z, by the components of `degrees` (POV-Ray's `rotate`).
    [[nodiscard]] static Affine rotate_xyz(const Vec3<S>& degrees) noexcept {
        return rotate_axis({1, 0, 0}, degrees.x)
            .then(rotate_axis({0, 1, 0}, degrees.y))
            .then(rotate_axis({0, 0, 1}, degrees.z));
    }

    /// This transform followed by `next`.
    [[nodiscard]] Affine then(const Affine& next) const noexcept {
        return {next.linear * linear, next.linear * translation + next.translation};
    }
    [[nodiscard]] Affine inverse() const noexcept {
        const auto inv = glm::inverse(linear);
        return {inv, -(inv * translation)};
    }
    [[nodiscard]] Vec3<S> point(const Vec3<S>& p) const noexcept { return linear * p + translation; }
    [[nodiscard]] Vec3<S> vector(const Vec3<S>& v) const noexcept { return linear * v; }
    /// Normals transform by the inverse transpose; the result is not normalised.
    [[nodiscard]] Vec3<S> normal_from_inverse(const Vec3<S>& n) const noexcept {
        return glm::transpose(linear) * n;
    }
    [[nodiscard]] S determinant() const noexcept { return glm::determinant(linear); }
    [[nodiscard]] bool is_identity() const noexcept {
        return linear == glm::mat<3, 3, S, glm::defaultp>(S(1)) && translation == Vec3<S>(S(0));
    }
};

}  // namespace photon
