// SPDX-License-Identifier: MIT
#pragma once

#include "../estimator/visible_disc.hpp"
#include "shading_context.hpp"

namespace photon {

/// Probes the tangent plane at `x` (already offset off the surface) with one ray per sector of
/// length `radius` and clips each sector at the first occluder found.
template <class SceneT, Scalar S>
[[nodiscard]] VisibleDisc probe_visible_disc(const SceneT& scene, const Vec3<S>& x, const Vec3<S>& n, float radius,
                                             unsigned sectors, ShadingContext& ctx) {
    VisibleDisc disc(Vec3<float>(n), sectors, radius);
    for (unsigned s = 0; s < disc.sectors(); ++s) {
        Ray<S> ray{x, Vec3<S>(disc.sector_direction(s)), S(radius)};
        ++ctx.rays.probe;
        if (const auto hit = scene.intersect(ray))
            disc.clip(s, Vec3<float>(hit->hit.point - x), Vec3<float>(hit->hit.normal));
    }
    return disc;
}

}  // namespace photon
