// SPDX-License-Identifier: MIT
#pragma once
// POV-Ray's adaptive area light (`adaptive N`; trace.cpp, TraceAreaLightSubsetShadowRay): the
// N1 x N2 grid of emitters is shadow-tested at its four corners first, and a region of the grid
// is split into four while its level is below N or its corners' shadows differ (by more than
// 0.1 summed over the channels). A region's light is the mean of its four quarters' (each
// quarter counting the same whatever its size, as POV-Ray averages), a grid point tested once
// however many regions share it. Where the light is wholly seen or wholly hidden the corners
// agree and a few rays stand for the whole grid; at a shadow's edge the grid is refined there.
// Biased, as POV-Ray's (a shadow smaller than the corners' spacing can be missed), so used only
// where photon renders as POV-Ray does (rt and pm's direct light), never by the judges.

#include <cmath>
#include <optional>
#include <vector>

#include "../math/vec.hpp"

namespace photon {

/// What one emitter of the grid gives a shading point: its light there (shadow included) and
/// its shadow alone (1 seen, 0 hidden, per channel through media), which the split compares.
template <Scalar S> struct GridSample {
    Rgb<S> light{S(0)};
    Rgb<S> shadow{S(0)};
};

/// The light of an N1 x N2 grid at one point by POV-Ray's adaptive subdivision, at least `level`
/// levels deep. sample(i, j) gives emitter (i, j)'s GridSample<S>; `grid` is scratch, kept in
/// double for float and double scenes alike (resized here).
template <Scalar S, class SampleFn>
[[nodiscard]] Rgb<S> adaptive_grid_light(unsigned size1, unsigned size2, unsigned level, SampleFn&& sample,
                                         std::vector<std::optional<GridSample<double>>>& grid) {
    grid.assign(std::size_t(size1) * size2, std::nullopt);
    auto at = [&](unsigned i, unsigned j) -> const GridSample<double>& {
        auto& g = grid[std::size_t(i) * size2 + j];
        if (!g) {
            const GridSample<S> s = sample(i, j);
            g = GridSample<double>{Rgb<double>(s.light), Rgb<double>(s.shadow)};
        }
        return *g;
    };
    auto differ = [](const GridSample<double>& a, const GridSample<double>& b) {
        return std::abs(a.shadow.x - b.shadow.x) + std::abs(a.shadow.y - b.shadow.y) + std::abs(a.shadow.z - b.shadow.z) > 0.1;
    };
    // The region [u1, u2] x [v1, v2] of grid points at subdivision depth `depth`.
    auto region = [&](auto&& self, unsigned u1, unsigned v1, unsigned u2, unsigned v2, unsigned depth) -> Rgb<double> {
        const GridSample<double> c[4] = {at(u1, v1), at(u2, v1), at(u1, v2), at(u2, v2)};
        if ((u2 - u1 > 1 || v2 - v1 > 1) &&
            (depth < level || differ(c[0], c[1]) || differ(c[1], c[3]) || differ(c[3], c[2]) || differ(c[2], c[0]))) {
            const unsigned ul = (u1 + u2) / 2, uh = (u1 + u2 + 1) / 2, vl = (v1 + v2) / 2, vh = (v1 + v2 + 1) / 2;
            return (self(self, u1, v1, ul, vl, depth + 1) + self(self, uh, v1, u2, vl, depth + 1) +
                    self(self, u1, vh, ul, v2, depth + 1) + self(self, uh, vh, u2, v2, depth + 1)) *
                   0.25;
        }
        return (c[0].light + c[1].light + c[2].light + c[3].light) * 0.25;
    };
    return Rgb<S>(region(region, 0u, 0u, size1 - 1, size2 - 1, 0u));
}

}  // namespace photon
