// SPDX-License-Identifier: MIT
#pragma once
// The bounding box of an intersection of half-spaces (POV-Ray's polyhedra: `intersection` of
// planes, shapes2.inc's Tetrahedron to Icosahedron), which no child's own bounds limit: every
// plane is infinite. Its vertices are where three of the planes meet inside all the others; a
// cube of half-size `reach` closes it first, so that an unbounded intersection (a wedge) has
// vertices too, and an axis whose extent reaches the cube stays infinite. Vertex enumeration is
// cubic in the planes' count, run once per object at the scene's build; past `max_half_spaces`
// the box is left infinite.

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <span>
#include <vector>

#include "../math/vec.hpp"
#include "bbox.hpp"

namespace photon {

/// {x : dot(normal, x) <= offset}.
struct HalfSpace {
    glm::dvec3 normal;
    double offset;
};

inline constexpr std::size_t max_half_spaces = 48;


/// The bounds of the intersection of `spaces`, infinite on the axes where it is unbounded (or
/// wider than `reach` from the origin); an empty box when the intersection is empty.
template <Scalar S> [[nodiscard]] BBox<S> half_space_bounds(std::span<const HalfSpace> spaces, double reach = 1e7) {
    if (spaces.size() > max_half_spaces) return BBox<S>::infinite();
    std::vector<HalfSpace> all(spaces.begin(), spaces.end());
    for (int a = 0; a < 3; ++a) {
        glm::dvec3 n(0.0);
        n[a] = 1.0;
        all.push_back({n, reach});
        all.push_back({-n, reach});
    }
    // Rounding in a vertex grows with the coordinates it is made of.
    double scale = 0.0;
    for (const HalfSpace& h : spaces) scale = std::max(scale, std::abs(h.offset) / glm::length(h.normal));
    constexpr double relative = 1e-9;
    glm::dvec3 lo(std::numeric_limits<double>::infinity()), hi(-std::numeric_limits<double>::infinity());
    bool any = false;
    for (std::size_t i = 0; i < all.size(); ++i) {
        const double li = glm::length(all[i].normal);
        if (!(li > 0.0)) continue;
        for (std::size_t j = i + 1; j < all.size(); ++j)
            for (std::size_t k = j + 1; k < all.size(); ++k) {
                const glm::dvec3 &a = all[i].normal, &b = all[j].normal, &c = all[k].normal;
                const glm::dvec3 bc = glm::cross(b, c);
                const double det = glm::dot(a, bc);
                if (!(std::abs(det) > 1e-12 * li * glm::length(b) * glm::length(c))) continue;  // parallel
                const glm::dvec3 x =
                    (all[i].offset * bc + all[j].offset * glm::cross(c, a) + all[k].offset * glm::cross(a, b)) / det;
                const double tolerance = relative * std::max(scale, std::max({std::abs(x.x), std::abs(x.y), std::abs(x.z)}));
                bool inside = true;
                for (std::size_t m = 0; m < all.size() && inside; ++m)
                    inside = glm::dot(all[m].normal, x) <= all[m].offset + tolerance * glm::length(all[m].normal);
                if (!inside) continue;
                lo = glm::min(lo, x), hi = glm::max(hi, x);
                any = true;
            }
    }
    if (!any) return BBox<S>{};
    BBox<S> box;
    for (int a = 0; a < 3; ++a) {
        const bool open_low = lo[a] <= -reach * (1 - 1e-6), open_high = hi[a] >= reach * (1 - 1e-6);
        const auto pad = [&](double v) { return 4.0 * relative * std::max(scale, std::abs(v)); };
        box.min[a] = open_low ? -std::numeric_limits<S>::infinity() : rounded_down<S>(lo[a] - pad(lo[a]));
        box.max[a] = open_high ? std::numeric_limits<S>::infinity() : rounded_up<S>(hi[a] + pad(hi[a]));
    }
    return box;
}

}  // namespace photon
