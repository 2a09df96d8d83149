// SPDX-License-Identifier: MIT
#pragma once

#include <cmath>
#include <stdexcept>

#include "../geometry/ray.hpp"

namespace photon {

/// Pinhole camera with POV-Ray's conventions: a ray through image position (u, v) in [0,1]^2
/// (u to the right, v down) has direction `direction + (u - 0.5) right + (0.5 - v) up`.
/// With right = cross(up, direction), +x appears on the right for a camera looking along +z
/// with up +y (POV-Ray's left-handed view: red wall on the left in the Cornell box).
template <Scalar S> class PinholeCamera {
public:
    /// Raw POV-Ray vectors. Throws std::invalid_argument if they are degenerate.
    PinholeCamera(const Vec3<S>& location, const Vec3<S>& direction, const Vec3<S>& right, const Vec3<S>& up)
        : location_(location), direction_(direction), right_(right), up_(up) {
        if (!is_finite(location) || !is_finite(direction) || !is_finite(right) || !is_finite(up) ||
            !(glm::length(glm::cross(right, up)) > S(0)) || !(glm::length(direction) > S(0)))
            throw std::invalid_argument("camera: direction, right and up must be finite, non-zero and not parallel");
    }

    /// Looks from `location` at `target`, `sky` giving up. `horizontal_fov_degrees` in (0, 180),
    /// `aspect` = image width / height.
    [[nodiscard]] static PinholeCamera look_at(const Vec3<S>& location, const Vec3<S>& target, const Vec3<S>& sky,
                                               S horizontal_fov_degrees, S aspect) {
        if (!(horizontal_fov_degrees > S(0) && horizontal_fov_degrees < S(180)))
            throw std::invalid_argument("camera: field of view must be in (0, 180) degrees");
        if (!(aspect > S(0)) || !std::isfinite(aspect)) throw std::invalid_argument("camera: aspect must be positive");
        const Vec3<S> forward = target - location;
        if (!(glm::length(forward) > S(0))) throw std::invalid_argument("camera: look_at equals location");
        const Vec3<S> f = glm::normalize(forward);
        const Vec3<S> side = glm::cross(sky, f);
        if (!(glm::length(side) > S(0))) throw std::invalid_argument("camera: sky is parallel to the view direction");
        const Vec3<S> right = glm::normalize(side) * aspect;
        const Vec3<S> up = glm::normalize(glm::cross(f, right));
        const S focal = S(0.5) * aspect / std::tan(horizontal_fov_degrees * pi<S> / S(360));
        return PinholeCamera(location, f * focal, right, up);
    }

    /// Primary ray (unit direction) through image position (u, v).
    [[nodiscard]] Ray<S> ray(S u, S v) const noexcept {
        const Vec3<S> d = direction_ + (u - S(0.5)) * right_ + (S(0.5) - v) * up_;
        return {location_, glm::normalize(d)};
    }

    [[nodiscard]] const Vec3<S>& location() const noexcept { return location_; }
    [[nodiscard]] const Vec3<S>& direction() const noexcept { return direction_; }
    [[nodiscard]] const Vec3<S>& right() const noexcept { return right_; }
    [[nodiscard]] const Vec3<S>& up() const noexcept { return up_; }

private:
    Vec3<S> location_, direction_, right_, up_;
};

}  // namespace photon
