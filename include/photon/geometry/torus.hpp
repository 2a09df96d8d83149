// SPDX-License-Identifier: MIT
#pragma once

#include <cmath>
#include <limits>
#include <optional>
#include <stdexcept>

#include "polynomial_roots.hpp"
#include "primitive.hpp"
#include "quadric_support.hpp"

namespace photon {

/// Torus around the y axis, centred at the origin, in the xz plane: the points at distance
/// `minor` from the circle of radius `major`, as POV-Ray's `torus { R, r }` (placed elsewhere
/// with Transformed). `minor` above `major` (a spindle torus) is allowed, as in POV-Ray.
template <Scalar S> class Torus {
public:
    using scalar_type = S;

    /// Throws std::invalid_argument unless both radii are positive and finite.
    Torus(S major, S minor) : major_(major), minor_(minor) {
        if (!(major > S(0)) || !(minor > S(0)) || !std::isfinite(major) || !std::isfinite(minor))
            throw std::invalid_argument("torus: major and minor radius must be positive and finite");
    }

    [[nodiscard]] S major_radius() const noexcept { return major_; }
    [[nodiscard]] S minor_radius() const noexcept { return minor_; }
    [[nodiscard]] BBox<S> bounds() const noexcept {
        const S outer = major_ + minor_;
        return {Vec3<S>(-outer, -minor_, -outer), Vec3<S>(outer, minor_, outer)};
    }

    /// Solid: the points within `minor` of the circle of radius `major` in the xz plane.
    [[nodiscard]] bool contains(const Vec3<S>& p) const noexcept {
        const S ring = std::sqrt(p.x * p.x + p.z * p.z) - major_;
        return ring * ring + p.y * p.y <= minor_ * minor_;
    }

    /// The quartic (|q|^2 + R^2 - r^2)^2 = 4 R^2 (qx^2 + qz^2) along the ray, solved in double
    /// (also for float) by bracketing (polynomial_roots.hpp), after three steps that keep its
    /// coefficients well conditioned: the origin moves to where the ray enters the bounding
    /// sphere (a far origin would cancel most digits of the constant term), lengths are in
    /// units of R + r (the coefficients are of order 1 at any scale, 1e-3 or 1e4), and the
    /// direction is unit length (the leading coefficient is 1).
    [[nodiscard]] std::optional<Hit<S>> intersect(const Ray<S>& ray) const noexcept {
        const S outer = major_ + minor_;
        const auto span = detail::sphere_span(ray, Vec3<S>(S(0)), outer);
        if (!span || !(span->second > S(0)) || !(span->first < ray.t_max)) return std::nullopt;
        const double shift = double(detail::origin_shift(*span));
        const glm::dvec3 d(ray.direction);
        const double speed = glm::length(d);
        if (!(speed > 0.0)) return std::nullopt;
        const double unit = double(outer);
        const glm::dvec3 p = (glm::dvec3(ray.origin) + shift * d) / unit, u = d / speed;
        const double big = double(major_) / unit, small = double(minor_) / unit;
        // Roots in t' = (t - shift) * speed / unit: up to the sphere's exit (a little past it,
        // rounding), and to t_max.
        double hi = (double(span->second) - shift) * speed / unit * (1.0 + 1e-9) + 1e-12;
        if (std::isfinite(double(ray.t_max))) hi = std::min(hi, (double(ray.t_max) - shift) * speed / unit);
        if (!(hi > 0.0)) return std::nullopt;

        const double k = glm::dot(p, u), m = glm::dot(p, p) + big * big - small * small, four_r2 = 4.0 * big * big;
        const std::array<double, 5> c{m * m - four_r2 * (p.x * p.x + p.z * p.z),
                                      4.0 * k * m - 2.0 * four_r2 * (p.x * u.x + p.z * u.z),
                                      4.0 * k * k + 2.0 * m - four_r2 * (u.x * u.x + u.z * u.z), 4.0 * k, 1.0};
        // From a little before the sphere's entry: where the ray enters the torus exactly there
        // (the outer equator touches the sphere), the rounded shift can pass the root.
        const double slack = 64.0 * double(std::numeric_limits<S>::epsilon()) *
                             (double(max_component(glm::abs(ray.origin))) / unit + 1.0);
        const auto roots = detail::roots_in<4>(c, -slack, hi);
        for (std::size_t i = 0; i < roots.count; ++i) {
            const double local = roots.value[i];
            const S t = S(shift + local * unit / speed);
            if (!(t > S(0)) || !(t < ray.t_max)) continue;
            const glm::dvec3 q = p + local * u;  // in units of R + r
            const double ring = std::sqrt(q.x * q.x + q.z * q.z);
            const glm::dvec3 n = ring > 0.0 ? q - big * glm::dvec3(q.x / ring, 0.0, q.z / ring)
                                            : glm::dvec3(0.0, q.y < 0.0 ? -1.0 : 1.0, 0.0);
            return Hit<S>{t, ray.at(t), Vec3<S>(glm::normalize(n))};
        }
        return std::nullopt;
    }

private:
    S major_, minor_;
};

}  // namespace photon
