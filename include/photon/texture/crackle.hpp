// SPDX-License-Identifier: MIT
#pragma once
// POV-Ray 3.7's cell patterns, value for value: `cells` (one random value per unit cube) and
// `crackle` (the distances to the nearest random cell points: a Voronoi diagram with its form,
// metric, offset and solid variants). Both draw from POV-Ray's table of 32768 pattern random
// numbers (core/math/randomsequence.cpp: boost's mt19937 with its default seed through
// uniform_real on [0, 1)), indexed by the noise hash of the cube, so that a scene's crackle is
// the one POV-Ray shows (source/core/material/pattern.cpp, CellsPattern, CracklePattern).

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <random>
#include <vector>

#include "../math/vec.hpp"
#include "noise.hpp"

namespace photon {

/// `crackle`'s modifiers with POV-Ray's defaults: the value is form.x * d1 + form.y * d2 +
/// form.z * d3, the distances to the three nearest cell points in the Minkowski `metric`, each
/// with `offset` added; `solid` gives every cell the noise at its point instead.
struct CrackleParams {
    Vec3<double> form{-1.0, 1.0, 0.0};
    double metric = 2.0;
    double offset = 0.0;
    bool solid = false;

    friend bool operator==(const CrackleParams&, const CrackleParams&) = default;
};

namespace crackle_detail {

/// POV-Ray's PatternRands: 32768 doubles in [0, 1) from mt19937 (seed 5489), each draw
/// divided by 2^32 (boost::uniform_real over an integer engine).
inline const std::vector<double>& pattern_rands() {
    static const std::vector<double> table = [] {
        std::mt19937 engine;  // default seed 5489, as boost::mt19937
        std::vector<double> t(32768);
        for (double& v : t) {
            double r;
            do r = double(engine()) / 4294967296.0;
            while (!(r < 1.0));  // boost's loop; never taken for a 32-bit draw
            v = r;
        }
        return t;
    }();
    return table;
}
inline double pattern_rand(std::size_t index) { return pattern_rands()[index % 32768]; }

/// POV-Ray's Hash3d: the noise hash of three integers' low 12 bits.
inline int hash3d(int a, int b, int c) noexcept {
    const auto& h = noise_detail::noise_tables().hash;
    return int(h[std::size_t(int(h[std::size_t(int(h[std::size_t(a & 0xFFF)]) ^ (b & 0xFFF))]) ^ (c & 0xFFF))]);
}

/// The cube offsets crackle searches, in POV-Ray's order: every cube within two steps on at most
/// one axis and one step on the others (81 of them), the cube itself included.
inline const std::array<std::array<int, 3>, 81>& neighbour_cubes() noexcept {
    static const std::array<std::array<int, 3>, 81> table = [] {
        std::array<std::array<int, 3>, 81> t{};
        std::size_t n = 0;
        for (int x = -2; x <= 2; ++x)
            for (int y = -2; y <= 2; ++y)
                for (int z = -2; z <= 2; ++z)
                    if ((std::abs(x) == 2) + (std::abs(y) == 2) + (std::abs(z) == 2) <= 1) t[n++] = {x, y, z};
        return t;
    }();
    return table;
}

/// The random point of the unit cube with corner (x, y, z) (IntPickInCube).
inline Vec3<double> cell_point(int x, int y, int z) {
    const std::size_t seed = std::size_t(hash3d(x & 0xFFF, y & 0xFFF, z & 0xFFF));
    return {x + pattern_rand(seed), y + pattern_rand(seed + 1), z + pattern_rand(seed + 2)};
}

}  // namespace crackle_detail

/// POV-Ray's `cells`: the random value of the unit cube holding p.
[[nodiscard]] inline double cells_value(const Vec3<double>& p) {
    constexpr double eps = 1.0e-10;  // POV-Ray's EPSILON
    using namespace crackle_detail;
    const auto cell = [](double v) { return noise_detail::lattice_cell(std::floor(v + eps)); };
    return std::min(pattern_rand(std::size_t(hash3d(cell(p.x), cell(p.y), cell(p.z)))), 1.0);
}

/// POV-Ray's `crackle` at p, clamped to [0, 1] as POV-Ray does.
[[nodiscard]] inline double crackle_value(const Vec3<double>& p, const CrackleParams& c,
                                          NoiseGenerator generator = NoiseGenerator::range_corrected) {
    using namespace crackle_detail;
    constexpr double eps = 1.0e-10;
    const auto cell = [](double v) { return noise_detail::lattice_cell(std::floor(v - eps)); };
    const int fx = cell(p.x), fy = cell(p.y), fz = cell(p.z);
    const bool square = c.metric == 2.0, unity = c.metric == 1.0;
    const auto distance = [&](const Vec3<double>& d) {
        if (square) return glm::dot(d, d);
        if (unity) return std::fabs(d.x) + std::fabs(d.y) + std::fabs(d.z);
        return std::pow(std::fabs(d.x), c.metric) + std::pow(std::fabs(d.y), c.metric) + std::pow(std::fabs(d.z), c.metric);
    };
    // The 81 cell points around the point's cube, kept per thread for the next call in the same
    // cube (POV-Ray caches them too): neighbouring pixels and photons mostly land in one cube.
    struct Cache {
        int x = 0, y = 0, z = 0;
        bool valid = false;
        std::array<Vec3<double>, 81> points;
    };
    thread_local Cache cache;
    if (!cache.valid || cache.x != fx || cache.y != fy || cache.z != fz) {
        const auto& cubes = neighbour_cubes();
        for (std::size_t i = 0; i < 81; ++i)
            cache.points[i] = cell_point(fx + cubes[i][0], fy + cubes[i][1], fz + cubes[i][2]);
        cache.x = fx, cache.y = fy, cache.z = fz, cache.valid = true;
    }
    const std::array<Vec3<double>, 81>& points = cache.points;
    // The three smallest distances (d1 <= d2 <= d3) over the 81 cubes, in POV-Ray's order so
    // that ties pick the same nearest point.
    double d1 = distance(points[0] - p), d2 = distance(points[1] - p), d3 = distance(points[2] - p);
    std::size_t nearest = 0;
    if (d2 < d1) std::swap(d1, d2), nearest = 1;
    if (d3 < d1) std::swap(d1, d3), nearest = 2;
    if (d3 < d2) std::swap(d2, d3);
    for (std::size_t i = 3; i < 81; ++i) {
        const double d = distance(points[i] - p);
        if (d < d1) {
            d3 = d2, d2 = d1, d1 = d, nearest = i;
        } else if (d < d2) {
            d3 = d2, d2 = d;
        } else if (d < d3) {
            d3 = d;
        }
    }
    if (c.offset != 0.0) {
        const double o = square ? c.offset * c.offset : unity ? c.offset : std::pow(c.offset, c.metric);
        d1 += o, d2 += o, d3 += o;
    }
    double v;
    if (c.solid)
        v = pov_noise(points[nearest], generator);
    else if (square)
        v = c.form.x * std::sqrt(d1) + c.form.y * std::sqrt(d2) + c.form.z * std::sqrt(d3);
    else if (unity)
        v = c.form.x * d1 + c.form.y * d2 + c.form.z * d3;
    else
        v = c.form.x * std::pow(d1, 1.0 / c.metric) + c.form.y * std::pow(d2, 1.0 / c.metric) +
            c.form.z * std::pow(d3, 1.0 / c.metric);
    return std::max(std::min(v, 1.0), 0.0);
}

}  // namespace photon
