// SPDX-License-Identifier: MIT
#pragma once

#include <cmath>

#include "../estimator/visible_disc.hpp"
#include "shading_context.hpp"

namespace photon {

/// Probes the tangent plane at `x` (already offset off the surface) with one ray per sector of
/// length `radius` and clips each sector at the first occluder found. A hit on a surface within
/// 30 degrees of the tangent plane is the shaded surface itself curving up (the inside of a
/// sphere), not a wall across the disc, and is ignored.
template <class SceneT, Scalar S>
[[nodiscard]] VisibleDisc probe_visible_disc(const SceneT& scene, const Vec3<S>& x, const Vec3<S>& n, float radius,
                                             unsigned sectors, ShadingContext& ctx) {
    VisibleDisc disc(Vec3<float>(n), sectors, radius);
    for (unsigned s = 0; s < disc.sectors(); ++s) {
        Ray<S> ray{x, Vec3<S>(disc.sector_direction(s)), S(radius)};
        ++ctx.rays.probe;
        const auto hit = scene.intersect(ray);
        if (hit && std::abs(glm::dot(hit->hit.normal, n)) < S(0.866))
            disc.clip(s, Vec3<float>(hit->hit.point - x), Vec3<float>(hit->hit.normal));
    }
    return disc;
}

}  // namespace photon
