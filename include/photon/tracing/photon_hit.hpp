// SPDX-License-Identifier: MIT
#pragma once
// The surface a photon meets: the first one along its ray that photons do not pass through.
// POV-Ray lets photons through a light's `looks_like` object (PH_PASSTHRU_FLAG) as its shadow
// rays (no_shadow), so the object, seen by the camera, neither shades nor catches its light.

#include <optional>

#include "../geometry/offset.hpp"
#include "../geometry/ray.hpp"

namespace photon {

/// scene.intersect(ray), past objects with ObjectOptions::passes_photons; `ray` then starts
/// beyond the last one passed, and each extra query adds 1 to `rays`.
template <class SceneT, Scalar S, class Count>
[[nodiscard]] auto photon_intersect(const SceneT& scene, Ray<S>& ray, Count& rays) {
    auto surface = scene.intersect(ray);
    for (int passed = 0; surface && scene.objects()[surface->object].options.passes_photons && passed < 64; ++passed) {
        const Vec3<S> n = surface->hit.normal;
        const Vec3<S> side = glm::dot(n, ray.direction) < S(0) ? -n : n;
        ray = Ray<S>{offset_origin(surface->hit.point, side, intersection_error(surface->hit.point, ray.origin)), ray.direction};
        surface = scene.intersect(ray);
        ++rays;
    }
    return surface;
}

}  // namespace photon
