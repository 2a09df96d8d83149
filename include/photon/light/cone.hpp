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
        // 1 - cos in double from the half-angle itself: in float 1 - cos(0.1 deg) is 4% off and
        // below 0.03 degrees it is 0, which made the intensity power / 0.
        const double theta = double(half_angle_degrees) * pi<double> / 180.0;
        one_minus_cos_ = S(one_minus_cos(theta));
        cos_half_angle_ = S(std::cos(theta));
        frame_ = Frame<S>::from_normal(axis_);
    }
    /// From a full field of view (twice the half-angle), in degrees.
    [[nodiscard]] static Cone from_field_of_view(const Vec3<S>& axis, S fov_degrees) {
        return Cone(axis, fov_degrees / S(2));
    }

    [[nodiscard]] const Vec3<S>& axis() const noexcept { return axis_; }
    [[nodiscard]] S half_angle_degrees() const noexcept { return half_angle_; }
    [[nodiscard]] S cos_half_angle() const noexcept { return cos_half_angle_; }
    [[nodiscard]] S one_minus_cos_half_angle() const noexcept { return one_minus_cos_; }
    [[nodiscard]] S solid_angle() const noexcept { return cone_solid_angle_1mc(one_minus_cos_); }
    /// Compared as 1 - cos, which stays exact for directions nearly along a narrow cone's axis.
    [[nodiscard]] bool contains(const Vec3<S>& unit_dir) const noexcept {
        return one_minus_cos_between(unit_dir, axis_) <= one_minus_cos_;
    }
    /// Uniform direction in the cone.
    [[nodiscard]] Vec3<S> sample(Vec2<S> u) const noexcept {
        return frame_.to_world(uniform_cone_1mc(u, one_minus_cos_));
    }

private:
    Vec3<S> axis_;
    S half_angle_, cos_half_angle_, one_minus_cos_;
    Frame<S> frame_;
};

}  // namespace photon
