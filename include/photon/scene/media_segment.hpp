// SPDX-License-Identifier: MIT
#pragma once
// Which media a ray segment crosses (integrator/media_seen.hpp says how each pass uses them): a
// segment that ends on the inside of a surface whose material holds media (POV-Ray's interior
// media) ran through them; one that ends on the inside of another transmissive surface ran inside
// glass without media; every other segment (ending on an outside, on the inside of an opaque
// surface, or leaving the scene, then as long as POV-Ray's BOUND_HUGE) ran through the scene's
// atmospheric media. photon keeps no stack of the objects a ray is in: media of nested objects
// do not add, and POV-Ray's `hollow` (atmosphere inside an object too) is not modelled.

#include <optional>
#include <span>
#include <type_traits>

#include "../material/scatter.hpp"
#include "../material/medium.hpp"

namespace photon {

/// The media on the segment of a ray that ends at `surface` seen from side `f` (none: the ray
/// left the scene). Empty when there are none.
template <class SceneT, Scalar S, class SurfaceT>
[[nodiscard]] std::span<const Medium<S>> media_on_segment(const SceneT& scene, const std::optional<SurfaceT>& surface,
                                                          std::type_identity_t<const Facing<S>*> f) {
    if constexpr (requires { scene.media(); }) {
        if (surface && f && !f->entering) {
            const MaterialParams<S>& p = surface->material->params();
            if (!p.media.empty()) return p.media;
            if (!is_black(p.transmission)) return {};
        }
        return scene.media();
    } else {
        return {};
    }
}

/// The length of the segment: to the hit, or POV-Ray's BOUND_HUGE for a ray leaving the scene.
template <Scalar S, class SurfaceT>
[[nodiscard]] S media_segment_length(const Ray<S>& ray, const std::optional<SurfaceT>& surface) noexcept {
    const S scale = glm::length(ray.direction);
    return surface ? surface->hit.t * scale : S(2e10);
}

/// The transmittance alone of the media on a segment (photons, gathers, paths after a diffuse vertex).
template <class SceneT, Scalar S, class SurfaceT>
[[nodiscard]] Rgb<S> media_transmittance_seen(const SceneT& scene, const Ray<S>& ray, const std::optional<SurfaceT>& surface,
                                              std::type_identity_t<const Facing<S>*> f, Pcg32& rng) {
    const std::span<const Medium<S>> media = media_on_segment<SceneT, S>(scene, surface, f);
    if (media.empty()) return Rgb<S>(S(1));
    return media_transmittance(media, ray.origin, glm::normalize(ray.direction), media_segment_length(ray, surface), rng);
}

}  // namespace photon
