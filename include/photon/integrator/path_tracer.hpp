// SPDX-License-Identifier: MIT
#pragma once
// Reference solution: unbiased path tracing (Kajiya 1986) of the same light paths the photon
// mapper renders, to measure the photon mapper's error. Slow by design; not a rendering mode
// for pictures. A path continues by the same Russian roulette as photons. Lights stay invisible
// to camera and mirror rays (as in every other mode).
//
// Direct light at a diffuse vertex has two strategies, combined by multiple importance sampling
// (Veach 1997, power heuristic): one shadow ray per light (IncidentSampler's cone), and the
// vertex's own diffuse continuation when it meets a sphere light. Light met after mirrors or
// glass that follow a diffuse vertex (caustics, L S+ D E) has one strategy only, the path's
// continuation: it counts with weight 1, and it is found by chance, so it is noisy. Through
// mirrors or glass a point light is never met: those caustics are missing (black).
//
// The sky (light/environment.hpp) is one more light with both strategies: a shadow ray drawn
// as environment_lighting draws them (its density environment_direct_pdf), and the diffuse
// continuation that leaves the scene. Camera and mirror rays that leave the scene see it.
// Fog fades the segments of the path until its first diffuse vertex (fog_seen.hpp); participating
// media light and dim those segments and dim the later ones (media_seen.hpp).

#include <limits>
#include <string>

#include "../geometry/offset.hpp"
#include "../light/light_sample.hpp"
#include "../material/scatter.hpp"
#include "direct_lighting.hpp"
#include "environment_lighting.hpp"
#include "fog_seen.hpp"
#include "media_seen.hpp"
#include "../settings/render_settings.hpp"

namespace photon {

/// Veach's power heuristic (beta = 2) for one sample of each of two strategies: the weight of
/// the strategy of density `pdf` against the other's `other`. Written as 1 / (1 + (b/a)^2) so
/// that the densities of tiny lights (1e11 per steradian and more) cannot overflow.
template <Scalar S> [[nodiscard]] S power_heuristic(S pdf, S other) noexcept {
    if (!(pdf > S(0))) return S(0);
    const S ratio = other / pdf;
    return S(1) / (S(1) + ratio * ratio);
}

/// What the reference cannot see in `scene`, as a sentence (empty when it sees everything): a
/// point or area light (points, area_light.hpp) shining through mirrors or glass onto diffuse
/// surfaces (L S+ D E) is a path no path tracer samples, so it renders black.
template <class SceneT> [[nodiscard]] std::string reference_blind_spot(const SceneT& scene) {
    bool point_light = false, specular = false, diffuse = false;
    for (const auto& light : scene.lights()) point_light = point_light || (!light_has_surface(light) && light_is_lit(light));
    for (std::uint32_t i = 0; i < scene.objects().size(); ++i) {
        specular = specular || scene.any_material_of(i, is_specular_material);
        diffuse = diffuse || scene.any_material_of(i, has_diffuse_material);
    }
    if (!point_light || !specular || !diffuse) return {};
    return "mode reference cannot see light from point and area lights through mirrors or glass onto diffuse "
           "surfaces (L S+ D E caustics): it renders them black; use sphere lights for a complete reference";
}

template <class SceneT> class PathTracer {
public:
    using S = typename SceneT::scalar_type;

    static constexpr unsigned max_vertices = 256;  ///< a backstop; Russian roulette ends paths first

    PathTracer(const SceneT& scene, const RenderSettings& settings) noexcept
        : scene_(scene), mis_(settings.reference_mis) {}

    [[nodiscard]] Rgb<S> radiance(Ray<S> ray, ShadingContext& ctx) const {
        Rgb<S> result(S(0)), throughput(S(1));
        Arrival arrival;
        for (unsigned vertex = 0; vertex < max_vertices; ++vertex) {
            const auto surface = scene_.intersect(ray);
            std::optional<Facing<S>> f_here;
            if (surface) f_here = facing(*surface->material, surface->hit.point, surface->hit.normal, ray.direction);
            if (arrival.kind == Arrival::unseen) {  // media on what the camera sees, as radiance() applies them
                if (const auto media = media_seen(scene_, ray, surface, f_here ? &*f_here : nullptr, ctx)) {
                    result += throughput * media->added;
                    throughput *= media->transmittance;
                }
            } else {  // after a diffuse vertex they only dim, as they dim gathers and photons
                throughput *= media_transmittance_seen(scene_, ray, surface, f_here ? &*f_here : nullptr, ctx.rng);
            }
            if (arrival.kind == Arrival::unseen)  // fog on what the camera sees, as radiance() applies it
                if (const auto fog = fog_seen(scene_, ray, surface, f_here ? &*f_here : nullptr)) {
                    result += throughput * fog->added;
                    throughput *= fog->transmittance;
                }
            if (arrival.kind != Arrival::unseen) result += throughput * lights_met(ray, surface, arrival, ctx);
            result += throughput * sky_met(ray, surface, arrival, ctx);
            if (!surface) break;
            const Material<S>& material = *surface->material;
            const Facing<S>& f = *f_here;
            throughput *= segment_transmittance(material, f, surface->hit.t);  // absorbed inside coloured glass
            const Vec3<S>& x = surface->hit.point;
            const S error = intersection_error(x, ray.origin);
            // Russian roulette's probability of the diffuse event (its pd), the BSDF strategy's
            // share of the direct light here.
            const Scattering<S> sc = material.scattering(x, f.shading_cos, f.entering);
            const S pd = material.has_diffuse() ? average(sc.diffuse) : S(0);
            // The camera sees x (through mirrors and glass at most): POV-Ray's ambient, highlights
            // and brilliance show here, and only here, as in radiance() and sppm's camera paths.
            const bool seen = arrival.kind == Arrival::unseen;
            if (seen) result += throughput * material.ambient_at(x);
            // What the camera sees of x is seen_gain times what x passes on (material.hpp).
            const S gain = seen ? material.seen_gain() : S(1);
            if (material.has_diffuse() || (seen && material.has_highlight()))  // a highlight needs no diffuse
                result += throughput * sample_lights(x, offset_origin(x, f.normal, error), f.shading, f.normal,
                                                     -ray.direction, material, sc.diffuse * gain, pd, seen, ctx);
            const PhotonScatter<S> s = russian_roulette(material, sc, f, ray.direction, ctx.rng, PathFlow::from_camera);
            if (s.event == ScatterEvent::absorbed) break;
            throughput *= s.weight * gain;
            // Brilliance makes the direct light here something no path samples: light sampling
            // alone counts it (weight 1), so the continuation gets no MIS share (density 0).
            if (s.event == ScatterEvent::diffuse)
                arrival = {Arrival::diffuse, x,
                           seen && material.has_brilliance() ? S(0) : pd * glm::dot(f.shading, s.direction) * inv_pi<S>,
                           f.shading};
            else if (arrival.kind != Arrival::unseen)
                arrival.kind = Arrival::specular;
            const Vec3<S> side = s.event == ScatterEvent::transmission ? -f.normal : f.normal;
            ray = Ray<S>{offset_origin(x, side, error), s.direction};
            if (s.event == ScatterEvent::diffuse) ++ctx.rays.gather; else if (s.event == ScatterEvent::transmission) ++ctx.rays.refraction; else ++ctx.rays.reflection;
        }
        return result;
    }

private:
    /// How the current ray was made, which decides what light it may collect.
    struct Arrival {
        enum Kind {
            unseen,    ///< from the camera through mirrors and glass only: lights are invisible
            diffuse,   ///< straight out of a diffuse vertex: weighted against its light sample
            specular,  ///< mirrors or glass after a diffuse vertex: a caustic path, weight 1
        } kind = unseen;
        Vec3<S> from{};    ///< the diffuse vertex (diffuse only)
        S bsdf_pdf = S(0);  ///< density of the ray's direction: pd cos(theta) / pi (diffuse only)
        Vec3<S> normal{};  ///< the diffuse vertex's shading normal (diffuse only)
    };

    /// One light sample per light at a diffuse vertex x (shadow rays from `shadow_origin`),
    /// reflected towards wo; n is the shading normal, geometric_n the geometric one (light from
    /// below the surface counts for nothing). The Lambertian part is weighted against the BSDF
    /// strategy, whose density is pd cos / pi. Where the camera sees x (`seen`), POV-Ray's
    /// highlights and brilliance apply (highlight.hpp), with weight 1, as no path samples them
    /// (they are direct light only, as in pm's direct_lighting, which this matches); elsewhere x
    /// is Lambertian, as gathers and photons see it.
    [[nodiscard]] Rgb<S> sample_lights(const Vec3<S>& x, const Vec3<S>& shadow_origin, const Vec3<S>& n,
                                       const Vec3<S>& geometric_n, const Vec3<S>& wo, const Material<S>& material,
                                       const Rgb<S>& albedo, S pd, bool seen, ShadingContext& ctx) const {
        Rgb<S> total(S(0));
        const Rgb<S> brdf = albedo * inv_pi<S>;
        const bool highlights = seen && material.has_highlight();
        const bool brilliance = seen && material.has_brilliance();
        const Rgb<S> surface_color = highlights && material.params().metallic > S(0) ? material.highlight_color_at(x) : Rgb<S>(S(1));
        const Rgb<S> highlight_weight = highlights ? material.highlight_weight_at(x) : Rgb<S>(S(0));
        for (const Light<S>& light : scene_.lights()) {
            const auto sample = sample_light(light, x, ctx.rng.uniform2<S>());
            if (!sample) continue;
            const S cos_theta = glm::dot(n, sample->direction);
            if (!(cos_theta > S(0)) || !(glm::dot(geometric_n, sample->direction) > S(0))) continue;
            if (light_casts_shadows(light)) {
                ++ctx.rays.shadow;
                if (scene_.occluded(Ray<S>{shadow_origin, sample->direction,
                                           shadow_ray_length(shadow_origin, sample->direction, sample->distance)}))
                    continue;
            }
            const S weight = sample->delta || !mis_ || brilliance ? S(1) : power_heuristic(sample->pdf, pd * cos_theta * inv_pi<S>);
            Rgb<S> f = brdf * ((brilliance ? diffuse_cosine(material, cos_theta) : cos_theta) * weight);
            if (highlights) f += highlight_weight * highlight(material, surface_color, n, wo, sample->direction);
            total += f * sample->radiance / sample->pdf *
                     shadow_ray_media(scene_, light, shadow_origin, sample->direction, sample->distance, ctx.rng);
        }
        if (scene_.has_environment_light() && material.has_diffuse())
            // Under brilliance the continuation gets no share (its density is set to 0): weight 1.
            total += sample_sky(*scene_.environment(), shadow_origin, n, geometric_n, brdf, brilliance ? S(0) : pd, ctx);
        return total;
    }

    /// One shadow ray to the sky, drawn as environment_lighting draws them, weighted against
    /// the diffuse continuation (density pd cos / pi). Lambertian, as environment_lighting.
    [[nodiscard]] Rgb<S> sample_sky(const Environment<S>& sky, const Vec3<S>& shadow_origin, const Vec3<S>& n,
                                    const Vec3<S>& geometric_n, const Rgb<S>& brdf, S pd, ShadingContext& ctx) const {
        const Vec2<S> u = ctx.rng.uniform2<S>();
        const bool by_cosine = sky.is_constant() || ctx.rng.uniform<S>() < S(0.5);
        const Vec3<S> d = by_cosine ? Frame<S>::from_normal(n).to_world(cosine_hemisphere(u)) : sky.sample(u).direction;
        const S cos_theta = glm::dot(n, d);
        if (!(cos_theta > S(0)) || !(glm::dot(geometric_n, d) > S(0))) return Rgb<S>(S(0));
        const S pdf = environment_direct_pdf(sky, n, d);
        if (!(pdf > S(0))) return Rgb<S>(S(0));
        ++ctx.rays.shadow;
        if (scene_.occluded(Ray<S>{shadow_origin, d})) return Rgb<S>(S(0));
        const S weight = mis_ ? power_heuristic(pdf, pd * cos_theta * inv_pi<S>) : S(1);
        return brdf * sky.radiance(d) * (cos_theta * weight / pdf);
    }

    /// The sky seen by `ray` when it leaves the scene (no `surface`), weighted for `arrival`:
    /// in full by camera and mirror rays and by caustic paths (one strategy), by the power
    /// heuristic after a diffuse vertex. A diffuse continuation that meets an object that casts
    /// no shadow sees the sky through it, as the shadow rays do.
    [[nodiscard]] Rgb<S> sky_met(const Ray<S>& ray, const std::optional<SurfaceHit<S>>& surface, const Arrival& arrival,
                                 ShadingContext& ctx) const {
        if (!scene_.has_environment_light()) return Rgb<S>(S(0));
        if (arrival.kind != Arrival::diffuse) return surface ? Rgb<S>(S(0)) : sky_seen(scene_, ray.direction);
        if (!mis_) return Rgb<S>(S(0));  // shadow rays alone cover it
        if (surface) {
            if (scene_.objects()[surface->object].options.casts_shadow) return Rgb<S>(S(0));
            ++ctx.rays.shadow;
            if (scene_.occluded(Ray<S>{ray.origin, ray.direction})) return Rgb<S>(S(0));
        }
        const Environment<S>& sky = *scene_.environment();
        const Vec3<S> d = glm::normalize(ray.direction);
        return sky.radiance(d) * power_heuristic(arrival.bsdf_pdf, environment_direct_pdf(sky, arrival.normal, d));
    }

    /// Emission of the sphere lights `ray` meets before its surface hit (lights are not objects:
    /// all of them on the ray count, as they would for shadow rays), weighted for `arrival`.
    [[nodiscard]] Rgb<S> lights_met(const Ray<S>& ray, const std::optional<SurfaceHit<S>>& surface,
                                    const Arrival& arrival, ShadingContext& ctx) const {
        if (arrival.kind == Arrival::diffuse && !mis_) return Rgb<S>(S(0));  // light sampling alone covers it
        const S t_hit = surface ? surface->hit.t : std::numeric_limits<S>::infinity();
        Rgb<S> found(S(0));
        for (const Light<S>& light : scene_.lights()) {
            const auto hit = intersect_light(light, ray);
            if (!hit || is_black(hit->radiance)) continue;
            if (arrival.kind == Arrival::specular) {
                if (hit->t < t_hit) found += hit->radiance;
                continue;
            }
            // Seen as the vertex's shadow ray would see it: through objects without shadows too.
            if (!(hit->t < t_hit) && light_casts_shadows(light)) {
                if (scene_.objects()[surface->object].options.casts_shadow) continue;
                ++ctx.rays.shadow;
                if (scene_.occluded(Ray<S>{ray.origin, ray.direction, hit->t})) continue;
            }
            found += hit->radiance * power_heuristic(arrival.bsdf_pdf, light_pdf(light, arrival.from, ray.direction));
        }
        return found;
    }

    const SceneT& scene_;
    bool mis_;
};

}  // namespace photon
