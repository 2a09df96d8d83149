// SPDX-License-Identifier: MIT
#pragma once
// POV-Ray's `spline { }` value: floats or vectors (up to 5 components) at parameters kept in
// increasing order, interpolated linearly, quadratically, by Catmull-Rom (`cubic_spline`) or by a
// natural cubic, with POV-Ray 3.7's rules at the ends (no extrapolation: the end values hold;
// Catmull-Rom holds the second and next-to-last points, its first and last being tangents only).

#include <algorithm>
#include <array>
#include <cstddef>
#include <vector>

namespace photon::dsl {

struct Spline {
    enum class Kind { linear, quadratic, cubic, natural };
    using Point = std::array<double, 5>;

    Kind kind = Kind::linear;
    std::vector<double> t;     ///< increasing
    std::vector<Point> value;  ///< value[i] at t[i]
    int dim = 0;               ///< 0: the values are floats; else vectors of dim components

    /// Inserts or, at an existing parameter, replaces (as POV-Ray's Insert_Spline_Entry).
    void insert(double p, const Point& v) {
        std::size_t i = 0;
        while (i < t.size() && t[i] < p) ++i;
        if (i < t.size() && t[i] == p) {
            value[i] = v;
            return;
        }
        t.insert(t.begin() + std::ptrdiff_t(i), p);
        value.insert(value.begin() + std::ptrdiff_t(i), v);
    }

    /// The value at p, interpolated as `k` says.
    [[nodiscard]] Point at(double p, Kind k) const {
        const std::size_t n = t.size();
        if (n == 1) return value[0];
        // i: the segment's end, as POV-Ray's findt: 0 up to the first parameter, n from the last,
        // else the first entry whose parameter is >= p.
        std::size_t i = 0;
        if (p >= t.back())
            i = n;
        else if (p > t.front())
            i = std::size_t(std::lower_bound(t.begin(), t.end(), p) - t.begin());
        Point r{};
        if (k == Kind::cubic) {
            for (int c = 0; c < 5; ++c) {
                if (n == 2)
                    r[c] = (value[0][c] + value[1][c]) / 2;
                else if (i < 2)
                    r[c] = value[1][c];
                else if (i >= n - 1)
                    r[c] = value[n - 2][c];
                else
                    r[c] = catmull_rom(i - 1, c, p);
            }
            return r;
        }
        if (i == 0) return value.front();
        if (i >= n) return value.back();
        std::vector<double> second;
        if (k == Kind::natural) second = natural_second_derivatives();
        for (int c = 0; c < 5; ++c) {
            if (k == Kind::linear || (k == Kind::quadratic && n == 2))
                r[c] = linear(i - 1, c, p);
            else if (k == Kind::quadratic)
                r[c] = quadratic(i > 1 ? i - 1 : i, c, p);
            else
                r[c] = natural(second, i - 1, c, p);
        }
        return r;
    }

private:
    double linear(std::size_t i, int c, double p) const {
        return (p - t[i]) * (value[i + 1][c] - value[i][c]) / (t[i + 1] - t[i]) + value[i][c];
    }
    /// The parabola through entries i-1, i, i+1.
    double quadratic(std::size_t i, int c, double p) const {
        const double p1 = t[i - 1], p2 = t[i], p3 = t[i + 1];
        const double v1 = value[i - 1][c], v2 = value[i][c], v3 = value[i + 1][c];
        const double d = (p2 - p1) * (p3 - p1) * (p3 - p2);
        const double a = (-p2 * v1 + p3 * v1 + p1 * v2 - p3 * v2 - p1 * v3 + p2 * v3) / d;
        const double b = (p2 * p2 * v1 - p3 * p3 * v1 - p1 * p1 * v2 + p3 * p3 * v2 + p1 * p1 * v3 - p2 * p2 * v3) / d;
        const double e = (-p2 * p2 * p3 * v1 + p2 * p3 * p3 * v1 + p1 * p1 * p3 * v2 - p1 * p3 * p3 * v2 -
                          p1 * p1 * p2 * v3 + p1 * p2 * p2 * v3) /
                         d;
        return (a * p + b) * p + e;
    }
    /// Hermite segment from entry i to i+1 with the Catmull-Rom tangents of its neighbours.
    double catmull_rom(std::size_t i, int c, double p) const {
        const double dt = t[i + 1] - t[i], u = (p - t[i]) / dt;
        const double slope0 = (value[i][c] - value[i - 1][c]) / (t[i] - t[i - 1]);
        const double slope1 = (value[i + 1][c] - value[i][c]) / dt;
        const double slope2 = (value[i + 2][c] - value[i + 1][c]) / (t[i + 2] - t[i + 1]);
        const double m0 = (slope0 + slope1) / 2 * dt, m1 = (slope2 + slope1) / 2 * dt;
        return value[i][c] * (2 * u * u * u - 3 * u * u + 1) + value[i + 1][c] * (3 * u * u - 2 * u * u * u) +
               m0 * (u * u * u - 2 * u * u + u) + m1 * (u * u * u - u * u);
    }
    /// Second derivatives of the natural cubic through every entry (zero at both ends), per
    /// component: entry 5 * i + c.
    std::vector<double> natural_second_derivatives() const {
        const std::size_t n = t.size();
        std::vector<double> m(5 * n, 0.0), h(n), b(n), u(n), v(n);
        for (int c = 0; c < 5; ++c) {
            for (std::size_t i = 0; i + 1 < n; ++i) {
                h[i] = t[i + 1] - t[i];
                b[i] = (value[i + 1][c] - value[i][c]) / h[i];
            }
            if (n < 3) continue;
            u[1] = 2 * (h[0] + h[1]);
            v[1] = 6 * (b[1] - b[0]);
            for (std::size_t i = 2; i + 1 < n; ++i) {
                u[i] = 2 * (h[i] + h[i - 1]) - h[i - 1] * h[i - 1] / u[i - 1];
                v[i] = 6 * (b[i] - b[i - 1]) - h[i - 1] * v[i - 1] / u[i - 1];
            }
            for (std::size_t i = n - 2; i > 0; --i) m[5 * i + c] = (v[i] - h[i] * m[5 * (i + 1) + c]) / u[i];
        }
        return m;
    }
    double natural(const std::vector<double>& m, std::size_t i, int c, double p) const {
        const double h = t[i + 1] - t[i], mi = m[5 * i + c], mj = m[5 * (i + 1) + c];
        double q = mi / 2 + (p - t[i]) * (mj - mi) / (6 * h);
        q = -(h / 6) * (mj + 2 * mi) + (value[i + 1][c] - value[i][c]) / h + (p - t[i]) * q;
        return value[i][c] + (p - t[i]) * q;
    }
};

}  // namespace photon::dsl
