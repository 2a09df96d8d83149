// SPDX-License-Identifier: MIT
#pragma once
// POV-Ray's polynomial surfaces (`quartic`, `cubic`, `poly`, `polynomial`): p(x, y, z) = 0 for a
// polynomial of order 2 to 35, solid where p < 0 (POV-Ray's Inside_Poly), with the gradient as the
// outward normal. Along a ray p is a polynomial in t, expanded exactly (up to rounding) in double
// and solved by bracketing its real roots (polynomial_roots.hpp), not by POV-Ray's Sturm
// sequences: every root reported is a sign change of that polynomial.
//
// Most such surfaces are unbounded (or are not known to be bounded), so bounds() is infinite and
// the scene tests them outside its BVH. A scene may give POV-Ray's `bounded_by` sphere or box:
// then, as in POV-Ray (Ray_In_Bound), a ray that neither meets the bound nor starts in it meets no
// part of the surface, and one that does meets all of it, also outside the bound; bounds() is
// then the bound's box, which puts the surface in the BVH (exact where the surface lies inside
// its bound, POV-Ray's intent; where it does not, the scene file already warned).

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "polynomial_roots.hpp"
#include "primitive.hpp"
#include "quadric_support.hpp"

namespace photon {

/// The number of terms of a polynomial of `order` in x, y and z: (n + 1)(n + 2)(n + 3) / 6.
[[nodiscard]] constexpr std::size_t polynomial_term_count(int order) noexcept {
    const auto n = std::size_t(order);
    return (n + 1) * (n + 2) * (n + 3) / 6;
}

/// The index of x^i y^j z^k (i + j + k <= order) in POV-Ray's order (Poly::Set_Coeff): the
/// terms with a higher power of x come first, then those with a higher power of y, then of z.
[[nodiscard]] constexpr std::size_t polynomial_term_index(int order, int i, int j, int k) noexcept {
    std::size_t index = 0;
    for (int a = order; a > i; --a) index += std::size_t(order - a + 1) * std::size_t(order - a + 2) / 2;
    for (int b = order - i; b > j; --b) index += std::size_t(order - i - b + 1);
    return index + std::size_t(order - i - j - k);
}

/// One term c x^i y^j z^k.
struct PolynomialTerm {
    int i = 0, j = 0, k = 0;
    double c = 0.0;
};

/// The powers (i, j, k) of term `index` in POV-Ray's order for `order`: x's power descending,
/// then y's, then z's (a quartic's 35 terms run x^4, x^3 y, x^3 z, x^3, x^2 y^2, ..., z, 1).
[[nodiscard]] inline std::array<int, 3> polynomial_term_powers(int order, std::size_t index) noexcept {
    for (int i = order; i >= 0; --i)
        for (int j = order - i; j >= 0; --j)
            for (int k = order - i - j; k >= 0; --k)
                if (index-- == 0) return {i, j, k};
    return {0, 0, 0};
}

/// POV-Ray's bounded_by object for a polynomial, in the surface's own coordinates.
struct PolynomialGate {
    enum class Kind { sphere, box } kind = Kind::sphere;
    glm::dvec3 center{0.0};  ///< sphere
    double radius = 0.0;     ///< sphere
    glm::dvec3 min{0.0}, max{0.0};  ///< box
};

/// An implicit polynomial surface, solid where the polynomial is negative.
template <Scalar S> class PolynomialSurface {
public:
    using scalar_type = S;
    static constexpr int max_order = int(detail::max_runtime_degree);

    /// `coefficients` in POV-Ray's order (polynomial_term_powers), polynomial_term_count(order)
    /// of them. Throws std::invalid_argument unless 1 <= order <= 35, the count is right, every
    /// coefficient is finite and some term of x, y or z is not zero.
    PolynomialSurface(int order, std::vector<double> coefficients);

    /// The same surface, where a ray that neither meets `gate` nor starts in it meets nothing.
    /// Throws std::invalid_argument for a gate that is not finite or has no volume.
    [[nodiscard]] PolynomialSurface gated(const PolynomialGate& gate) const;

    [[nodiscard]] int order() const noexcept { return order_; }
    [[nodiscard]] const std::vector<double>& coefficients() const noexcept { return coefficients_; }
    [[nodiscard]] const std::optional<PolynomialGate>& gate() const noexcept { return gate_; }

    /// The polynomial at p (negative inside), in double.
    [[nodiscard]] double value(const glm::dvec3& p) const noexcept;
    /// Its gradient at p (out of the solid).
    [[nodiscard]] glm::dvec3 gradient(const glm::dvec3& p) const noexcept;

    /// Solid: where the polynomial is negative (POV-Ray's inside test; the gate plays no part).
    [[nodiscard]] bool contains(const Vec3<S>& p) const noexcept { return value(glm::dvec3(p)) < 0.0; }

    /// Infinite: the surface is not known to be bounded (and a gated one has hits outside its gate).
    /// Infinite, or the gate's box: a ray that misses the gate sees nothing of the surface, so
    /// the scene may leave the surface to its BVH (a ray that passes the gate sees all of it, and
    /// the BVH then tests it as any object whose box the ray crosses).
    [[nodiscard]] BBox<S> bounds() const noexcept {
        if (!gate_) return BBox<S>::infinite();
        if (gate_->kind == PolynomialGate::Kind::sphere)
            return {Vec3<S>(gate_->center - gate_->radius), Vec3<S>(gate_->center + gate_->radius)};
        return {Vec3<S>(gate_->min), Vec3<S>(gate_->max)};
    }

    /// The nearest root of p(o + t d) in (0, t_max), in double also for float: the polynomial in
    /// t is expanded about the ray's point nearest the gate's centre (or the origin), with a unit
    /// direction, so that a far origin does not cancel the digits of its coefficients; roots
    /// are searched up to Fujiwara's bound on their size.
    [[nodiscard]] std::optional<Hit<S>> intersect(const Ray<S>& ray) const noexcept;

private:
    /// Whether the line o + t d, t > 0, meets the gate or starts in it (POV-Ray's Ray_In_Bound).
    [[nodiscard]] bool passes_gate(const glm::dvec3& o, const glm::dvec3& d) const noexcept;
    /// intersect() for an order of at most N: arrays of N + 1 coefficients, so that a quartic's
    /// expansion and roots (most of POV-Ray's polynomials are quartics) work on a few doubles.
    template <std::size_t N> [[nodiscard]] std::optional<Hit<S>> intersect_up_to(const Ray<S>& ray) const noexcept;
    /// The roots of eqn's polynomial of `degree` <= N in [lo, hi], ascending.
    template <std::size_t N>
    [[nodiscard]] static auto roots_of(const std::array<double, N + 1>& eqn, std::size_t degree, double lo, double hi) noexcept;

    int order_;
    std::vector<double> coefficients_;
    std::vector<PolynomialTerm> terms_;  ///< the nonzero ones, in POV-Ray's order (grouped by i, then j)
    double top_magnitude_ = 0.0;         ///< sum of |c| over the terms of the highest degree present
    int top_degree_ = 0;
    std::optional<PolynomialGate> gate_;
};

template <Scalar S>
PolynomialSurface<S>::PolynomialSurface(int order, std::vector<double> coefficients)
    : order_(order), coefficients_(std::move(coefficients)) {
    if (order < 1 || order > max_order) throw std::invalid_argument("polynomial: order must be 1 to 35");
    if (coefficients_.size() != polynomial_term_count(order))
        throw std::invalid_argument("polynomial: an order " + std::to_string(order) + " polynomial has " +
                                    std::to_string(polynomial_term_count(order)) + " coefficients");
    std::size_t index = 0;
    for (int i = order; i >= 0; --i)
        for (int j = order - i; j >= 0; --j)
            for (int k = order - i - j; k >= 0; --k) {
                const double c = coefficients_[index++];
                if (!std::isfinite(c)) throw std::invalid_argument("polynomial: coefficients must be finite");
                if (c != 0.0) terms_.push_back({i, j, k, c});
            }
    if (terms_.empty() || (terms_.size() == 1 && terms_[0].i + terms_[0].j + terms_[0].k == 0))
        throw std::invalid_argument("polynomial: the coefficients of x, y and z are all zero: no surface");
    for (const PolynomialTerm& t : terms_) top_degree_ = std::max(top_degree_, t.i + t.j + t.k);
    for (const PolynomialTerm& t : terms_)
        if (t.i + t.j + t.k == top_degree_) top_magnitude_ += std::abs(t.c);
}

template <Scalar S> PolynomialSurface<S> PolynomialSurface<S>::gated(const PolynomialGate& gate) const {
    const bool ok = gate.kind == PolynomialGate::Kind::sphere
                        ? std::isfinite(glm::length(gate.center)) && gate.radius > 0.0 && std::isfinite(gate.radius)
                        : std::isfinite(glm::length(gate.min)) && std::isfinite(glm::length(gate.max)) &&
                              gate.min.x < gate.max.x && gate.min.y < gate.max.y && gate.min.z < gate.max.z;
    if (!ok) throw std::invalid_argument("polynomial: the bound must be a finite sphere or box with a volume");
    PolynomialSurface out = *this;
    out.gate_ = gate;
    return out;
}

template <Scalar S> double PolynomialSurface<S>::value(const glm::dvec3& p) const noexcept {
    std::array<double, detail::max_runtime_degree + 1> x{}, y{}, z{};
    x[0] = y[0] = z[0] = 1.0;
    for (int n = 1; n <= order_; ++n) x[n] = x[n - 1] * p.x, y[n] = y[n - 1] * p.y, z[n] = z[n - 1] * p.z;
    double v = 0.0;
    for (const PolynomialTerm& t : terms_) v += t.c * x[t.i] * y[t.j] * z[t.k];
    return v;
}

template <Scalar S> glm::dvec3 PolynomialSurface<S>::gradient(const glm::dvec3& p) const noexcept {
    std::array<double, detail::max_runtime_degree + 1> x{}, y{}, z{};
    x[0] = y[0] = z[0] = 1.0;
    for (int n = 1; n <= order_; ++n) x[n] = x[n - 1] * p.x, y[n] = y[n - 1] * p.y, z[n] = z[n - 1] * p.z;
    glm::dvec3 g(0.0);
    for (const PolynomialTerm& t : terms_) {
        if (t.i > 0) g.x += t.c * t.i * x[t.i - 1] * y[t.j] * z[t.k];
        if (t.j > 0) g.y += t.c * t.j * x[t.i] * y[t.j - 1] * z[t.k];
        if (t.k > 0) g.z += t.c * t.k * x[t.i] * y[t.j] * z[t.k - 1];
    }
    return g;
}

template <Scalar S> bool PolynomialSurface<S>::passes_gate(const glm::dvec3& o, const glm::dvec3& d) const noexcept {
    if (!gate_) return true;
    const PolynomialGate& g = *gate_;
    if (g.kind == PolynomialGate::Kind::sphere) {
        const auto span = detail::sphere_span(Ray<double>{o, d}, g.center, g.radius);
        return span && span->second > 0.0;
    }
    double enter = -std::numeric_limits<double>::infinity(), leave = std::numeric_limits<double>::infinity();
    for (int a = 0; a < 3; ++a) {
        if (d[a] == 0.0) {
            if (o[a] < g.min[a] || o[a] > g.max[a]) return false;
            continue;
        }
        double t0 = (g.min[a] - o[a]) / d[a], t1 = (g.max[a] - o[a]) / d[a];
        if (t0 > t1) std::swap(t0, t1);
        enter = std::max(enter, t0), leave = std::min(leave, t1);
    }
    return enter <= leave && leave > 0.0;
}

template <Scalar S> std::optional<Hit<S>> PolynomialSurface<S>::intersect(const Ray<S>& ray) const noexcept {
    return order_ <= 4 ? intersect_up_to<4>(ray) : intersect_up_to<detail::max_runtime_degree>(ray);
}

template <Scalar S>
template <std::size_t N>
auto PolynomialSurface<S>::roots_of(const std::array<double, N + 1>& eqn, std::size_t degree, double lo, double hi) noexcept {
    if constexpr (N <= 4) {
        detail::Roots<4> out;
        const auto take = [&](const auto& roots) {
            for (std::size_t r = 0; r < roots.count; ++r) out.push(roots.value[r]);
        };
        switch (degree) {
        case 1: take(detail::roots_in<1>({eqn[0], eqn[1]}, lo, hi)); break;
        case 2: take(detail::roots_in<2>({eqn[0], eqn[1], eqn[2]}, lo, hi)); break;
        case 3: take(detail::roots_in<3>({eqn[0], eqn[1], eqn[2], eqn[3]}, lo, hi)); break;
        default: take(detail::roots_in<4>({eqn[0], eqn[1], eqn[2], eqn[3], eqn[4]}, lo, hi)); break;
        }
        return out;
    } else {
        return detail::roots_up_to(eqn.data(), degree, lo, hi);
    }
}

template <Scalar S>
template <std::size_t N>
std::optional<Hit<S>> PolynomialSurface<S>::intersect_up_to(const Ray<S>& ray) const noexcept {
    const glm::dvec3 origin(ray.origin), direction(ray.direction);
    const double speed = glm::length(direction);
    if (!(speed > 0.0) || !std::isfinite(speed)) return std::nullopt;
    const glm::dvec3 u = direction / speed;
    if (!passes_gate(origin, u)) return std::nullopt;
    // Expand about the ray's point nearest the gate's centre (the origin without a gate).
    const glm::dvec3 focus = !gate_ ? glm::dvec3(0.0)
                             : gate_->kind == PolynomialGate::Kind::sphere ? gate_->center
                                                                           : 0.5 * (gate_->min + gate_->max);
    const double shift = glm::dot(focus - origin, u);
    const glm::dvec3 o = origin + shift * u;

    // p(o + s u) as a polynomial in s, term group by term group: for each (i, j), the z terms
    // sum to w(s) = sum_k c_ijk (o_z + s u_z)^k, which multiplies (o_x + s u_x)^i (o_y + s u_y)^j.
    using Poly = std::array<double, N + 1>;
    const auto n_order = std::size_t(order_);
    const auto power_of = [&](int axis, std::size_t n, Poly& out) {  // (o_a + s u_a)^n
        out[0] = 1.0;
        for (std::size_t m = 1; m <= n; ++m) {
            out[m] = out[m - 1] * u[axis];
            for (std::size_t e = m - 1; e > 0; --e) out[e] = out[e] * o[axis] + out[e - 1] * u[axis];
            out[0] *= o[axis];
        }
    };
    const auto multiply = [](const Poly& a, std::size_t da, const Poly& b, std::size_t db, Poly& out) {
        for (std::size_t e = 0; e <= da + db; ++e) out[e] = 0.0;
        for (std::size_t p = 0; p <= da; ++p)
            if (a[p] != 0.0)
                for (std::size_t q = 0; q <= db; ++q) out[p + q] += a[p] * b[q];
    };
    std::array<Poly, N + 1> z_power;
    for (std::size_t n = 0; n <= n_order; ++n) power_of(2, n, z_power[n]);
    Poly eqn, xi, yj, xy, w, product;
    for (std::size_t e = 0; e <= n_order; ++e) eqn[e] = 0.0;
    int current_i = -1;
    for (std::size_t first = 0; first < terms_.size();) {
        const int i = terms_[first].i, j = terms_[first].j;
        const auto di = std::size_t(i), dj = std::size_t(j);
        std::size_t dw = 0, last = first;
        for (std::size_t e = 0; e + di + dj <= n_order; ++e) w[e] = 0.0;
        for (; last < terms_.size() && terms_[last].i == i && terms_[last].j == j; ++last) {
            const PolynomialTerm& t = terms_[last];
            const auto k = std::size_t(t.k);
            for (std::size_t e = 0; e <= k; ++e) w[e] += t.c * z_power[k][e];
            dw = std::max(dw, k);
        }
        if (i != current_i) power_of(0, di, xi), current_i = i;
        power_of(1, dj, yj);
        multiply(xi, di, yj, dj, xy);
        multiply(xy, di + dj, w, dw, product);
        for (std::size_t e = 0; e <= di + dj + dw; ++e) eqn[e] += product[e];
        first = last;
    }

    // The degree along this ray: the top coefficient is p's highest homogeneous part at u, zero
    // (within its rounding error) along an asymptotic direction.
    std::size_t degree = std::size_t(top_degree_);
    if (std::abs(eqn[degree]) <= 16.0 * std::numeric_limits<double>::epsilon() * top_magnitude_) eqn[degree] = 0.0;
    while (degree > 0 && eqn[degree] == 0.0) --degree;
    if (degree == 0) return std::nullopt;

    // Fujiwara's bound: every root has |s| <= 2 max_m |c[d-m] / c[d]|^(1/m); kept where Horner's
    // rule cannot overflow.
    double reach = 0.0, total = 0.0;
    for (std::size_t m = 1; m <= degree; ++m) {
        const double ratio = std::abs(eqn[degree - m] / eqn[degree]) / (m == degree ? 2.0 : 1.0);
        reach = std::max(reach, std::pow(ratio, 1.0 / double(m)));
    }
    for (std::size_t e = 0; e <= degree; ++e) total += std::abs(eqn[e]);
    reach = std::min(2.0 * reach, std::pow(1e300 / total, 1.0 / double(degree)));
    const double lo = -shift;  // t = 0
    double hi = reach;
    if (std::isfinite(double(ray.t_max))) hi = std::min(hi, double(ray.t_max) * speed - shift);
    if (!(hi > lo)) return std::nullopt;
    const auto roots = roots_of<N>(eqn, degree, std::max(lo, -reach), hi);
    for (std::size_t r = 0; r < roots.count; ++r) {
        const double s = roots.value[r];
        const S t = S((shift + s) / speed);
        if (!(t > S(0)) || !(t < ray.t_max)) continue;
        const glm::dvec3 q = o + s * u;
        glm::dvec3 n = gradient(q);
        const double len = glm::length(n);
        n = len > 0.0 && std::isfinite(len) ? n / len : -u;  // a singular point: facing the ray
        return Hit<S>{t, ray.at(t), Vec3<S>(n)};
    }
    return std::nullopt;
}

}  // namespace photon
