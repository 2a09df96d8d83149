// SPDX-License-Identifier: MIT
#pragma once
// POV-Ray's quadric: the surface A x^2 + B y^2 + C z^2 + D xy + E xz + F yz + G x + H y + I z + J = 0
// and, as a solid, the points where that polynomial is <= 0 (POV-Ray's Inside_Quadric). Most
// quadrics are unbounded (the infinite cylinders, cones, paraboloids and hyperboloids of
// shapes.inc); they are bounded in practice by a CSG intersection, which meets their box.

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <stdexcept>
#include <utility>

#include <glm/mat3x3.hpp>
#include <glm/matrix.hpp>

#include "../math/symmetric_eigen.hpp"
#include "../math/transform.hpp"
#include "primitive.hpp"
#include "quadric_support.hpp"

namespace photon {

/// The ten numbers of POV-Ray's `quadric { <A, B, C>, <D, E, F>, <G, H, I>, J }`.
template <Scalar S> struct QuadricCoefficients {
    Vec3<S> squares{S(0)};  ///< A, B, C: of x^2, y^2, z^2
    Vec3<S> mixed{S(0)};    ///< D, E, F: of xy, xz, yz
    Vec3<S> linear{S(0)};   ///< G, H, I: of x, y, z
    S constant = S(0);      ///< J
};

/// A quadric surface, solid where its polynomial is <= 0; the normal is the polynomial's
/// gradient (out of the solid), as POV-Ray's.
///
/// Stored in double for either scalar, as q(p - origin) with q(u) = u'Mu + 2b'u + j, where
/// `origin` is the quadric's centre when it has one: a shape placed far from the world's origin
/// then keeps its own scale in its numbers (the expanded polynomial of a unit sphere at 1000 has
/// J = 3e6 - 1, whose rounding moves the surface), and transforming it (transformed()) only moves
/// the origin and maps M and b, never expanding.
template <Scalar S> class Quadric {
public:
    using scalar_type = S;

    /// Throws std::invalid_argument unless every coefficient is finite and some coefficient of x,
    /// y or z (quadratic or linear) is not zero (0 = J is no surface).
    explicit Quadric(const QuadricCoefficients<S>& c) {
        const Vec3<double> sq(c.squares), mx(c.mixed), ln(c.linear);
        if (!is_finite(sq) || !is_finite(mx) || !is_finite(ln) || !std::isfinite(double(c.constant)))
            throw std::invalid_argument("quadric: coefficients must be finite");
        m_ = glm::dmat3(sq.x, 0.5 * mx.x, 0.5 * mx.y,  // symmetric: column and row order agree
                        0.5 * mx.x, sq.y, 0.5 * mx.z,  //
                        0.5 * mx.y, 0.5 * mx.z, sq.z);
        b_ = 0.5 * ln;
        j_ = double(c.constant);
        if (max_abs(m_) == 0.0 && b_ == glm::dvec3(0.0))
            throw std::invalid_argument("quadric: the coefficients of x, y and z are all zero: no surface");
        recenter();
        update_bounds();
    }

    /// The same surface and solid placed by `to_world` (POV-Ray transforms the matrix form the
    /// same way), in double also for float: a map given in double (a scene file's) keeps its
    /// precision, so a rotation by 90 degrees leaves an infinite cylinder exactly along an axis.
    /// Throws std::invalid_argument when the map is singular or not finite.
    template <Scalar T> [[nodiscard]] Quadric transformed(const Affine<T>& to_world) const {
        const glm::dmat3 linear(to_world.linear);
        const double det = glm::determinant(linear);
        if (!(std::abs(det) > 0.0) || !std::isfinite(det) || !is_finite(Vec3<double>(to_world.translation)))
            throw std::invalid_argument("transform: matrix must be invertible and finite");
        // Around the new origin (the old one's image) a point u is the old origin plus L u.
        const glm::dmat3 l = glm::inverse(linear);
        Quadric q = *this;
        q.origin_ = linear * origin_ + glm::dvec3(to_world.translation);
        q.m_ = glm::transpose(l) * m_ * l;
        q.m_ = 0.5 * (q.m_ + glm::transpose(q.m_));  // exactly symmetric
        q.b_ = glm::transpose(l) * b_;
        q.update_bounds();
        return q;
    }

    /// POV-Ray's coefficients of the polynomial about the world's origin (expanded: for a shape
    /// far from the origin, rounded as that form must be).
    [[nodiscard]] QuadricCoefficients<S> coefficients() const noexcept {
        const glm::dvec3 lin = b_ - m_ * origin_;  // half the linear terms
        QuadricCoefficients<S> c;
        c.squares = Vec3<S>(m_[0][0], m_[1][1], m_[2][2]);
        c.mixed = Vec3<S>(2.0 * m_[1][0], 2.0 * m_[2][0], 2.0 * m_[2][1]);
        c.linear = Vec3<S>(2.0 * lin);
        c.constant = S(glm::dot(origin_, m_ * origin_) - 2.0 * glm::dot(b_, origin_) + j_);
        return c;
    }

    /// The polynomial at p (negative inside).
    [[nodiscard]] double value(const Vec3<S>& p) const noexcept { return local_value(glm::dvec3(p) - origin_); }

    /// Solid: where the polynomial is <= 0, as POV-Ray's inside test.
    [[nodiscard]] bool contains(const Vec3<S>& p) const noexcept { return value(p) <= 0.0; }

    /// The solid's box, exact up to rounding: finite along the axes its solid does not extend
    /// along forever (an ellipsoid in all three, Cylinder_Y in x and z), infinite along the
    /// others, empty when the polynomial is positive everywhere (nothing to render).
    [[nodiscard]] BBox<S> bounds() const noexcept { return bounds_; }

    /// The two roots of q along the ray, solved in double: the origin first moves to where the
    /// ray enters the bounding sphere of a bounded quadric (a far origin would cancel the digits
    /// of the constant term); the discriminant is taken at the parabola's vertex (Hearn and
    /// Baker's form for the sphere, generalised) when that is the smaller rounding error, so
    /// grazing rays stay exact; the small root comes from c / q (Press et al.); and one guarded
    /// Newton step on the polynomial at the root corrects what the far origin's terms lost.
    [[nodiscard]] std::optional<Hit<S>> intersect(const Ray<S>& ray) const noexcept {
        const glm::dvec3 d(ray.direction);
        glm::dvec3 o = glm::dvec3(ray.origin) - origin_;
        double shift = 0.0;
        if (bounded_) {
            const auto span = detail::sphere_span(Ray<double>{o, d}, sphere_center_, sphere_radius_);
            if (!span || !(span->second > 0.0) || !(span->first < double(ray.t_max))) return std::nullopt;
            shift = detail::origin_shift(*span);
            o += shift * d;
        }
        const glm::dvec3 md = m_ * d, half_gradient = m_ * o + b_;
        const double a = glm::dot(d, md), beta = glm::dot(d, half_gradient);
        const double c = glm::dot(o, half_gradient) + glm::dot(b_, o) + j_;
        double discriminant = beta * beta - a * c;
        if (a != 0.0) {
            const double vertex = -beta / a;
            const glm::dvec3 pv = o + vertex * d;
            if (std::isfinite(vertex) && std::abs(a) * magnitude(pv) < beta * beta + std::abs(a * c))
                discriminant = -a * local_value(pv);
        }
        if (!(discriminant >= 0.0)) return std::nullopt;
        const double q = -(beta + std::copysign(std::sqrt(discriminant), beta));
        double roots[2];
        if (q == 0.0) {
            if (a == 0.0) return std::nullopt;  // the polynomial is constant along the ray
            roots[0] = roots[1] = 0.0;          // touching at the origin
        } else {
            roots[0] = c / q;
            roots[1] = q / a;  // infinite when a = 0 (one root: the ray is parallel to an asymptote)
            if (roots[0] > roots[1]) std::swap(roots[0], roots[1]);
        }
        const double gap = roots[1] - roots[0];
        for (double local : roots) {
            if (!std::isfinite(local)) continue;
            const glm::dvec3 p = o + local * d;
            const double slope = 2.0 * glm::dot(d, m_ * p + b_);
            if (slope != 0.0) {
                const double step = local_value(p) / slope;
                if (std::abs(step) < 0.25 * gap || !std::isfinite(gap)) local -= step;
            }
            const S t = S(shift + local);
            if (!(t > S(0)) || !(t < ray.t_max)) continue;
            const glm::dvec3 hit_local = o + local * d;
            glm::dvec3 n = m_ * hit_local + b_;
            const double len = glm::length(n);
            n = len > 0.0 && std::isfinite(len) ? n / len : -d / glm::length(d);  // a cone's apex: facing the ray
            return Hit<S>{t, ray.at(t), Vec3<S>(n)};
        }
        return std::nullopt;
    }

private:
    [[nodiscard]] static double max_abs(const glm::dmat3& m) noexcept {
        double v = 0.0;
        for (int i = 0; i < 3; ++i)
            for (int k = 0; k < 3; ++k) v = std::max(v, std::abs(m[i][k]));
        return v;
    }
    [[nodiscard]] double local_value(const glm::dvec3& u) const noexcept {
        return glm::dot(u, m_ * u + 2.0 * b_) + j_;
    }
    /// The size of the terms of local_value(u): its rounding error is about eps times this.
    [[nodiscard]] double magnitude(const glm::dvec3& u) const noexcept {
        const double r = glm::length(u);
        return 3.0 * m_scale_ * r * r + 2.0 * b_length_ * r + std::abs(j_);
    }

    /// Moves the origin to the centre, where M has one: the point where the gradient's part in
    /// M's range vanishes (the axis of a cylinder, the apex of a cone).
    void recenter() {
        const SymmetricEigen3 e = symmetric_eigen(m_);
        const double big = std::max({std::abs(e.values.x), std::abs(e.values.y), std::abs(e.values.z)});
        glm::dvec3 center(0.0);
        for (int k = 0; k < 3; ++k)
            if (std::abs(e.values[k]) > 1e-12 * big) center -= (glm::dot(e.vectors[k], b_) / e.values[k]) * e.vectors[k];
        j_ = local_value(center);
        b_ += m_ * center;
        origin_ += center;
    }

    /// The solid {u'Mu + 2b'u + j <= 0}: with M's eigen-decomposition, a negative eigenvalue makes
    /// it unbounded in every direction (it holds a cone around that eigenvector), as does a zero
    /// eigenvalue whose eigenvector b is not orthogonal to (a paraboloid). Otherwise it is
    /// {(u - c)'M(u - c) <= k}: empty for k < 0, and reaching sqrt(k * e_i'M^+e_i) along axis i
    /// unless a zero eigenvector (an axis it extends along forever) has a component along i.
    void update_bounds() noexcept {
        m_scale_ = max_abs(m_);
        b_length_ = glm::length(b_);
        bounded_ = false;
        bounds_ = BBox<S>::infinite();
        const SymmetricEigen3 e = symmetric_eigen(m_);
        const double big = std::max({std::abs(e.values.x), std::abs(e.values.y), std::abs(e.values.z)});
        if (!(big > 0.0)) return;  // a half-space
        glm::dvec3 center(0.0), pseudo_inverse_diagonal(0.0);
        bool infinite_axis[3] = {false, false, false};
        for (int k = 0; k < 3; ++k) {
            const double lambda = e.values[k];
            const glm::dvec3 v = e.vectors[k];
            if (lambda < -1e-12 * big) return;
            if (lambda <= 1e-12 * big) {
                // b along the eigenvector makes a paraboloid; rounding leaves traces of b there after
                // a transformation, far below b's scale sqrt(lambda j).
                if (std::abs(glm::dot(v, b_)) > 1e-9 * std::sqrt(big * std::abs(j_))) return;
                for (int i = 0; i < 3; ++i) infinite_axis[i] = infinite_axis[i] || std::abs(v[i]) > 1e-12;
                continue;
            }
            center -= (glm::dot(v, b_) / lambda) * v;
            pseudo_inverse_diagonal += (v * v) / lambda;
        }
        const double k = -local_value(center);
        if (k < 0.0) {
            bounds_ = BBox<S>{};
            return;
        }
        glm::dvec3 lo(-std::numeric_limits<double>::infinity()), hi(std::numeric_limits<double>::infinity());
        for (int i = 0; i < 3; ++i) {
            if (infinite_axis[i]) continue;
            const double reach = std::sqrt(k * pseudo_inverse_diagonal[i]);
            const double c = origin_[i] + center[i];
            const double pad = 1e-9 * (std::abs(c) + reach) + std::numeric_limits<double>::min();
            lo[i] = c - reach - pad;
            hi[i] = c + reach + pad;
        }
        // Rounded outward to S, so that the box still holds the solid.
        for (int i = 0; i < 3; ++i) {
            bounds_.min[i] = rounded_down<S>(lo[i]);
            bounds_.max[i] = rounded_up<S>(hi[i]);
        }
        bounded_ = bounds_.is_finite();
        if (bounded_) {
            const glm::dvec3 half = 0.5 * (hi - lo);
            sphere_center_ = 0.5 * (hi + lo) - origin_;
            sphere_radius_ = glm::length(half);
        }
    }

    glm::dvec3 origin_{0.0};
    glm::dmat3 m_{0.0};
    glm::dvec3 b_{0.0};
    double j_ = 0.0;
    double m_scale_ = 0.0, b_length_ = 0.0;  ///< for the rounding error of the polynomial's value
    BBox<S> bounds_;
    bool bounded_ = false;
    glm::dvec3 sphere_center_{0.0};  ///< of the bounded solid's box, relative to origin_
    double sphere_radius_ = 0.0;
};

}  // namespace photon
