// SPDX-License-Identifier: MIT
#pragma once

#include <cmath>
#include <optional>
#include <stdexcept>

#include "../config.hpp"
#include "primitive.hpp"

namespace photon {

namespace detail {
/// Unit normal along cross(e1, e2), or zero when the triangle has no representable area. The
/// cross product is scaled by its largest component before normalising: for a triangle with edges
/// near the bottom of the exponent range (1e-19 in float) its squared length underflows to 0 and
/// a plain normalize gives NaN although the cross product itself is not zero.
template <Scalar S> [[nodiscard]] inline Vec3<S> triangle_normal(const Vec3<S>& e1, const Vec3<S>& e2) noexcept {
    const Vec3<S> n = glm::cross(e1, e2);
    const S largest = max_component(glm::abs(n));
    if (!(largest > S(0)) || !std::isfinite(largest)) return Vec3<S>(S(0));
    return glm::normalize(n / largest);
}

/// Moller-Trumbore ray/triangle test on (v0, e1 = v1 - v0, e2 = v2 - v0). Returns t in
/// (0, t_max) or nothing. Degenerate triangles (zero area) have det = 0 and never hit.
template <Scalar S>
[[nodiscard]] PHOTON_FORCEINLINE std::optional<S> intersect_triangle(const Ray<S>& ray, const Vec3<S>& v0,
                                                                     const Vec3<S>& e1, const Vec3<S>& e2) noexcept {
    const Vec3<S> p = glm::cross(ray.direction, e2);
    const S det = glm::dot(e1, p);
    if (det == S(0) || !std::isfinite(det)) return std::nullopt;
    const S inv_det = S(1) / det;
    const Vec3<S> s = ray.origin - v0;
    const S u = glm::dot(s, p) * inv_det;
    if (u < S(0) || u > S(1)) return std::nullopt;
    const Vec3<S> q = glm::cross(s, e1);
    const S v = glm::dot(ray.direction, q) * inv_det;
    if (v < S(0) || u + v > S(1)) return std::nullopt;
    const S t = glm::dot(e2, q) * inv_det;
    if (!(t > S(0)) || !(t < ray.t_max)) return std::nullopt;
    return t;
}
}  // namespace detail

/// A single triangle; its normal follows the winding (counter-clockwise v0, v1, v2 seen from the
/// front). Degenerate triangles are accepted and never hit.
template <Scalar S> class Triangle {
public:
    using scalar_type = S;

    /// Throws std::invalid_argument on non-finite vertices.
    Triangle(const Vec3<S>& v0, const Vec3<S>& v1, const Vec3<S>& v2) : v0_(v0), e1_(v1 - v0), e2_(v2 - v0) {
        if (!is_finite(v0) || !is_finite(v1) || !is_finite(v2))
            throw std::invalid_argument("triangle: vertices must be finite");
        normal_ = detail::triangle_normal(e1_, e2_);
    }

    [[nodiscard]] Vec3<S> vertex(int i) const noexcept { return i == 0 ? v0_ : (i == 1 ? v0_ + e1_ : v0_ + e2_); }
    [[nodiscard]] const Vec3<S>& normal() const noexcept { return normal_; }
    [[nodiscard]] bool is_degenerate() const noexcept { return normal_ == Vec3<S>(S(0)); }
    [[nodiscard]] BBox<S> bounds() const noexcept {
        return BBox<S>::of_point(v0_).extend(v0_ + e1_).extend(v0_ + e2_);
    }

    [[nodiscard]] std::optional<Hit<S>> intersect(const Ray<S>& ray) const noexcept {
        if (is_degenerate()) return std::nullopt;
        const auto t = detail::intersect_triangle(ray, v0_, e1_, e2_);
        if (!t) return std::nullopt;
        return Hit<S>{*t, ray.at(*t), normal_};
    }

private:
    Vec3<S> v0_, e1_, e2_, normal_;
};

}  // namespace photon
