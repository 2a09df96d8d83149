// SPDX-License-Identifier: MIT
#pragma once
// POV-Ray's superellipsoid { <e, n> }: the points with
//   N(p) = ( (|x|^(2/e) + |y|^(2/e))^(e/n) + |z|^(2/n) )^(n/2) <= 1,
// inside the cube [-1, 1]^3 (placed elsewhere with Transformed). N is homogeneous of degree 1 and
// does not decrease when any |coordinate| grows; with e, n <= 2 it is a norm (convex), above 2 the
// shape is a star with sharp ridges along the axes.
//
// POV-Ray 3.7 cuts the ray at nine symmetry planes and looks for sign changes of N - 1 at those
// cuts (with a guess for an unseen pair of roots between them), so a thin ridge between two
// cuts can be missed. Here the roots are isolated by interval bisection along the ray inside the
// box: since N grows with each |coordinate|, N at the smallest |x|, |y|, |z| a piece of the ray
// reaches is a lower bound on N over the piece and N at the largest an upper bound, both exact
// for that box of coordinates. A piece whose bounds lie both above 1 or both below holds no root
// and is dropped; the others are halved, nearest first. A piece whose ends differ in sign is
// refined by the Illinois variant of regula falsi: at once when N is convex (then a piece with a
// sign change holds exactly one root), else once it is shorter than 1e-7 of the chord (an enter
// and an exit closer together than that before a crossing would be missed). A piece without a
// sign change whose bounds still straddle 1 when it is 1e-10 of the chord long is a tangent
// ray: a miss. All in double, also for float.

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <optional>
#include <stdexcept>

#include "primitive.hpp"

namespace photon {

template <Scalar S> class Superellipsoid {
public:
    using scalar_type = S;

    /// POV-Ray's <e, n>: e shapes the cross-sections in xy, n the profile along z (1 and 1 is the
    /// unit sphere, small values a rounded box). Throws std::invalid_argument unless both are
    /// positive and finite.
    Superellipsoid(S e, S n) : e_(double(e)), n_(double(n)), xy_power_(2.0 / e_), z_power_(2.0 / n_) {
        if (!(e_ > 0.0) || !(n_ > 0.0) || !std::isfinite(e_) || !std::isfinite(n_))
            throw std::invalid_argument("superellipsoid: e and n must be positive and finite");
        convex_ = e_ <= 2.0 && n_ <= 2.0;
    }

    [[nodiscard]] S east_west() const noexcept { return S(e_); }
    [[nodiscard]] S north_south() const noexcept { return S(n_); }
    [[nodiscard]] BBox<S> bounds() const noexcept {
        const S pad = S(1) + S(4) * std::numeric_limits<S>::epsilon();
        return {Vec3<S>(-pad), Vec3<S>(pad)};
    }

    /// Solid: N(p) <= 1.
    [[nodiscard]] bool contains(const Vec3<S>& p) const noexcept { return size(glm::dvec3(glm::abs(p))) <= 1.0; }

    [[nodiscard]] std::optional<Hit<S>> intersect(const Ray<S>& ray) const noexcept {
        const glm::dvec3 o(ray.origin), d(ray.direction);
        double t0 = 0.0, t1 = std::isfinite(double(ray.t_max)) ? double(ray.t_max) : std::numeric_limits<double>::max();
        constexpr double reach = 1.0 + 1e-9;  // the box, a little wider, so that its faces are outside
        for (int k = 0; k < 3; ++k) {
            if (d[k] == 0.0) {
                if (std::abs(o[k]) > reach) return std::nullopt;
                continue;
            }
            double a = (-reach - o[k]) / d[k], b = (reach - o[k]) / d[k];
            if (a > b) std::swap(a, b);
            t0 = std::max(t0, a), t1 = std::min(t1, b);
        }
        if (!(t0 < t1)) return std::nullopt;
        const auto t = first_root(o, d, t0, t1);
        if (!t) return std::nullopt;
        const S ts = S(*t);
        if (!(ts > S(0)) || !(ts < ray.t_max)) return std::nullopt;
        return Hit<S>{ts, ray.at(ts), Vec3<S>(normal_at(o + *t * d))};
    }

private:
    /// x^p, by multiplication for the small whole powers scenes use most (<1, 1> is the sphere,
    /// p = 2): std::pow costs several times a product.
    [[nodiscard]] static double power(double x, double p) noexcept {
        if (p == 2.0) return x * x;
        if (p == 4.0) return (x * x) * (x * x);
        if (p == 1.0) return x;
        return std::pow(x, p);
    }
    /// (u^p + v^p)^(1/p) for u, v >= 0, scaled by the larger so that no power overflows.
    [[nodiscard]] static double combine(double u, double v, double p) noexcept {
        const double big = std::max(u, v), small = std::min(u, v);
        if (big == 0.0) return 0.0;
        const double sum = 1.0 + power(small / big, p);
        return big * (p == 2.0 ? std::sqrt(sum) : p == 1.0 ? sum : std::pow(sum, 1.0 / p));
    }

    /// N at a point given by its absolute coordinates.
    [[nodiscard]] double size(const glm::dvec3& a) const noexcept {
        return combine(combine(a.x, a.y, xy_power_), a.z, z_power_);
    }

    /// N - 1 along the ray.
    [[nodiscard]] double excess(const glm::dvec3& o, const glm::dvec3& d, double t) const noexcept {
        return size(glm::abs(o + t * d)) - 1.0;
    }

    /// Whether N - 1 may vanish on the piece [ta, tb] of the ray (the bounds described above).
    [[nodiscard]] bool may_cross(const glm::dvec3& o, const glm::dvec3& d, double ta, double tb) const noexcept {
        const glm::dvec3 a = o + ta * d, b = o + tb * d;
        glm::dvec3 lo, hi;
        for (int k = 0; k < 3; ++k) {
            hi[k] = std::max(std::abs(a[k]), std::abs(b[k]));
            lo[k] = (a[k] < 0.0) != (b[k] < 0.0) ? 0.0 : std::min(std::abs(a[k]), std::abs(b[k]));
        }
        return size(lo) <= 1.0 && size(hi) >= 1.0;
    }

    struct Piece {
        double ta, tb, fa, fb;
    };

    /// The nearest t in [t0, t1] where N - 1 changes sign.
    [[nodiscard]] std::optional<double> first_root(const glm::dvec3& o, const glm::dvec3& d, double t0,
                                                   double t1) const noexcept {
        const double chord = t1 - t0;
        const double resolve = convex_ ? std::numeric_limits<double>::infinity() : 1e-7 * chord;
        const double finest = 1e-10 * chord;
        std::array<Piece, 96> stack;
        std::size_t top = 0;
        stack[top++] = {t0, t1, excess(o, d, t0), excess(o, d, t1)};
        while (top > 0) {
            const Piece piece = stack[--top];
            if (piece.fa == 0.0 && piece.ta > t0) return piece.ta;
            if (!may_cross(o, d, piece.ta, piece.tb)) continue;
            const double width = piece.tb - piece.ta;
            const bool change = (piece.fa < 0.0) != (piece.fb < 0.0) && piece.fb != 0.0;
            if (change && width <= resolve) return refine(o, d, piece);
            if (width <= finest || top + 2 > stack.size()) {
                if (change) return refine(o, d, piece);
                continue;  // tangent: a miss
            }
            const double tm = 0.5 * (piece.ta + piece.tb), fm = excess(o, d, tm);
            stack[top++] = {tm, piece.tb, fm, piece.fb};  // far half first: the near one is popped next
            stack[top++] = {piece.ta, tm, piece.fa, fm};
        }
        return std::nullopt;
    }

    /// The root in a piece whose ends differ in sign, by the Illinois method (regula falsi that
    /// halves the weight of an end kept twice, so both ends converge).
    [[nodiscard]] double refine(const glm::dvec3& o, const glm::dvec3& d, Piece p) const noexcept {
        int kept = 0;  // +1: the low end was kept last time, -1: the high end
        for (int iteration = 0; iteration < 100; ++iteration) {
            double t = p.tb - p.fb * (p.tb - p.ta) / (p.fb - p.fa);
            if (!(t > p.ta && t < p.tb)) t = 0.5 * (p.ta + p.tb);
            if (p.tb - p.ta <= 4.0 * std::numeric_limits<double>::epsilon() * std::max(std::abs(p.ta), std::abs(p.tb)))
                return t;
            const double f = excess(o, d, t);
            if (f == 0.0) return t;
            if ((f < 0.0) == (p.fa < 0.0)) {
                p.ta = t, p.fa = f;
                if (kept == -1) p.fb *= 0.5;
                kept = -1;
            } else {
                p.tb = t, p.fb = f;
                if (kept == 1) p.fa *= 0.5;
                kept = 1;
            }
        }
        return 0.5 * (p.ta + p.tb);
    }

    /// The gradient of N, normalised. On a ridge (a coordinate 0 where its power is below 1) the
    /// gradient is unbounded; the infinite components then decide the direction alone.
    [[nodiscard]] glm::dvec3 normal_at(const glm::dvec3& p) const noexcept {
        const glm::dvec3 a = glm::abs(p);
        const double r = combine(a.x, a.y, xy_power_), n = combine(r, a.z, z_power_);
        glm::dvec3 g(0.0);
        if (n > 0.0) {
            const double outer = std::pow(r / n, z_power_ - 1.0);
            if (r > 0.0) {
                g.x = outer * std::pow(a.x / r, xy_power_ - 1.0);
                g.y = outer * std::pow(a.y / r, xy_power_ - 1.0);
            }
            g.z = std::pow(a.z / n, z_power_ - 1.0);
        }
        if (std::isinf(g.x) || std::isinf(g.y) || std::isinf(g.z))
            g = glm::dvec3(std::isinf(g.x) ? 1.0 : 0.0, std::isinf(g.y) ? 1.0 : 0.0, std::isinf(g.z) ? 1.0 : 0.0);
        if (!(g.x + g.y + g.z > 0.0)) g = a;  // not expected on the surface; the radial direction
        for (int k = 0; k < 3; ++k)
            if (p[k] < 0.0) g[k] = -g[k];
        return glm::normalize(g);
    }

    double e_, n_, xy_power_, z_power_;
    bool convex_ = true;
};

}  // namespace photon
