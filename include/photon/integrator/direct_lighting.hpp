// SPDX-License-Identifier: MIT
#pragma once
// Direct light by shadow rays (paper, section 5.1): one ray per point light, n x n stratified
// rays per sphere light, one per emitter (or jittered cell) of an area light's grid, whose unoccluded estimate is exact and whose partial occlusion gives
// soft shadows; none for a light that casts no shadows. The sky's direct light joins it
// (environment_lighting.hpp). POV-Ray's highlights and brilliance
// (highlight.hpp) are added here only, for direct light.

#include <cmath>
#include <span>
#include <vector>

#include "../geometry/bbox.hpp"
#include "../geometry/offset.hpp"
#include "../light/light.hpp"
#include "../material/highlight.hpp"
#include "../material/material.hpp"
#include "../math/sampling.hpp"
#include "area_light_adaptive.hpp"
#include "environment_lighting.hpp"
#include "filtered_shadow.hpp"
#include "media_seen.hpp"
#include "separating_wall.hpp"
#include "shading_context.hpp"

namespace photon {

/// The most objects an area light's shadow rays test one by one; past it a BVH walk per ray is
/// cheaper than testing each of them against every ray.
inline constexpr std::size_t occluder_list_limit = 32;

/// How direct_lighting samples what it may choose.
struct DirectLightOptions {
    /// Per light, whether it reaches what the camera sees (EffectsPlan::light_emits); null: all.
    const std::vector<bool>* reaches = nullptr;
    unsigned sky_samples = 0;  ///< shadow rays to the sky; 0: its own Environment::shadow_samples
    /// False leaves the sky's light out (rt, as POV-Ray's ray tracing, where the sky lights
    /// diffuse surfaces only under radiosity).
    bool sky_light = true;
    /// An area light with POV-Ray's `adaptive N` is sampled as POV-Ray samples it
    /// (area_light_adaptive.hpp) when its shadow rays are its own grid: rt and pm, as POV-Ray
    /// renders; the judges (sppm, the path tracer) sample every emitter.
    bool adaptive_area_lights = false;
    /// Shadow rays pass transparent surfaces, filtered, as POV-Ray's without photons
    /// (filtered_shadow.hpp): rt. Elsewhere glass stops them (its light arrives by photons).
    bool filtered_shadows = false;
    /// A sphere or area light asked for at least 2 x coarse_shadow_rays rays, and small as seen
    /// from the point (coarse_shadow_light_size), is tried with
    /// coarse_shadow_rays first, and takes the rest only where they disagree (shadow rays where
    /// the light's visibility varies): pm. Biased as POV-Ray's adaptive area light is (a shadow
    /// that all four miss is missed), so never in the judges; rt tests every ray, as POV-Ray does
    /// without `adaptive`.
    bool coarse_shadows = false;
    /// False leaves POV-Ray's highlights out: a point no camera ray sees (a final gather's hit).
    bool highlights = true;
};

/// The rays of coarse_shadows' first try, one in each quarter of the light.
inline constexpr unsigned coarse_shadow_rays = 4;
/// coarse_shadows tries a light with few rays only where its radius is under this fraction of
/// its distance: a light seen wider varies too much over its face for four rays (a ceiling beside
/// the lamp would turn grainy).
inline constexpr double coarse_shadow_light_size = 0.1;

/// What one shadow ray saw of its light.
enum class ShadowSeen { none, all, part };

/// Radiance reflected towards `wo` at the surface point `x` with unit shading normal `n` on the
/// shaded side (a normal field's tilt, else the geometric normal), from every light, by shadow
/// rays leaving from `shadow_origin` (x offset off the surface); light from below the geometric
/// surface (unit normal `geometric_n`, same side) counts for nothing.
/// `albedo` is the material's diffuse reflectance at x (material.diffuse_at(x)), read once by the
/// caller, which needs it too. Callers shade only points the camera sees (directly or through
/// mirrors and glass): the highlights and brilliance apply there only.
/// The light is evaluated at x itself, not at the offset origin: the offset grows with the
/// distance from the world origin (1.5 cm at 1000 units in float) and would otherwise bias
/// cos(theta) / d^2 by as much (2% for a light 1.5 units away).
/// Lights with `(*options.reaches)[l] == false` are skipped: the light-path plan proved that none
/// of their light reaches a point the camera sees (walled off, or zero power), so their shadow
/// rays would all add zero. The scene's sky, if any, adds its direct light
/// (environment_lighting; Lambertian only) unless options.sky_light is false.
template <class SceneT, Scalar S>
[[nodiscard]] Rgb<S> direct_lighting(const SceneT& scene, const Vec3<S>& x, const Vec3<S>& shadow_origin,
                                     const Vec3<S>& n, const Vec3<S>& geometric_n, const Vec3<S>& wo,
                                     const Material<S>& material,
                                     const Rgb<S>& albedo, unsigned shadow_samples, ShadingContext& ctx,
                                     const DirectLightOptions& options = {}) {
    Rgb<S> total(S(0));
    const Rgb<S> brdf = albedo * inv_pi<S>;
    const bool highlights = options.highlights && material.has_highlight();
    const Rgb<S> surface_color = highlights && material.params().metallic > S(0) ? material.highlight_color_at(x) : Rgb<S>(S(1));
    const Rgb<S> highlight_weight = highlights ? material.highlight_weight_at(x) : Rgb<S>(S(0));
    const auto lights = scene.lights();
    for (std::size_t l = 0; l < lights.size(); ++l) {
        if (options.reaches && l < options.reaches->size() && !(*options.reaches)[l]) continue;
        const Light<S>& light = lights[l];
        const IncidentSampler<S> sampler(light, x);
        const auto [columns, rows] = sampler.strata(shadow_samples);
        const unsigned count = columns * rows;
        // A `shadowless` light: no shadow rays, and no highlights (POV-Ray's fill light, trace.cpp).
        const bool shadows = light_casts_shadows(light);
        // All shadow rays to this light stay in the box around their origin and the light
        // (moved by the origin's offset, as the rays are), so only the objects touching that
        // box can block them: found once here, not per ray. Where the box holds many objects
        // (a CSG sculpture of thousands of parts), each ray walks the BVH instead.
        bool culled = false;
        if (shadows && count > 1) {
            const Vec3<S> reach = light_center(light) + (shadow_origin - x);
            BBox<S> region = BBox<S>::of_point(shadow_origin);
            region.extend(BBox<S>{reach - light_radius(light), reach + light_radius(light)});
            culled = scene.occluders_in(region, ctx.occluders, occluder_list_limit);
            // A wall across every ray to this light (a lamp in another room): none can arrive.
            if (culled && wall_between(scene, std::span<const std::uint32_t>(ctx.occluders), shadow_origin, reach,
                                       light_radius(light))) {
                ++ctx.rays.walled_lights;
                continue;
            }
        }
        // What a shadow ray towards `incident` lets through: 1 unblocked, black blocked, and,
        // with filtered shadows (rt), the colour of the transparent surfaces it passes.
        const auto shadow_filter = [&](const auto& incident) -> Rgb<S> {
            ++ctx.rays.shadow;
            const Ray<S> shadow{shadow_origin, incident.direction,
                                shadow_ray_length(shadow_origin, incident.direction, incident.distance)};
            if (!(culled ? scene.occluded_by(ctx.occluders, shadow) : scene.occluded(shadow))) return Rgb<S>(S(1));
            return options.filtered_shadows ? filtered_shadow(scene, shadow) : Rgb<S>(S(0));
        };
        // POV-Ray's adaptive area light: its grid refined where the shadow changes.
        const auto* area = std::get_if<AreaLight<S>>(&light);
        if (options.adaptive_area_lights && area && area->adaptive && shadows && columns == area->size1 &&
            rows == area->size2 && count > 1) {
            total += adaptive_grid_light<S>(
                area->size1, area->size2, *area->adaptive,
                [&](unsigned i, unsigned j) {
                    const Vec2<S> u{(S(i) + (area->jitter ? ctx.rng.uniform<S>() : S(0.5))) / S(area->size1),
                                    (S(j) + (area->jitter ? ctx.rng.uniform<S>() : S(0.5))) / S(area->size2)};
                    GridSample<S> g;
                    const auto incident = sampler.sample(u);
                    if (!incident) return g;
                    const Rgb<S> filter = shadow_filter(*incident);
                    if (is_black(filter)) return g;
                    g.shadow = filter * shadow_ray_media(scene, light, shadow_origin, incident->direction, incident->distance, ctx.rng);
                    const S cos_theta = glm::dot(n, incident->direction);
                    if (!(cos_theta > S(0)) || !(glm::dot(geometric_n, incident->direction) > S(0))) return g;
                    Rgb<S> f = brdf * diffuse_cosine(material, cos_theta);
                    if (highlights && shadows) f += highlight_weight * highlight(material, surface_color, n, wo, incident->direction);
                    g.light = f * incident->irradiance * g.shadow;
                    return g;
                },
                ctx.area_grid);
            continue;
        }
        // One ray to the light at u: its light at x, and whether it saw the light whole, not at all
        // or in part (filtered, rt).
        const auto light_at = [&](const Vec2<S>& u, ShadowSeen& seen) -> Rgb<S> {
            seen = ShadowSeen::none;
            const auto incident = sampler.sample(u);
            if (!incident) return Rgb<S>(S(0));
            const S cos_theta = glm::dot(n, incident->direction);
            if (!(cos_theta > S(0)) || !(glm::dot(geometric_n, incident->direction) > S(0))) return Rgb<S>(S(0));
            const Rgb<S> filter = shadows ? shadow_filter(*incident) : Rgb<S>(S(1));
            if (is_black(filter)) return Rgb<S>(S(0));
            seen = filter == Rgb<S>(S(1)) ? ShadowSeen::all : ShadowSeen::part;
            Rgb<S> f = brdf * diffuse_cosine(material, cos_theta);
            if (highlights && shadows) f += highlight_weight * highlight(material, surface_color, n, wo, incident->direction);
            return f * incident->irradiance * filter *
                   shadow_ray_media(scene, light, shadow_origin, incident->direction, incident->distance, ctx.rng);
        };
        Rgb<S> sum(S(0));
        ShadowSeen seen = ShadowSeen::none;
        if (options.coarse_shadows && shadows && sampler.is_area() && count >= 2 * coarse_shadow_rays &&
            light_radius(light) < coarse_shadow_light_size * glm::length(light_center(light) - x)) {
            // 2 x 2 strata first: where their rays agree the light is taken as wholly seen (or
            // hidden), and they stand for the full count; where they differ, a penumbra, the
            // point takes its full count afresh (so that those rays are not chosen by these).
            sum = light_at(stratified(0, 2, 2, ctx.rng.uniform2<S>()), seen);
            const ShadowSeen first = seen;
            bool agree = first != ShadowSeen::part;
            for (unsigned i = 1; i < coarse_shadow_rays; ++i) {
                sum += light_at(stratified(i, 2, 2, ctx.rng.uniform2<S>()), seen);
                agree = agree && seen == first;
            }
            if (agree) {
                total += sum / S(coarse_shadow_rays);
                continue;
            }
            sum = Rgb<S>(S(0));
        }
        for (unsigned i = 0; i < count; ++i)
            sum += light_at(sampler.is_area() ? stratified(i, columns, rows, ctx.rng.uniform2<S>()) : Vec2<S>(S(0.5)), seen);
        total += sum / S(count);
    }
    if constexpr (requires { scene.environment(); })
        if (options.sky_light && scene.has_environment_light() && material.has_diffuse())
            total += environment_lighting(scene, *scene.environment(), shadow_origin, n, geometric_n, albedo, ctx,
                                          options.sky_samples);
    return total;
}

}  // namespace photon
