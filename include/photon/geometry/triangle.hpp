// SPDX-License-Identifier: MIT
#pragma once

#include <cmath>
#include <optional>
#include <stdexcept>
#include <type_traits>

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

/// A ray prepared for the watertight ray/triangle test of Woop, Benthin and Wald (2013,
/// "Watertight Ray/Triangle Intersection"): the vertices are translated to the ray origin and
/// sheared so that the ray runs along the z axis. Two triangles sharing an edge then compute the
/// same edge function for it (with opposite signs), so no ray slips between the triangles of a
/// mesh, as it can with Moller-Trumbore. (This needs the products rounded separately: no FMA
/// contraction, which baseline x86-64 has no instruction for.)
template <Scalar S> struct WatertightRay {
    Vec3<S> origin;
    int kz;        ///< the direction's largest axis; the test is instantiated for each (see below)
    S sx, sy, sz;  ///< shear and scale

    explicit WatertightRay(const Ray<S>& ray) noexcept : origin(ray.origin), kz(max_dimension(glm::abs(ray.direction))) {
        const Vec3<S> d = ray.direction;
        sx = d[(kz + 1) % 3] / d[kz];
        sy = d[(kz + 2) % 3] / d[kz];
        sz = S(1) / d[kz];
    }
};

/// Calls f(std::integral_constant<int, Kz>) with Kz = ray.kz, so that the axes of the watertight
/// test are compile-time constants in everything f runs.
template <Scalar S, class F> PHOTON_FORCEINLINE decltype(auto) with_shear_axis(const WatertightRay<S>& ray, F&& f) {
    switch (ray.kz) {
    case 0: return f(std::integral_constant<int, 0>{});
    case 1: return f(std::integral_constant<int, 1>{});
    default: return f(std::integral_constant<int, 2>{});
    }
}

/// Watertight test of the triangle (v0, v1, v2) for a ray whose kz is Kz: t in (0, t_max) or
/// nothing. Degenerate triangles and non-finite values never hit. Edges and vertices count as
/// inside, so a ray through a shared edge hits at least one of the two triangles. Both windings
/// are hit (the paper's swap of x and y for negative directions only fixes the sign of det).
template <int Kz, Scalar S>
[[nodiscard]] PHOTON_FORCEINLINE std::optional<S> intersect_watertight(const WatertightRay<S>& ray, S t_max,
                                                                       const Vec3<S>& v0, const Vec3<S>& v1,
                                                                       const Vec3<S>& v2) noexcept {
    constexpr int kx = (Kz + 1) % 3, ky = (Kz + 2) % 3;
    const Vec3<S> a = v0 - ray.origin, b = v1 - ray.origin, c = v2 - ray.origin;
    const S ax = a[kx] - ray.sx * a[Kz], ay = a[ky] - ray.sy * a[Kz];
    const S bx = b[kx] - ray.sx * b[Kz], by = b[ky] - ray.sy * b[Kz];
    const S cx = c[kx] - ray.sx * c[Kz], cy = c[ky] - ray.sy * c[Kz];
    S u = cx * by - cy * bx, v = ax * cy - ay * cx, w = bx * ay - by * ax;
    if constexpr (sizeof(S) < sizeof(double)) {
        // An edge function of exactly zero may be a rounding artefact: decide it in double.
        if (u == S(0) || v == S(0) || w == S(0)) {
            u = S(double(cx) * double(by) - double(cy) * double(bx));
            v = S(double(ax) * double(cy) - double(ay) * double(cx));
            w = S(double(bx) * double(ay) - double(by) * double(ax));
        }
    }
    if ((u < S(0) || v < S(0) || w < S(0)) && (u > S(0) || v > S(0) || w > S(0))) return std::nullopt;
    const S det = u + v + w;
    if (det == S(0) || !std::isfinite(det)) return std::nullopt;
    const S t = ray.sz * (u * a[Kz] + v * b[Kz] + w * c[Kz]) / det;
    if (!(t > S(0)) || !(t < t_max)) return std::nullopt;
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
