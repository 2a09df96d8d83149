// SPDX-License-Identifier: MIT
#pragma once
// POV-Ray's sor (surface of revolution): around the y axis, the squared radius is a cubic in the
// height on each segment, the Hermite cubic through the squared radii of two points P[i+1],
// P[i+2] with the slopes POV-Ray takes from their neighbours (d(r^2)/dy = 2 r dr/dy, dr/dy from
// P[i] to P[i+2] and from P[i+1] to P[i+3]); N points give N - 3 segments. Closed by flat discs
// at the lowest and highest height unless `open` (the inside is the closed solid's then too, as
// POV-Ray's).
//
// Along a ray the height is linear and the squared distance from the axis quadratic in t, so
// each segment is a cubic in t, solved by bracketing (polynomial_roots.hpp) over the t where
// the ray is at the segment's heights. In double, also for float, with the origin first moved
// along the ray next to the shape; each segment's cubic is kept in its own parameter
// s = (y - y1) / (y2 - y1), so heights far from 0 lose no digits.

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <optional>
#include <stdexcept>
#include <vector>

#include "polynomial_roots.hpp"
#include "primitive.hpp"

namespace photon {

template <Scalar S> class Sor {
public:
    using scalar_type = S;

    /// POV-Ray's points as (radius, height): at least four, radii not negative, the heights of
    /// the second to the second-last strictly rising, every point finite. Throws
    /// std::invalid_argument otherwise.
    explicit Sor(const std::vector<glm::dvec2>& points, bool open = false) : open_(open) {
        const std::size_t n = points.size();
        if (n < 4) throw std::invalid_argument("sor: at least four points are needed");
        for (std::size_t i = 0; i < n; ++i) {
            if (!std::isfinite(points[i].x) || !std::isfinite(points[i].y) || points[i].x < 0.0)
                throw std::invalid_argument("sor: points must be finite with radii not negative");
            if (i > 1 && i + 1 < n && !(points[i].y > points[i - 1].y))
                throw std::invalid_argument("sor: the heights of the second to the second-last point must rise");
        }
        if (!(points[2].y != points[0].y) || !(points[n - 1].y != points[n - 3].y))
            throw std::invalid_argument("sor: the first and last points need heights apart from their neighbours'");
        double radius2 = 0.0;
        for (std::size_t i = 0; i + 3 < n; ++i) {
            const glm::dvec2 p0 = points[i], p1 = points[i + 1], p2 = points[i + 2], p3 = points[i + 3];
            Segment g;
            g.y1 = p1.y, g.height = p2.y - p1.y;
            // Hermite in s: values r^2 at both ends, slopes d(r^2)/ds = 2 r dr/dy * height.
            const double v0 = p1.x * p1.x, v1 = p2.x * p2.x;
            const double m0 = 2.0 * p1.x * (p2.x - p0.x) / (p2.y - p0.y) * g.height;
            const double m1 = 2.0 * p2.x * (p3.x - p1.x) / (p3.y - p1.y) * g.height;
            g.q = {v0, m0, 3.0 * (v1 - v0) - 2.0 * m0 - m1, 2.0 * (v0 - v1) + m0 + m1};
            // The widest squared radius: the ends and the turns of q.
            g.radius2 = std::max(v0, v1);
            const auto turns = detail::roots_in<2>({g.q[1], 2.0 * g.q[2], 3.0 * g.q[3]}, 0.0, 1.0);
            for (std::size_t k = 0; k < turns.count; ++k) g.radius2 = std::max(g.radius2, at(g.q, turns.value[k]));
            radius2 = std::max(radius2, g.radius2);
            segments_.push_back(g);
        }
        y_lo_ = points[1].y, y_hi_ = points[n - 2].y;
        base_radius2_ = std::max(0.0, segments_.front().q[0]);
        cap_radius2_ = std::max(0.0, at(segments_.back().q, 1.0));
        radius_ = std::sqrt(radius2);
        const double pad = 4.0 * std::numeric_limits<S>::epsilon() * std::max({radius_, std::abs(y_lo_), std::abs(y_hi_)});
        bounds_ = {Vec3<S>(S(-radius_ - pad), S(y_lo_ - pad), S(-radius_ - pad)),
                   Vec3<S>(S(radius_ + pad), S(y_hi_ + pad), S(radius_ + pad))};
    }

    [[nodiscard]] bool open() const noexcept { return open_; }
    [[nodiscard]] BBox<S> bounds() const noexcept { return bounds_; }

    /// Solid: between the lowest and highest height, within the squared radius of that height.
    [[nodiscard]] bool contains(const Vec3<S>& p) const noexcept {
        const glm::dvec3 q(p);
        if (!(q.y >= y_lo_ && q.y <= y_hi_)) return false;
        const Segment& g = segment_at(q.y);
        return q.x * q.x + q.z * q.z <= at(g.q, (q.y - g.y1) / g.height);
    }

    [[nodiscard]] std::optional<Hit<S>> intersect(const Ray<S>& ray) const noexcept {
        glm::dvec3 d(ray.direction);
        const double speed = glm::length(d);
        if (!(speed > 0.0)) return std::nullopt;
        d /= speed;
        const glm::dvec3 centre(0.0, 0.5 * (y_lo_ + y_hi_), 0.0);
        const double shift = glm::dot(centre - glm::dvec3(ray.origin), d);
        const glm::dvec3 o = glm::dvec3(ray.origin) + shift * d;  // local t' = t * speed - shift
        const double r = d.x * d.x + d.z * d.z, m = d.x * o.x + d.z * o.z, rho2 = o.x * o.x + o.z * o.z;
        // The ray's stretch within the widest radius (a vertical ray: all of it, or none).
        double lo = -shift, hi = std::isfinite(double(ray.t_max)) ? double(ray.t_max) * speed - shift
                                                                   : std::numeric_limits<double>::infinity();
        const double reach2 = radius_ * radius_ * (1.0 + 1e-9);
        if (r > 0.0) {
            const double gap2 = std::max(0.0, rho2 - m * m / r);
            if (gap2 > reach2) return std::nullopt;
            const double half = std::sqrt((reach2 - gap2) / r) + 1e-9 * radius_, centre_t = -m / r;
            lo = std::max(lo, centre_t - half), hi = std::min(hi, centre_t + half);
        } else if (rho2 > reach2) {
            return std::nullopt;
        }
        if (!(lo < hi)) return std::nullopt;

        double best = hi;
        glm::dvec3 normal(0.0);
        bool found = false;
        const auto take = [&](double t, const glm::dvec3& n) {
            if (!(t > lo && t < best)) return;
            const S world = S((t + shift) / speed);
            if (!(world > S(0)) || !(world < ray.t_max)) return;
            best = t, normal = n, found = true;
        };
        if (!open_ && d.y != 0.0)
            for (const bool top : {false, true}) {
                const double h = top ? y_hi_ : y_lo_, disc2 = top ? cap_radius2_ : base_radius2_;
                const double t = (h - o.y) / d.y, px = o.x + t * d.x, pz = o.z + t * d.z;
                if (disc2 > 0.0 && px * px + pz * pz <= disc2) take(t, glm::dvec3(0.0, top ? 1.0 : -1.0, 0.0));
            }
        for (const Segment& g : segments_) {
            if (g.radius2 < 0.0) continue;
            // s(t) = s0 + s1 t; the ray's t at the segment's heights.
            const double s1 = d.y / g.height, s0 = (o.y - g.y1) / g.height;
            double a = lo, b = std::min(hi, best);
            if (s1 != 0.0) {
                double ta = -s0 / s1, tb = (1.0 - s0) / s1;
                if (ta > tb) std::swap(ta, tb);
                a = std::max(a, ta), b = std::min(b, tb);
            } else if (!(s0 >= 0.0 && s0 <= 1.0)) {
                continue;
            }
            if (!(a <= b)) continue;
            // q(s0 + s1 t) - (rho2 + 2 m t + r t^2), composed by Horner's rule.
            std::array<double, 4> c{g.q[3], 0.0, 0.0, 0.0};
            for (int k = 2; k >= 0; --k) {
                // c <- c * (s0 + s1 t) + q[k]
                std::array<double, 4> next{};
                for (int j = 0; j < 3; ++j) next[std::size_t(j)] += c[std::size_t(j)] * s0, next[std::size_t(j + 1)] += c[std::size_t(j)] * s1;
                next[0] += g.q[std::size_t(k)];
                c = next;
            }
            c[0] -= rho2, c[1] -= 2.0 * m, c[2] -= r;
            const auto roots = detail::roots_in<3>(c, a, b);
            for (std::size_t k = 0; k < roots.count; ++k) {
                const double t = roots.value[k];
                const glm::dvec3 p = o + t * d;
                const double s = std::clamp(s0 + s1 * t, 0.0, 1.0);
                take(t, glm::dvec3(p.x, -0.5 * slope(g.q, s) / g.height, p.z));
            }
        }
        if (!found) return std::nullopt;
        const S t = S((best + shift) / speed);
        if (normal == glm::dvec3(0.0)) normal = glm::dvec3(0.0, 1.0, 0.0);
        return Hit<S>{t, ray.at(t), Vec3<S>(glm::normalize(normal))};
    }

private:
    struct Segment {
        double y1 = 0.0, height = 1.0;  ///< the segment spans y1 to y1 + height
        std::array<double, 4> q{};      ///< r^2 = q[0] + q[1] s + q[2] s^2 + q[3] s^3, s = (y - y1) / height
        double radius2 = 0.0;           ///< the largest r^2 on it
    };

    [[nodiscard]] static double at(const std::array<double, 4>& k, double s) noexcept {
        return k[0] + s * (k[1] + s * (k[2] + s * k[3]));
    }
    [[nodiscard]] static double slope(const std::array<double, 4>& k, double s) noexcept {
        return k[1] + s * (2.0 * k[2] + s * 3.0 * k[3]);
    }
    /// The first segment whose heights hold y (as POV-Ray's inside test).
    [[nodiscard]] const Segment& segment_at(double y) const noexcept {
        for (const Segment& g : segments_)
            if (y <= g.y1 + g.height) return g;
        return segments_.back();
    }

    std::vector<Segment> segments_;
    double y_lo_ = 0.0, y_hi_ = 0.0, radius_ = 0.0, base_radius2_ = 0.0, cap_radius2_ = 0.0;
    bool open_ = false;
    BBox<S> bounds_;
};

}  // namespace photon
