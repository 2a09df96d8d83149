// SPDX-License-Identifier: MIT
#pragma once
// POV-Ray's lathe: a profile of line, quadratic and cubic Bezier curves in the (radius, height)
// plane turned around the y axis, exactly (no tessellation). POV-Ray's four spline types are all
// such curves (the scene language converts linear, quadratic, cubic and Bezier points to them).
//
// A ray meets the surface of one curve (X(w), Y(w)), w in [0, 1], where its height is Y(w) and
// its distance from the axis |X(w)|; with the ray o + t d, eliminating t = (Y - o.y) / d.y gives
//   F(w) = r (Y - o.y)^2 + 2 m d.y (Y - o.y) + d.y^2 (o.x^2 + o.z^2 - X^2) = 0,
// r = d.x^2 + d.z^2, m = d.x o.x + d.z o.z, a polynomial of twice the curve's degree (POV-Ray's
// equation), solved by bracketing (polynomial_roots.hpp). For a ray within 1e-5 of horizontal F
// degenerates to a double root; there the heights Y(w) = o.y are solved instead and the ring's
// quadratic gives t. Either way a few Newton steps on the two equations in (w, t) polish the hit.
// All in double, also for float, with the origin first moved along the ray next to the shape.
//
// Inside (as POV-Ray's): a point whose horizontal half-line away from the axis crosses the turned
// profile an odd number of times. The profile need not be closed; the normal points to the side
// that test calls outside.

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <optional>
#include <stdexcept>
#include <vector>

#include "outline.hpp"
#include "polynomial_roots.hpp"
#include "primitive.hpp"

namespace photon {

template <Scalar S> class Lathe {
public:
    using scalar_type = S;

    /// The profile's curves: control points as (radius, height). Throws std::invalid_argument
    /// when it is empty, a degree is not 1 to 3, or a point is not finite.
    explicit Lathe(const std::vector<OutlineSegment>& profile) {
        if (profile.empty()) throw std::invalid_argument("lathe: the profile has no curves");
        double radius = 0.0, y_lo = std::numeric_limits<double>::infinity(), y_hi = -y_lo;
        for (const OutlineSegment& g : profile) {
            if (g.degree < 1 || g.degree > 3) throw std::invalid_argument("lathe: a curve's degree must be 1, 2 or 3");
            Curve c;
            c.degree = g.degree;
            const auto& p = g.control;
            for (int i = 0; i <= g.degree; ++i)
                if (!std::isfinite(p[std::size_t(i)].x) || !std::isfinite(p[std::size_t(i)].y))
                    throw std::invalid_argument("lathe: points must be finite");
            if (g.degree == 1) c.x = {p[0].x, p[1].x - p[0].x, 0, 0}, c.y = {p[0].y, p[1].y - p[0].y, 0, 0};
            for (int axis = 0; axis < 2; ++axis) {
                std::array<double, 4>& k = axis == 0 ? c.x : c.y;
                const auto v = [&](int i) { return p[std::size_t(i)][axis]; };
                if (g.degree == 2) k = {v(0), 2.0 * (v(1) - v(0)), v(0) - 2.0 * v(1) + v(2), 0.0};
                if (g.degree == 3)
                    k = {v(0), 3.0 * (v(1) - v(0)), 3.0 * (v(0) - 2.0 * v(1) + v(2)), v(3) - v(0) + 3.0 * (v(1) - v(2))};
            }
            // The curve's own extent (its ends and turns, not its control points: as POV-Ray's
            // bounding cylinders, and tighter).
            const auto turns = detail::roots_in<2>({c.y[1], 2.0 * c.y[2], 3.0 * c.y[3]}, 0.0, 1.0);
            const auto x_turns = detail::roots_in<2>({c.x[1], 2.0 * c.x[2], 3.0 * c.x[3]}, 0.0, 1.0);
            const auto extend = [&](double w) {
                c.radius = std::max(c.radius, std::abs(at(c.x, w)));
                c.y_lo = std::min(c.y_lo, at(c.y, w)), c.y_hi = std::max(c.y_hi, at(c.y, w));
            };
            extend(0.0), extend(1.0);
            for (std::size_t i = 0; i < turns.count; ++i) extend(turns.value[i]);
            for (std::size_t i = 0; i < x_turns.count; ++i) extend(x_turns.value[i]);
            // Cut at the turns of Y(w), so that a horizontal line meets each piece at most once.
            double w0 = 0.0;
            for (std::size_t i = 0; i <= turns.count; ++i) {
                const double w1 = i < turns.count ? turns.value[i] : 1.0;
                if (w1 > w0) pieces_.push_back({curves_.size(), w0, w1});
                w0 = w1;
            }
            radius = std::max(radius, c.radius), y_lo = std::min(y_lo, c.y_lo), y_hi = std::max(y_hi, c.y_hi);
            curves_.push_back(c);
        }
        radius_ = radius, y_lo_ = y_lo, y_hi_ = y_hi;
        const double pad = 4.0 * std::numeric_limits<S>::epsilon() * std::max({radius, std::abs(y_lo), std::abs(y_hi)});
        bounds_ = {Vec3<S>(S(-radius - pad), S(y_lo - pad), S(-radius - pad)),
                   Vec3<S>(S(radius + pad), S(y_hi + pad), S(radius + pad))};
    }

    [[nodiscard]] BBox<S> bounds() const noexcept { return bounds_; }
    [[nodiscard]] std::size_t curve_count() const noexcept { return curves_.size(); }

    /// Solid: an odd count of the profile's crossings beyond the point on its horizontal half-line.
    [[nodiscard]] bool contains(const Vec3<S>& p) const noexcept {
        const glm::dvec3 q(p);
        return inside_profile(std::sqrt(q.x * q.x + q.z * q.z), q.y);
    }

    [[nodiscard]] std::optional<Hit<S>> intersect(const Ray<S>& ray) const noexcept {
        glm::dvec3 d(ray.direction);
        const double speed = glm::length(d);
        if (!(speed > 0.0)) return std::nullopt;
        d /= speed;
        // Move the origin to the ray's closest approach to the box's centre (a far origin would
        // cancel the digits of F's coefficients); local t' = t * speed - shift.
        const glm::dvec3 centre(0.0, 0.5 * (y_lo_ + y_hi_), 0.0);
        const double shift = glm::dot(centre - glm::dvec3(ray.origin), d);
        const glm::dvec3 o = glm::dvec3(ray.origin) + shift * d;
        const double t_far = std::isfinite(double(ray.t_max)) ? double(ray.t_max) * speed - shift
                                                              : std::numeric_limits<double>::infinity();
        const double t_near = -shift;
        const double r = d.x * d.x + d.z * d.z, m = d.x * o.x + d.z * o.z, rho2 = o.x * o.x + o.z * o.z;
        // Closest approach to the axis, and the heights the ray has within each curve's radius.
        const double axis_gap2 = r > 0.0 ? std::max(0.0, rho2 - m * m / r) : rho2;
        double best = t_far;
        glm::dvec2 best_normal(0.0);
        double best_w = 0.0;
        std::size_t best_curve = 0;
        bool found = false;
        for (std::size_t index = 0; index < curves_.size(); ++index) {
            const Curve& c = curves_[index];
            if (axis_gap2 > c.radius * c.radius * (1.0 + 1e-12)) continue;
            if (r > 0.0) {
                const double half = std::sqrt(std::max(0.0, (c.radius * c.radius - axis_gap2) / r)) * (1.0 + 1e-9);
                const double centre_t = -m / r;
                const double ya = o.y + (centre_t - half) * d.y, yb = o.y + (centre_t + half) * d.y;
                const double pad = 1e-9 * (c.y_hi - c.y_lo + c.radius);
                if (std::max(ya, yb) < c.y_lo - pad || std::min(ya, yb) > c.y_hi + pad) continue;
            }
            const auto take = [&](double w, double t) {
                if (!(w >= 0.0 && w <= 1.0) || !(t > t_near) || !(t < best)) return;
                const S world = S((t + shift) / speed);
                if (!(world > S(0)) || !(world < ray.t_max)) return;
                best = t, best_w = w, best_curve = index, found = true;
            };
            if (std::abs(d.y) >= 1e-5) sloping(c, o, d, r, m, rho2, take);
            else level(c, o, d, r, m, rho2, take);
        }
        if (!found) return std::nullopt;
        const S t = S((best + shift) / speed);
        const glm::dvec3 p = o + best * d;
        best_normal = outward(curves_[best_curve], best_w, std::sqrt(p.x * p.x + p.z * p.z), p.y);
        const double rho = std::sqrt(p.x * p.x + p.z * p.z);
        const glm::dvec3 n = rho > 0.0 ? glm::dvec3(best_normal.x * p.x / rho, best_normal.y, best_normal.x * p.z / rho)
                                       : glm::dvec3(0.0, best_normal.y < 0.0 ? -1.0 : 1.0, 0.0);
        return Hit<S>{t, ray.at(t), Vec3<S>(glm::normalize(n))};
    }

private:
    struct Curve {
        std::array<double, 4> x{}, y{};  ///< power basis: X(w) = x[0] + x[1] w + x[2] w^2 + x[3] w^3
        int degree = 1;
        double radius = 0.0, y_lo = std::numeric_limits<double>::infinity(), y_hi = -std::numeric_limits<double>::infinity();
    };
    struct Piece {
        std::size_t curve;
        double w0, w1;  ///< Y(w) is monotone between them
    };

    [[nodiscard]] static double at(const std::array<double, 4>& k, double w) noexcept {
        return k[0] + w * (k[1] + w * (k[2] + w * k[3]));
    }
    [[nodiscard]] static double slope(const std::array<double, 4>& k, double w) noexcept {
        return k[1] + w * (2.0 * k[2] + w * 3.0 * k[3]);
    }
    /// Product of two polynomials of degree up to 3.
    [[nodiscard]] static std::array<double, 7> times(const std::array<double, 4>& a, const std::array<double, 4>& b) noexcept {
        std::array<double, 7> out{};
        for (std::size_t i = 0; i < 4; ++i)
            for (std::size_t j = 0; j < 4; ++j) out[i + j] += a[i] * b[j];
        return out;
    }
    /// The roots in [0, 1] of a polynomial whose true degree is at most `degree`.
    template <std::size_t N> [[nodiscard]] static detail::Roots<6> roots01(const std::array<double, N>& c, int degree) {
        detail::Roots<6> out;
        const auto copy = [&](const auto& found) {
            for (std::size_t i = 0; i < found.count; ++i) out.push(found.value[i]);
        };
        const auto take = [&]<std::size_t D>() {
            std::array<double, D + 1> k{};
            for (std::size_t i = 0; i <= D && i < N; ++i) k[i] = c[i];
            copy(detail::roots_in<D>(k, 0.0, 1.0));
        };
        switch (degree) {
            case 1: take.template operator()<1>(); break;
            case 2: take.template operator()<2>(); break;
            case 3: take.template operator()<3>(); break;
            case 4: take.template operator()<4>(); break;
            default: take.template operator()<6>(); break;
        }
        return out;
    }

    /// A ray with a height component: the roots of F in w, t from the height.
    template <class Take>
    void sloping(const Curve& c, const glm::dvec3& o, const glm::dvec3& d, double r, double m, double rho2, Take& take) const {
        std::array<double, 4> dy = c.y;
        dy[0] -= o.y;
        const auto yy = times(dy, dy), xx = times(c.x, c.x);
        std::array<double, 7> f{};
        for (std::size_t i = 0; i < 7; ++i) f[i] = r * yy[i] - d.y * d.y * xx[i];
        for (std::size_t i = 0; i < 4; ++i) f[i] += 2.0 * m * d.y * dy[i];
        f[0] += d.y * d.y * rho2;
        const auto roots = roots01(f, 2 * c.degree);
        for (std::size_t i = 0; i < roots.count; ++i) {
            double w = roots.value[i], t = (at(dy, w)) / d.y;
            polish(c, o, d, r, m, w, t);
            take(w, t);
        }
    }

    /// A ray (nearly) level: the heights Y(w) = o.y, then the ring's quadratic in t.
    template <class Take>
    void level(const Curve& c, const glm::dvec3& o, const glm::dvec3& d, double r, double m, double rho2, Take& take) const {
        if (!(r > 0.0)) return;
        std::array<double, 4> dy = c.y;
        dy[0] -= o.y;
        const auto roots = roots01(dy, c.degree);
        for (std::size_t i = 0; i < roots.count; ++i) {
            const double w0 = roots.value[i], x = at(c.x, w0);
            const double disc = m * m - r * (rho2 - x * x);
            if (disc < 0.0) continue;
            const double root = std::sqrt(disc);
            for (const double t0 : {(-m - root) / r, (-m + root) / r}) {
                double w = w0, t = t0;
                polish(c, o, d, r, m, w, t);
                take(w, t);
            }
        }
    }

    /// Newton steps on Y(w) - o.y - t d.y = 0 and |o_xz + t d_xz|^2 - X(w)^2 = 0, kept only
    /// while they shrink the residual.
    static void polish(const Curve& c, const glm::dvec3& o, const glm::dvec3& d, double r, double m, double& w,
                       double& t) noexcept {
        const auto residual = [&](double w1, double t1, double& g1, double& g2) {
            const double x = at(c.x, w1), px = o.x + t1 * d.x, pz = o.z + t1 * d.z;
            g1 = at(c.y, w1) - o.y - t1 * d.y;
            g2 = px * px + pz * pz - x * x;
            return std::abs(g1) + std::abs(g2);
        };
        double g1, g2;
        double size = residual(w, t, g1, g2);
        for (int step = 0; step < 4 && size > 0.0; ++step) {
            const double a = slope(c.y, w), b = -d.y, cc = -2.0 * at(c.x, w) * slope(c.x, w), dd = 2.0 * (m + t * r);
            const double det = a * dd - b * cc;
            if (!(std::abs(det) > 0.0)) return;
            const double w1 = w - (g1 * dd - b * g2) / det, t1 = t - (a * g2 - cc * g1) / det;
            double h1, h2;
            const double next = residual(w1, t1, h1, h2);
            if (!(next < size)) return;
            w = w1, t = t1, g1 = h1, g2 = h2, size = next;
        }
    }

    /// The profile's crossings beyond (rho, y) on the horizontal half-line, by parity; each
    /// monotone piece counts when y is in [its lower end, its upper end), so a joint counts once.
    [[nodiscard]] bool inside_profile(double rho, double y) const noexcept {
        if (!(y >= y_lo_ && y <= y_hi_) || !(rho <= radius_)) return false;
        bool inside = false;
        for (const Piece& piece : pieces_) {
            const Curve& c = curves_[piece.curve];
            double wa = piece.w0, wb = piece.w1, ya = at(c.y, wa), yb = at(c.y, wb);
            if (ya == yb || !(y >= std::min(ya, yb) && y < std::max(ya, yb))) continue;
            // Bisection on the monotone piece: robust, and only a few dozen steps.
            for (int i = 0; i < 60 && wb - wa > 1e-15; ++i) {
                const double wm = 0.5 * (wa + wb), ym = at(c.y, wm);
                if ((ym < y) == (ya < y)) wa = wm, ya = ym;
                else wb = wm;
            }
            if (std::abs(at(c.x, 0.5 * (wa + wb))) > rho) inside = !inside;
        }
        return inside;
    }

    /// The profile's normal at curve parameter w, as (radial, height), turned to the outside.
    [[nodiscard]] glm::dvec2 outward(const Curve& c, double w, double rho, double y) const noexcept {
        const double sign = at(c.x, w) < 0.0 ? -1.0 : 1.0;
        glm::dvec2 n(slope(c.y, w), -sign * slope(c.x, w));
        const double length = glm::length(n);
        if (!(length > 0.0)) return {0.0, 1.0};
        n /= length;
        const double step = 1e-7 * std::max({radius_, y_hi_ - y_lo_, std::abs(y)});
        if (inside_profile(std::abs(rho + step * n.x), y + step * n.y)) n = -n;
        return n;
    }

    std::vector<Curve> curves_;
    std::vector<Piece> pieces_;
    double radius_ = 0.0, y_lo_ = 0.0, y_hi_ = 0.0;
    BBox<S> bounds_;
};

}  // namespace photon
