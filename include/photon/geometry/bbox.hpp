// SPDX-License-Identifier: MIT
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>

#include "../math/vec.hpp"

namespace photon {

/// Axis-aligned bounding box. The default box is empty (min = +inf, max = -inf) so that
/// extending it with anything gives that thing.
template <Scalar S> struct BBox {
    Vec3<S> min{std::numeric_limits<S>::infinity()};
    Vec3<S> max{-std::numeric_limits<S>::infinity()};

    [[nodiscard]] static BBox infinite() noexcept {
        return {Vec3<S>(-std::numeric_limits<S>::infinity()), Vec3<S>(std::numeric_limits<S>::infinity())};
    }
    [[nodiscard]] static BBox of_point(const Vec3<S>& p) noexcept { return {p, p}; }

    BBox& extend(const Vec3<S>& p) noexcept {
        min = glm::min(min, p);
        max = glm::max(max, p);
        return *this;
    }
    BBox& extend(const BBox& b) noexcept {
        min = glm::min(min, b.min);
        max = glm::max(max, b.max);
        return *this;
    }
    [[nodiscard]] bool is_empty() const noexcept {
        return !(min.x <= max.x && min.y <= max.y && min.z <= max.z);
    }
    [[nodiscard]] bool is_finite() const noexcept {
        return !is_empty() && photon::is_finite(min) && photon::is_finite(max);
    }
    [[nodiscard]] Vec3<S> extent() const noexcept { return max - min; }
    [[nodiscard]] Vec3<S> center() const noexcept { return (min + max) * S(0.5); }
    [[nodiscard]] S half_area() const noexcept {
        const Vec3<S> e = glm::max(extent(), Vec3<S>(S(0)));
        return e.x * e.y + e.y * e.z + e.z * e.x;
    }
    [[nodiscard]] bool contains(const Vec3<S>& p) const noexcept {
        return p.x >= min.x && p.y >= min.y && p.z >= min.z && p.x <= max.x && p.y <= max.y &&
               p.z <= max.z;
    }
    [[nodiscard]] bool overlaps(const BBox& b) const noexcept {
        return min.x <= b.max.x && b.min.x <= max.x && min.y <= b.max.y && b.min.y <= max.y &&
               min.z <= b.max.z && b.min.z <= max.z;
    }
    /// Largest absolute coordinate of the box: the scale that floating-point errors follow.
    [[nodiscard]] S magnitude() const noexcept {
        return std::max(max_component(glm::abs(min)), max_component(glm::abs(max)));
    }
};

/// x in S, rounded towards -infinity (down) or +infinity (up): the corners of a box computed in
/// double, so that it never shrinks when stored in S.
template <Scalar S> [[nodiscard]] S rounded_down(double x) noexcept {
    const S y = S(x);
    return double(y) > x ? std::nextafter(y, -std::numeric_limits<S>::infinity()) : y;
}
template <Scalar S> [[nodiscard]] S rounded_up(double x) noexcept {
    const S y = S(x);
    return double(y) < x ? std::nextafter(y, std::numeric_limits<S>::infinity()) : y;
}

}  // namespace photon
