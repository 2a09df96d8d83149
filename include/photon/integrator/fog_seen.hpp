// SPDX-License-Identifier: MIT
#pragma once
// Where the scene's fog (scene/fog.hpp) applies: to each segment of a camera ray and of the mirror
// and glass rays that continue it (the paths the camera sees through specular surfaces only),
// as POV-Ray applies it to its "hollow" rays. A segment that ends on the inside of a transmissive
// surface ran inside glass, where POV-Ray has no fog; one that ends on the inside of an opaque
// surface (a camera inside a sky dome) is outside every object and fogged. Shadow rays, photons,
// gathers and paths after a diffuse bounce see no fog (POV-Ray's default, without a light's
// `media_attenuation`), so every mode applies it to the same segments.

#include <optional>
#include <type_traits>

#include "../material/scatter.hpp"
#include "../scene/fog.hpp"

namespace photon {

/// The fog on a camera, mirror or glass ray's segment that ends at `surface` (seen from the side
/// `f`), or that leaves the scene when `surface` is empty; nullopt where there is none.
template <class SceneT, Scalar S, class SurfaceT>
[[nodiscard]] std::optional<FogEffect<S>> fog_seen(const SceneT& scene, const Ray<S>& ray,
                                                   const std::optional<SurfaceT>& surface,
                                                   std::type_identity_t<const Facing<S>*> f) {
    if constexpr (requires { scene.fogs(); }) {
        if (scene.fogs().empty()) return std::nullopt;
        const S scale = glm::length(ray.direction);
        if (!surface) return fog_along(scene.fogs(), ray.origin, ray.direction / scale, fog_unbounded_length<S>);
        if (f && !f->entering && !is_black(surface->material->params().transmission)) return std::nullopt;
        return fog_along(scene.fogs(), ray.origin, ray.direction / scale, surface->hit.t * scale);
    } else {
        return std::nullopt;
    }
}

}  // namespace photon
