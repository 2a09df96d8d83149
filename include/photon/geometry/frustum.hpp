// SPDX-License-Identifier: MIT
#pragma once
// The intersection shared by Cylinder and Cone: a solid of revolution whose radius varies
// linearly from r_base at the base to r_cap at the cap (equal radii: a cylinder), with or without
// its two end discs.

#include <cmath>
#include <optional>
#include <stdexcept>
#include <string>

#include "hit.hpp"
#include "quadric_support.hpp"

namespace photon::detail {

template <Scalar S> struct Frustum {
    Vec3<S> base;  ///< centre of the base disc
    Vec3<S> axis;  ///< unit vector from the base to the cap
    S length;      ///< distance from the base to the cap
    S r_base, r_cap;
    bool open;  ///< without end discs

    [[nodiscard]] Vec3<S> center() const noexcept { return base + axis * (length * S(0.5)); }
    [[nodiscard]] S bounding_radius() const noexcept {
        return std::sqrt(squared(length * S(0.5)) + squared(std::max(r_base, r_cap)));
    }
    /// Exact: the solid is the convex hull of its two end circles.
    [[nodiscard]] BBox<S> bounds() const noexcept {
        BBox<S> b = circle_bounds(base, axis, r_base);
        return b.extend(circle_bounds(base + axis * length, axis, r_cap));
    }

    /// Solid: height along the axis in [0, length], distance from the axis within the radius
    /// there. The same closed solid when `open` (POV-Ray's inside test ignores `open` too).
    [[nodiscard]] bool contains(const Vec3<S>& p) const noexcept {
        const Vec3<S> o = p - base;
        const S h = glm::dot(o, axis);
        if (!(h >= S(0) && h <= length)) return false;
        const S r = r_base + (r_cap - r_base) / length * h;
        return length_squared(o - h * axis) <= r * r;
    }

    /// Nearest hit with t in (0, ray.t_max). The lateral surface is |p - (p.a) a| = r_base + k h
    /// with h = p.a and k = (r_cap - r_base) / length, squared into a quadratic in t; each root
    /// counts when its h lies in [0, length]. Solved from an origin moved to the bounding
    /// sphere, so a far origin costs no precision. Normals point outward whichever side the ray
    /// comes from (a ray from inside meets the wall with its normal along the ray).
    [[nodiscard]] std::optional<Hit<S>> intersect(const Ray<S>& ray) const noexcept {
        const auto span = sphere_span(ray, center(), bounding_radius());
        if (!span || !(span->second > S(0)) || !(span->first < ray.t_max)) return std::nullopt;
        const S shift = origin_shift(*span);
        const Vec3<S> o = ray.at(shift) - base, d = ray.direction;
        const S oa = glm::dot(o, axis), da = glm::dot(d, axis);
        const Vec3<S> op = o - oa * axis, dp = d - da * axis;
        const S k = (r_cap - r_base) / length;
        const S rho = r_base + k * oa;  // lateral radius at the origin's height
        const S a = glm::dot(dp, dp) - k * k * da * da;
        const S b = glm::dot(op, dp) - k * da * rho;
        const S c = glm::dot(op, op) - rho * rho;

        S best = std::numeric_limits<S>::infinity();
        int part = -1;  // 0 wall, 1 base disc, 2 cap disc
        const auto consider = [&](S t, int which) {
            const S total = shift + t;
            if (total > S(0) && total < ray.t_max && t < best) best = t, part = which;
        };
        const auto wall = [&](S t) {
            const S h = oa + t * da;
            if (h >= S(0) && h <= length) consider(t, 0);
        };
        if (a != S(0)) {
            if (const auto roots = solve_quadratic(a, b, c)) wall(roots->first), wall(roots->second);
        } else if (b != S(0)) {
            wall(-c / (S(2) * b));  // parallel to a generator of the cone: one crossing
        }
        if (!open && da != S(0)) {
            const auto cap = [&](S h, S r, int which) {
                if (!(r > S(0))) return;
                const S t = (h - oa) / da;
                const Vec3<S> q = op + t * dp;
                if (glm::dot(q, q) <= r * r) consider(t, which);
            };
            cap(S(0), r_base, 1);
            cap(length, r_cap, 2);
        }
        if (part < 0) return std::nullopt;

        Hit<S> hit;
        hit.t = shift + best;
        hit.point = ray.at(hit.t);
        if (part == 1) {
            hit.normal = -axis;
        } else if (part == 2) {
            hit.normal = axis;
        } else {
            const Vec3<S> q = op + best * dp;  // from the axis to the hit point
            const S ql = glm::length(q);
            // Outward normal of |q| - (r_base + k h): q / |q| - k a (the apex, q = 0: along the axis).
            hit.normal = ql > S(0) ? glm::normalize(q / ql - k * axis) : (k < S(0) ? axis : -axis);
        }
        return hit;
    }
};

/// What Cylinder and TruncatedCone share: the checks of the two points, the accessors, bounds and
/// intersection. Each shape checks its own radii before constructing it.
template <Scalar S> class FrustumShape {
public:
    using scalar_type = S;

    [[nodiscard]] const Vec3<S>& base() const noexcept { return f_.base; }
    [[nodiscard]] Vec3<S> cap() const noexcept { return f_.base + f_.axis * f_.length; }
    [[nodiscard]] const Vec3<S>& axis() const noexcept { return f_.axis; }
    [[nodiscard]] S length() const noexcept { return f_.length; }
    [[nodiscard]] bool open() const noexcept { return f_.open; }
    [[nodiscard]] BBox<S> bounds() const noexcept { return f_.bounds(); }
    [[nodiscard]] std::optional<Hit<S>> intersect(const Ray<S>& ray) const noexcept { return f_.intersect(ray); }
    [[nodiscard]] bool contains(const Vec3<S>& p) const noexcept { return f_.contains(p); }

protected:
    /// Throws std::invalid_argument, naming `shape`, unless the points are finite and distinct.
    FrustumShape(const char* shape, const Vec3<S>& base, const Vec3<S>& cap, S r_base, S r_cap, bool open) {
        const S length = glm::length(cap - base);
        if (!is_finite(base) || !is_finite(cap))
            throw std::invalid_argument(std::string(shape) + ": base and cap points must be finite");
        if (!(length > S(0)) || !std::isfinite(length))
            throw std::invalid_argument(std::string(shape) + ": base and cap points must differ");
        f_ = {base, (cap - base) / length, length, r_base, r_cap, open};
    }

    Frustum<S> f_;
};

}  // namespace photon::detail
