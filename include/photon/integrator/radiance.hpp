// SPDX-License-Identifier: MIT
#pragma once
// Pass 2: radiance along a camera ray (paper, Figure 1, "ShadeRayPM"). At a diffuse hit the
// reflected radiance is split as in section 5: direct light by shadow rays, caustics from the
// caustic map, indirect light from the global map, read directly or through final gathering
// (Figure 2). Mirror and glass recurse up to the maximum ray depth. A material's ambient
// radiance is added where camera, mirror and glass rays meet it; gather rays do not see it.
// What arrives along a ray that ran inside absorbing glass is scaled by its transmittance.
// Camera, mirror and glass rays that leave the scene see the sky; gather rays do not (its
// direct light is the shadow rays', what it brings after a bounce the photons'). Fog fades
// what camera, mirror and glass rays bring, not what gathers bring (fog_seen.hpp). Participating
// media (media_seen.hpp) dim, light and glow on camera, mirror and glass rays, and dim gathers.

#include <limits>
#include <optional>
#include <vector>

#include "../estimator/irradiance_gradients.hpp"
#include "../geometry/offset.hpp"
#include "../material/scatter.hpp"
#include "../math/frame.hpp"
#include "boundary_probe.hpp"
#include "direct_lighting.hpp"
#include "fog_seen.hpp"
#include "media_seen.hpp"
#include "photon_maps.hpp"
#include "../settings/render_settings.hpp"

namespace photon {

/// Steps a final-gather path takes through hits nearer than the map's estimate radius before it
/// reads the map wherever it lands (RadianceIntegrator::gathered_radiance).
inline constexpr unsigned near_gather_steps = 4;

template <class SceneT> class RadianceIntegrator {
public:
    using S = typename SceneT::scalar_type;

    /// `lights_reaching[l] == false`: light l sends nothing to what the camera sees (the
    /// light-path plan's shadowed lights), so no shadow ray is traced to it; empty: all lights.
    /// Automatic estimate radii are the ones `maps` carry (with_estimate_radii).
    RadianceIntegrator(const SceneT& scene, const PhotonMaps& maps, const RenderSettings& settings,
                       std::vector<bool> lights_reaching = {})
        : scene_(scene), maps_(maps), settings_(with_estimate_radii(settings, maps)),
          lights_reaching_(std::move(lights_reaching)),
          filtered_shadows_(settings.mode == RenderMode::rt && has_transmissive_material(scene)) {}

    /// Radiance arriving along `ray` (towards its origin). `depth` is 1 for a camera ray; `weight`
    /// is the largest channel of what the ray's radiance is multiplied by in the pixel (1 for a
    /// camera ray), which POV-Ray's adc_bailout compares (RenderSettings::adc_bailout).
    [[nodiscard]] Rgb<S> radiance(const Ray<S>& ray, unsigned depth, ShadingContext& ctx, S weight = S(1)) const {
        const auto surface = scene_.intersect(ray);
        if (!surface) {
            Rgb<S> sky = sky_seen(scene_, ray.direction);
            if (const auto media = media_seen(scene_, ray, surface, nullptr, ctx)) sky = media->apply(sky);
            const auto fog = fog_seen(scene_, ray, surface, nullptr);
            return fog ? fog->apply(sky) : sky;
        }
        const Material<S>& material = *surface->material;
        const Facing<S> f = facing(material, surface->hit.point, surface->hit.normal, ray.direction);
        const Vec3<S>& x = surface->hit.point;
        const S error = intersection_error(x, ray.origin);
        Rgb<S> result = material.ambient_at(x);  // seen by camera, mirror and glass rays, not by gathers
        const S gain = material.seen_gain();      // the surface as written, where it reflects over 1
        // A highlight shows on a surface without diffuse reflection too (POV-Ray's black or glass
        // ball with `phong 1`): direct light is shaded for either.
        if (material.has_diffuse() || material.has_highlight()) {
            const Vec3<S> above = offset_origin(x, f.normal, error);
            const Rgb<S> albedo = material.diffuse_at(x) * gain;
            const Rgb<S> brdf = albedo * inv_pi<S>;
            switch (settings_.mode) {
            case RenderMode::rt:  // the sky is seen, but lights nothing: POV-Ray's ambient stands in
                result += direct_lighting(scene_, x, above, f.shading, f.normal, -ray.direction, material, albedo,
                                          settings_.shadow_samples, ctx,
                                          {.reaches = &lights_reaching_, .sky_light = false, .adaptive_area_lights = true,
                                           .filtered_shadows = filtered_shadows_});
                break;
            case RenderMode::pm:
                result += direct_lighting(scene_, x, above, f.shading, f.normal, -ray.direction, material, albedo,
                                          settings_.shadow_samples, ctx,
                                          {.reaches = &lights_reaching_, .adaptive_area_lights = true, .coarse_shadows = true});
                if (!material.has_diffuse()) break;
                result += brdf * caustic_irradiance(above, f.normal, ctx);
                result += brdf * (settings_.final_gather_rays > 0
                                      ? final_gather(above, f.shading, f.normal, ctx)
                                      : map_irradiance(maps_.global, settings_.global_estimate, above, f.normal, ctx));
                break;
            case RenderMode::pm_direct:
                if (!material.has_diffuse()) break;
                result += brdf * (map_irradiance(maps_.global, settings_.global_estimate, above, f.normal, ctx) +
                                  caustic_irradiance(above, f.normal, ctx));
                break;
            case RenderMode::reference: break;  // rendered by PathTracer
            case RenderMode::sppm: break;       // rendered by render_sppm (sppm.hpp)
            }
        }
        if (depth < settings_.max_ray_depth && material.is_specular())
            result += gain * specular(ray, *surface, f, error, depth, ctx, false, weight * gain);
        result *= segment_transmittance(material, f, surface->hit.t);  // absorbed inside coloured glass
        if (const auto media = media_seen(scene_, ray, surface, &f, ctx)) result = media->apply(result);
        const auto fog = fog_seen(scene_, ray, surface, &f);
        return fog ? fog->apply(result) : result;
    }

private:
    /// Mirror and refraction continuations, each weighted by its reflectance at this hit, each
    /// traced only where its weight in the pixel (`weight` times its reflectance's largest channel)
    /// is at least adc_bailout, as POV-Ray traces them (trace.cpp: a ray below it is black).
    /// `gathering`: the rays belong to a final gather and end in the global map.
    [[nodiscard]] Rgb<S> specular(const Ray<S>& ray, const SurfaceHit<S>& surface, const Facing<S>& f, S error,
                                  unsigned depth, ShadingContext& ctx, bool gathering, S weight) const {
        const Material<S>& material = *surface.material;
        const Vec3<S>& x = surface.hit.point;
        const Scattering<S> s = material.scattering(x, f.shading_cos, f.entering);
        Rgb<S> result(S(0));
        Rgb<S> reflected_weight = s.specular;
        if (!is_black(s.transmission)) {
            if (const auto refracted = refraction_direction(ray.direction, f, relative_eta(material, f.entering))) {
                const S w = weight * max_component(s.transmission);
                if (traced(w)) {
                    if (gathering) ++ctx.rays.gather; else ++ctx.rays.refraction;
                    const Ray<S> next{offset_origin(x, -f.normal, error), *refracted};
                    result += s.transmission * trace(next, depth + 1, ctx, gathering, w);
                }
            } else {
                reflected_weight += s.transmission;  // total internal reflection
            }
        }
        const S w = weight * max_component(reflected_weight);
        if (!is_black(reflected_weight) && traced(w)) {
            if (gathering) ++ctx.rays.gather; else ++ctx.rays.reflection;
            const Ray<S> next{offset_origin(x, f.normal, error), mirror_direction(ray.direction, f)};
            result += reflected_weight * trace(next, depth + 1, ctx, gathering, w);
        }
        return result;
    }

    /// Whether a ray of weight `w` in its pixel is traced (adc_bailout 0: always).
    [[nodiscard]] bool traced(S w) const noexcept { return w >= S(settings_.adc_bailout); }

    [[nodiscard]] Rgb<S> trace(const Ray<S>& ray, unsigned depth, ShadingContext& ctx, bool gathering, S weight) const {
        return gathering ? gathered_radiance(ray, depth, ctx, nullptr, weight) : radiance(ray, depth, ctx, weight);
    }

    /// Irradiance from one map at `x`, with the thin-wall probes if the settings ask for them.
    [[nodiscard]] Rgb<S> map_irradiance(const std::optional<PhotonMap>& map, const EstimateSettings& es,
                                        const Vec3<S>& x, const Vec3<S>& n, ShadingContext& ctx) const {
        if (!map || map->empty()) return Rgb<S>(S(0));
        ++ctx.estimates;
        if (es.boundary_probes == 0) return estimate_irradiance(*map, x, n, es, ctx.scratch);
        const VisibleDisc disc = probe_visible_disc(scene_, x, n, es.max_radius, es.boundary_probes, ctx);
        return estimate_irradiance(*map, x, n, es, ctx.scratch, &disc);
    }

    /// Irradiance at x from L S+ D paths: the caustic map, and the global pass's unaimed caustics.
    [[nodiscard]] Rgb<S> caustic_irradiance(const Vec3<S>& x, const Vec3<S>& n, ShadingContext& ctx) const {
        return map_irradiance(maps_.caustic, settings_.caustic_estimate, x, n, ctx) +
               map_irradiance(maps_.unaimed_caustic, settings_.global_estimate, x, n, ctx);
    }

    /// Indirect irradiance at x by final gathering (through the irradiance cache when there is one
    /// and it covers x), for shading normal n over geometric normal geometric_n. The pretrace
    /// covered every pixel's centre; a point of an anti-aliasing sample between records takes
    /// them with twice the error bound before it gathers in full (each full gather costs as much
    /// as a record).
    [[nodiscard]] Rgb<S> final_gather(const Vec3<S>& x, const Vec3<S>& n, const Vec3<S>& geometric_n,
                                      ShadingContext& ctx) const {
        if (maps_.irradiance_cache) {
            const Vec3<float> xf(x), nf(n);
            if (const auto e = maps_.irradiance_cache->interpolate(xf, nf, ctx.nearest)) return Rgb<S>(*e);
            if (const auto e = maps_.irradiance_cache->interpolate(xf, nf, ctx.nearest, 2.0f)) return Rgb<S>(*e);
        }
        return gather(x, n, settings_.final_gather_rays, ctx, geometric_n).irradiance;
    }

public:
    struct Gathered {
        Rgb<S> irradiance;
        S harmonic_distance;  ///< harmonic mean of the distances the rays travelled (inf: none hit)
    };

    /// Final gathering at x (already offset) with unit shading normal n: `rays` cosine-distributed
    /// rays, stratified in (theta, phi) cells (GatherStrata: the cells Ward and Heckbert's gradients
    /// need), whose hits are read from the global map, or its precomputed irradiance.
    /// E = pi * mean L. Under a tilted shading normal (geometric_n differs from n), the rays
    /// that would enter the surface bring nothing, as the path tracer's do. `samples`, if given,
    /// receives every cell's sample, row by row (for irradiance_gradients).
    [[nodiscard]] Gathered gather(const Vec3<S>& x, const Vec3<S>& n, unsigned rays, ShadingContext& ctx,
                                  std::optional<Vec3<S>> geometric_n = std::nullopt,
                                  std::vector<GatherSample<S>>* samples = nullptr) const {
        if (geometric_n && *geometric_n == n) geometric_n.reset();
        const GatherStrata strata = GatherStrata::for_rays(rays);
        const unsigned count = strata.count();
        const Frame<S> frame = Frame<S>::from_normal(n);
        if (samples) samples->clear();
        Rgb<S> sum(S(0));
        S inverse_distances = 0;
        for (unsigned i = 0; i < count; ++i) {
            const GatherSample<S> sample = gather_sample(x, frame, strata, i, ctx, geometric_n);
            sum += sample.radiance;
            inverse_distances += S(1) / sample.distance;
            if (samples) samples->push_back(sample);
        }
        return {sum * (pi<S> / S(count)),
                inverse_distances > S(0) ? S(count) / inverse_distances : std::numeric_limits<S>::infinity()};
    }

    /// One ray of a stratified gather at x (offset) in `frame` (z the shading normal): cell `cell`
    /// of `strata` (row by row), jittered within sub-cell `sub_cell` of `within` when the cell is
    /// split further; a direction below the geometric normal, when one is given, traces no ray
    /// and brings nothing.
    [[nodiscard]] GatherSample<S> gather_sample(const Vec3<S>& x, const Frame<S>& frame, const GatherStrata& strata,
                                                unsigned cell, ShadingContext& ctx,
                                                const std::optional<Vec3<S>>& geometric_n,
                                                GatherStrata within = {}, unsigned sub_cell = 0) const {
        const Vec2<S> jitter = ctx.rng.uniform2<S>();
        const Vec2<S> u{(S(sub_cell / within.columns) + jitter.x) / S(within.rows),
                        (S(sub_cell % within.columns) + jitter.y) / S(within.columns)};
        const Vec3<S> local = strata.direction(cell / strata.columns, cell % strata.columns, u);
        const Vec3<S> dir = frame.to_world(local);
        GatherSample<S> sample{local, Rgb<S>(S(0)), std::numeric_limits<S>::infinity()};
        if (!geometric_n || glm::dot(*geometric_n, dir) > S(0)) {
            ++ctx.rays.gather;
            sample.radiance = gathered_radiance(Ray<S>{x, dir}, 1, ctx, &sample.distance);
        }
        return sample;
    }

    /// Calls visit(x, n, geometric_n, path_length) for every diffuse hit of the camera ray and of the mirror
    /// and glass rays it spawns (as radiance() would shade them), with x already offset.
    template <class Visit>
    void for_each_diffuse_hit(const Ray<S>& ray, unsigned depth, S path_length, Visit&& visit, S weight = S(1)) const {
        const auto surface = scene_.intersect(ray);
        if (!surface) return;
        const Material<S>& material = *surface->material;
        const Facing<S> f = facing(material, surface->hit.point, surface->hit.normal, ray.direction);
        const Vec3<S>& x = surface->hit.point;
        const S error = intersection_error(x, ray.origin);
        const S length = path_length + surface->hit.t;
        if (material.has_diffuse()) visit(offset_origin(x, f.normal, error), f.shading, f.normal, length);
        if (depth >= settings_.max_ray_depth || !material.is_specular()) return;
        const Scattering<S> sc = material.scattering(x, f.shading_cos, f.entering);
        const S gain = material.seen_gain();
        Rgb<S> reflected_weight = sc.specular;
        if (!is_black(sc.transmission)) {
            if (const auto refracted = refraction_direction(ray.direction, f, relative_eta(material, f.entering))) {
                const S w = weight * gain * max_component(sc.transmission);
                if (traced(w))
                    for_each_diffuse_hit(Ray<S>{offset_origin(x, -f.normal, error), *refracted}, depth + 1, length, visit, w);
            } else {
                reflected_weight += sc.transmission;
            }
        }
        const S w = weight * gain * max_component(reflected_weight);
        if (!is_black(reflected_weight) && traced(w))
            for_each_diffuse_hit(Ray<S>{offset_origin(x, f.normal, error), mirror_direction(ray.direction, f)}, depth + 1,
                                 length, visit, w);
    }

private:
    /// Radiance along a gather ray: the global map's estimate at its first diffuse hit, through
    /// mirrors and glass.
    /// `distance`, if given, receives the distance to the first hit.
    [[nodiscard]] Rgb<S> gathered_radiance(const Ray<S>& ray, unsigned depth, ShadingContext& ctx,
                                           S* distance = nullptr, S weight = S(1)) const {
        const auto surface = scene_.intersect(ray);
        if (!surface) return Rgb<S>(S(0));
        if (distance) *distance = surface->hit.t;
        const Material<S>& material = *surface->material;
        const Facing<S> f = facing(material, surface->hit.point, surface->hit.normal, ray.direction);
        const S error = intersection_error(surface->hit.point, ray.origin);
        Rgb<S> result(S(0));
        if (material.has_diffuse()) {
            const Vec3<S> above = offset_origin(surface->hit.point, f.normal, error);
            const Rgb<S> albedo = material.diffuse_at(surface->hit.point);
            // A hit nearer the gathering point than the map's estimate radius lies where a contact
            // or crevice can be smaller than the estimate's disc, which would blur the light of
            // the open floor around into it (a lighter band where a ball meets the floor): its
            // light is traced one step further instead, direct light by a shadow ray and the
            // rest by one cosine-distributed ray read from the map where it lands (E = pi L).
            if (distance && surface->hit.t < S(settings_.global_estimate.max_radius)) {
                result += direct_lighting(scene_, surface->hit.point, above, f.shading, f.normal, -ray.direction, material,
                                          albedo, 1, ctx, {.reaches = &lights_reaching_, .highlights = false});
                const Vec3<S> dir = Frame<S>::from_normal(f.shading).to_world(cosine_hemisphere(ctx.rng.uniform2<S>()));
                if (glm::dot(dir, f.normal) > S(0)) {
                    ++ctx.rays.gather;
                    S further = 0;  // its hit, if near too, is traced on: up to near_gather_steps in all
                    result += albedo * gathered_radiance(Ray<S>{above, dir}, depth + 1, ctx,
                                                         depth < near_gather_steps ? &further : nullptr);
                }
            } else {
                const Rgb<S> irradiance = maps_.irradiance ? precomputed_irradiance(above, f.normal, ctx)
                                                           : map_irradiance(maps_.global, settings_.global_estimate,
                                                                            above, f.normal, ctx);
                // Irradiance, precomputed or estimated, times the albedo here: right under a texture.
                result += albedo * inv_pi<S> * irradiance;
            }
        }
        if (depth < settings_.max_ray_depth && material.is_specular())
            result += specular(ray, *surface, f, error, depth, ctx, true, weight);
        return result * segment_transmittance(material, f, surface->hit.t) *
               media_transmittance_seen(scene_, ray, surface, &f, ctx.rng);
    }

    /// Precomputed irradiance at a gather hit: the nearest sample on the same surface that x can
    /// see, or a density estimate from the global map where no sample qualifies (an object
    /// smaller than the sample spacing, a sample hidden behind a wall).
    ///
    /// The visibility test is a short shadow ray from x to the sample, both ends lifted off the
    /// surface by a quarter of their distance: unlifted, the chord between two points of a convex
    /// surface runs inside it, so on a ball every sample was rejected and the ball's bounce light
    /// (colour bleeding onto the floor) read black. Lifted by d / 4, the segment clears a sphere of
    /// any radius for samples within the lookup's 25 degrees of normal, and a wall standing on
    /// the surface between them still blocks it unless it is lower than d / 4.
    [[nodiscard]] Rgb<S> precomputed_irradiance(const Vec3<S>& x, const Vec3<S>& n, ShadingContext& ctx) const {
        const auto visible = [&](const Vec3<float>& sample, const Vec3<float>& sample_normal) {
            const Vec3<S> p(sample);
            const S lift = glm::length(p - x) * S(0.25);
            const Vec3<S> from = x + lift * n;
            const Vec3<S> to = offset_origin(p, Vec3<S>(sample_normal), stored_point_error(p, x)) +
                               lift * Vec3<S>(sample_normal);
            ++ctx.rays.probe;
            return !scene_.occluded(Ray<S>{from, to - from, S(1)});
        };
        if (const auto e = maps_.irradiance->find(Vec3<float>(x), Vec3<float>(n), settings_.global_estimate.max_radius,
                                                  ctx.nearest, visible))
            return Rgb<S>(*e);
        return map_irradiance(maps_.global, settings_.global_estimate, x, n, ctx);
    }

    const SceneT& scene_;
    const PhotonMaps& maps_;
    const RenderSettings settings_;  ///< a copy, with the maps' estimate radii
    std::vector<bool> lights_reaching_;
    /// rt, in a scene with a surface that transmits light: shadow rays pass it, filtered
    /// (filtered_shadow.hpp); without one, every shadow-ray hit is opaque and the test is skipped.
    bool filtered_shadows_ = false;

    [[nodiscard]] static bool has_transmissive_material(const SceneT& scene) {
        for (std::uint32_t id = 0; id < scene.objects().size(); ++id)
            if (scene.any_material_of(id, is_transmissive_material)) return true;
        return false;
    }
};

}  // namespace photon
