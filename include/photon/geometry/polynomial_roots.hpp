// SPDX-License-Identifier: MIT
#pragma once
// Real roots of a polynomial of low degree inside an interval, by bracketing: the roots of the
// derivative (found the same way, recursively) cut the interval into pieces on which the
// polynomial is monotone; a piece whose ends differ in sign holds exactly one root, found by
// Newton steps kept inside the bracket (a step leaving it, or not shrinking it, bisects instead).
// Unlike the closed-form quartic (Ferrari), this never loses a root to cancellation in the
// resolvent cubic, and every root it reports is bracketed by a sign change of the polynomial
// itself. A root of even multiplicity (a tangent ray) shows no sign change and is found only when
// the polynomial's value at the derivative's root is exactly 0: grazing is a miss, or a hit, but
// never a wrong point.
//
// roots_up_to() does the same for a degree known only at run time (POV-Ray's poly, up to 35).

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>

namespace photon::detail {

/// Up to N real roots of a polynomial, ascending.
template <std::size_t N> struct Roots {
    std::array<double, N> value{};
    std::size_t count = 0;
    void push(double x) noexcept {
        if (count < N) value[count++] = x;
    }
};

/// c[0] + c[1] x + ... + c[D] x^D by Horner's rule.
template <std::size_t D> [[nodiscard]] inline double evaluate(const std::array<double, D + 1>& c, double x) noexcept {
    double v = c[D];
    for (std::size_t i = D; i-- > 0;) v = v * x + c[i];
    return v;
}

/// The one root of a monotone polynomial in [lo, hi] where p(lo) and p(hi) differ in sign.
template <std::size_t D>
[[nodiscard]] double bracketed_root(const std::array<double, D + 1>& c, const std::array<double, D>& dc, double lo,
                                    double hi, double p_lo) noexcept {
    double x = 0.5 * (lo + hi);
    for (int iteration = 0; iteration < 100; ++iteration) {
        const double p = evaluate<D>(c, x);
        if (p == 0.0) return x;
        if ((p < 0.0) == (p_lo < 0.0)) lo = x; else hi = x;
        const double slope = evaluate<D - 1>(dc, x);
        double next = slope != 0.0 ? x - p / slope : 0.5 * (lo + hi);
        if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);  // Newton left the bracket: bisect
        if (next == x || hi - lo <= 4.0 * std::numeric_limits<double>::epsilon() * std::max(std::abs(lo), std::abs(hi)))
            return next;
        x = next;
    }
    return x;
}

/// The real roots of c[0] + ... + c[D] x^D in [lo, hi], ascending (c[D] != 0 expected; a
/// polynomial that is identically 0 reports none).
template <std::size_t D> [[nodiscard]] Roots<D> roots_in(const std::array<double, D + 1>& c, double lo, double hi) noexcept {
    Roots<D> out;
    if constexpr (D == 1) {
        if (c[1] != 0.0) {
            const double x = -c[0] / c[1];
            if (x >= lo && x <= hi) out.push(x);
        }
        return out;
    } else {
        std::array<double, D> dc{};
        for (std::size_t i = 1; i <= D; ++i) dc[i - 1] = double(i) * c[i];
        const Roots<D - 1> turning = roots_in<D - 1>(dc, lo, hi);
        double a = lo, p_a = evaluate<D>(c, lo);
        if (p_a == 0.0) out.push(lo);
        for (std::size_t i = 0; i <= turning.count; ++i) {
            const double b = i < turning.count ? turning.value[i] : hi;
            const double p_b = evaluate<D>(c, b);
            if (p_b == 0.0) {
                if (out.count == 0 || out.value[out.count - 1] != b) out.push(b);
            } else if (p_a != 0.0 && (p_a < 0.0) != (p_b < 0.0)) {
                out.push(bracketed_root<D>(c, dc, a, b, p_a));
            }
            a = b, p_a = p_b;
        }
        return out;
    }
}

/// The highest degree roots_up_to() solves (POV-Ray's MAX_ORDER).
inline constexpr std::size_t max_runtime_degree = 35;

/// c[0] + c[1] x + ... + c[degree] x^degree by Horner's rule.
[[nodiscard]] inline double evaluate(const double* c, std::size_t degree, double x) noexcept {
    double v = c[degree];
    for (std::size_t i = degree; i-- > 0;) v = v * x + c[i];
    return v;
}

/// The real roots of c[0] + ... + c[degree] x^degree in [lo, hi], ascending, for 1 <= degree <=
/// max_runtime_degree and c[degree] != 0: roots_in() with the degree a run-time value. The
/// derivatives' roots are found level by level on the stack (about 600 bytes a level).
[[nodiscard]] inline Roots<max_runtime_degree> roots_up_to(const double* c, std::size_t degree, double lo,
                                                          double hi) noexcept {
    Roots<max_runtime_degree> out;
    if (degree == 1) {
        if (c[1] != 0.0) {
            const double x = -c[0] / c[1];
            if (x >= lo && x <= hi) out.push(x);
        }
        return out;
    }
    std::array<double, max_runtime_degree> dc{};
    for (std::size_t i = 1; i <= degree; ++i) dc[i - 1] = double(i) * c[i];
    const Roots<max_runtime_degree> turning = roots_up_to(dc.data(), degree - 1, lo, hi);
    double a = lo, p_a = evaluate(c, degree, lo);
    if (p_a == 0.0) out.push(lo);
    for (std::size_t i = 0; i <= turning.count; ++i) {
        const double b = i < turning.count ? turning.value[i] : hi;
        const double p_b = evaluate(c, degree, b);
        if (p_b == 0.0) {
            if (out.count == 0 || out.value[out.count - 1] != b) out.push(b);
        } else if (p_a != 0.0 && (p_a < 0.0) != (p_b < 0.0)) {
            // The root of the monotone piece [a, b]: Newton kept inside the bracket, as bracketed_root.
            double l = a, h = b, x = 0.5 * (a + b);
            for (int iteration = 0; iteration < 200; ++iteration) {
                const double p = evaluate(c, degree, x);
                if (p == 0.0) break;
                if ((p < 0.0) == (p_a < 0.0)) l = x; else h = x;
                const double slope = evaluate(dc.data(), degree - 1, x);
                double next = slope != 0.0 ? x - p / slope : 0.5 * (l + h);
                if (!(next > l && next < h)) next = 0.5 * (l + h);
                const bool done = next == x || h - l <= 4.0 * std::numeric_limits<double>::epsilon() *
                                                              std::max(std::abs(l), std::abs(h));
                x = next;
                if (done) break;
            }
            out.push(x);
        }
        a = b, p_a = p_b;
    }
    return out;
}

}  // namespace photon::detail
