// SPDX-License-Identifier: MIT
#pragma once

#include <cmath>
#include <stdexcept>

#include "../math/sampling.hpp"
#include "../math/vec.hpp"

namespace photon {

/// Directions within `half_angle` of `axis`: the paper's light "field of view". A light with a
/// cone emits only into it; its power is what leaves through the cone.
template <Scalar S> class Cone {
public:
    /// Throws std::invalid_argument unless the axis is non-zero and 0 < half_angle <= 180 degrees.
    Cone(const Vec3<S>& axis, S half_angle_degrees) {
        const S len = glm::length(axis);
        if (!(len > S(0)) || !std::isfinite(len))
            throw std::invalid_argument("cone: direction must be non-zero and finite");
        if (!(half_angle_degrees > S(0)) || !(half_angle_degrees <= S(180)))
            throw std::invalid_argument("cone: half-angle must be in (0, 180] degrees");
        axis_ = axis / len;
        half_angle_ = half_angle_degrees;
        cos_half_angle_ = std::cos(half_angle_degrees * pi<S> / S(180));
        frame_ = Frame<S>::from_normal(axis_);
    }
    /// From a full field of view (twice the half-angle), in degrees.
    [[nodiscard]] static Cone from_field_of_view(const Vec3<S>& axis, S fov_degrees) {
        return Cone(axis, fov_degrees / S(2));
    }

    [[nodiscard]] const Vec3<S>& axis() const noexcept { return axis_; }
    [[nodiscard]] S half_angle_degrees() const noexcept { return half_angle_; }
    [[nodiscard]] S cos_half_angle() const noexcept { return cos_half_angle_; }
    [[nodiscard]] S solid_angle() const noexcept { return cone_solid_angle(cos_half_angle_); }
    [[nodiscard]] bool contains(const Vec3<S>& unit_dir) const noexcept {
        return glm::dot(unit_dir, axis_) >= cos_half_angle_;
    }
    /// Uniform direction in the cone.
    [[nodiscard]] Vec3<S> sample(Vec2<S> u) const noexcept {
        return frame_.to_world(uniform_cone(u, cos_half_angle_));
    }

private:
    Vec3<S> axis_;
    S half_angle_, cos_half_angle_;
    Frame<S> frame_;
};

}  // namespace photon
