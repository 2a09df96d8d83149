// SPDX-License-Identifier: MIT
#pragma once
// Crofton's formula as a test of a surface: isotropic uniform lines through a ball of radius B
// cross a surface of area A on average A / (2 pi B^2) times. Shared by the shape tests
// (quadrics_test.cpp, csg_test.cpp), each of which walks a line's crossings its own way.

#include <photon/math/frame.hpp>
#include <photon/math/rng.hpp>
#include <photon/math/sampling.hpp>

#include <cmath>
#include <cstdint>
#include <utility>

namespace photon::testing {

/// Mean crossings of `lines` isotropic uniform lines through the ball (centre, radius), and its
/// standard error. `crossings(ray)` counts one line's crossings; the ray starts just outside the
/// ball and points along the line.
template <class S, class CountCrossings>
std::pair<double, double> mean_crossings(const Vec3<S>& center, S radius, int lines, std::uint64_t seed,
                                         CountCrossings&& crossings_of) {
    Pcg32 rng(seed, 0);
    long crossings = 0, squares = 0;
    for (int i = 0; i < lines; ++i) {
        const Vec3<S> u = uniform_sphere<S>(rng.uniform2<S>());
        const Frame<S> f = Frame<S>::from_normal(u);
        const Vec2<S> p = concentric_disc<S>(rng.uniform2<S>()) * radius;
        const long k = crossings_of(Ray<S>{center + f.tangent * p.x + f.bitangent * p.y - u * (radius * S(1.01)), u});
        crossings += k, squares += k * k;
    }
    const double mean = double(crossings) / lines, variance = double(squares) / lines - mean * mean;
    return {mean, std::sqrt(variance / lines)};
}

}  // namespace photon::testing
