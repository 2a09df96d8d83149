// SPDX-License-Identifier: MIT
#pragma once
// Direct light from the sky (light/environment.hpp) at a diffuse point, by shadow rays to
// infinity. A constant sky is sampled by the cosine: every unoccluded ray then brings exactly
// rho L, so a surface under an open sky is exact and one under a window is as noisy as the
// window's share of the hemisphere. A varying sky draws each ray either by the cosine or by the
// sky's table, with even odds, and weighs it by the mixture's density (one-sample MIS with the
// balance heuristic, Veach 1997): a bright spot is found by the table, the broad rest by the
// cosine, and neither can make the other's rays blow up. Lambertian only: POV-Ray's highlights
// and brilliance answer light_sources, not its sky.

#include "../light/environment.hpp"
#include "../math/frame.hpp"
#include "../math/sampling.hpp"
#include "shading_context.hpp"

namespace photon {

/// What a camera, mirror or glass ray along `direction` (any length) sees when it leaves
/// `scene`: the sky, or black without one.
template <class SceneT, Scalar S>
[[nodiscard]] Rgb<S> sky_seen(const SceneT& scene, const Vec3<S>& direction) noexcept {
    if constexpr (requires { scene.environment(); })
        if (scene.environment()) return scene.environment()->radiance(glm::normalize(direction));
    return Rgb<S>(S(0));
}

/// Density per steradian of environment_lighting's rays at unit `direction` from a point of
/// unit shading normal `n`: cos / pi for a constant sky, else the mean of that and the sky's.
template <Scalar S>
[[nodiscard]] S environment_direct_pdf(const Environment<S>& sky, const Vec3<S>& n, const Vec3<S>& direction) noexcept {
    const S cosine = std::max(S(0), glm::dot(n, direction)) * inv_pi<S>;
    return sky.is_constant() ? cosine : S(0.5) * (cosine + sky.pdf(direction));
}

/// Radiance that the Lambertian reflectance `albedo` at a point with unit shading normal `n`
/// (geometric normal `geometric_n`, same side; light from below it counts for nothing) reflects
/// from the sky, by `samples` stratified shadow rays from `shadow_origin` (0: sky.shadow_samples).
template <class SceneT, Scalar S>
[[nodiscard]] Rgb<S> environment_lighting(const SceneT& scene, const Environment<S>& sky, const Vec3<S>& shadow_origin,
                                          const Vec3<S>& n, const Vec3<S>& geometric_n, const Rgb<S>& albedo,
                                          ShadingContext& ctx, unsigned samples = 0) {
    if (sky.is_black() || is_black(albedo)) return Rgb<S>(S(0));
    const unsigned grid = strata_per_axis(samples > 0 ? samples : sky.shadow_samples);
    const unsigned count = grid * grid;
    const Frame<S> frame = Frame<S>::from_normal(n);
    Rgb<S> sum(S(0));
    for (unsigned i = 0; i < count; ++i) {
        const Vec2<S> u = stratified(i, grid, ctx.rng.uniform2<S>());
        const bool by_cosine = sky.is_constant() || ctx.rng.uniform<S>() < S(0.5);
        const Vec3<S> d = by_cosine ? frame.to_world(cosine_hemisphere(u)) : sky.sample(u).direction;
        const S cos_theta = glm::dot(n, d);
        if (!(cos_theta > S(0)) || !(glm::dot(geometric_n, d) > S(0))) continue;
        const S pdf = environment_direct_pdf(sky, n, d);
        if (!(pdf > S(0))) continue;
        ++ctx.rays.shadow;
        if (scene.occluded(Ray<S>{shadow_origin, d})) continue;
        sum += sky.radiance(d) * (cos_theta / pdf);
    }
    return albedo * inv_pi<S> * sum / S(count);
}

}  // namespace photon
