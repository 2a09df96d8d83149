// SPDX-License-Identifier: MIT
#pragma once
// What participating media (material/medium.hpp, on the segments scene/media_segment.hpp picks) do
// in each pass.
//
// Camera, mirror and glass rays (the paths until their first diffuse vertex) see everything:
// transmittance, emission and single scattering of every light (media_seen). Light reaching a
// sample point is traced as POV-Ray traces its shadow rays: through transmissive surfaces,
// tinted by their transmission, and dimmed by the interior media it crosses; atmospheric media
// do not dim it (POV-Ray's default without a light's `media_attenuation`). The sky lights no
// medium (POV-Ray scatters only light sources). Photons, gathers and the path tracer's
// continuations after a diffuse vertex are only attenuated (media_transmittance_seen), so light
// that reaches a diffuse surface through a murky volume is dimmed in every mode; light the media
// scatter on to surfaces (multiple scattering, POV-Ray's media photons) is not rendered.

#include <algorithm>
#include <optional>
#include <span>
#include <type_traits>
#include <variant>
#include <vector>

#include "../geometry/offset.hpp"
#include "../light/light.hpp"
#include "../material/scatter.hpp"
#include "../scene/media_segment.hpp"
#include "media_march.hpp"
#include "shading_context.hpp"

namespace photon {

/// The fraction of light that travels from `x` along unit `to_light` for `distance` as POV-Ray's
/// shadow rays see it: 0 at an opaque surface that casts shadows, times the transmission of each
/// transmissive one, times the interior media (and absorption) of the objects it leaves, and,
/// with `atmosphere` (the light's media_attenuation), times the atmospheric media outside them.
template <class SceneT, Scalar S>
[[nodiscard]] Rgb<S> media_light_transmittance(const SceneT& scene, Vec3<S> x, const Vec3<S>& to_light, S distance,
                                               bool atmosphere, ShadingContext& ctx) {
    Rgb<S> t(S(1));
    for (int crossing = 0; crossing < 32 && distance > S(0); ++crossing) {
        ++ctx.rays.shadow;
        const auto hit = scene.intersect(Ray<S>{x, to_light, distance});
        if (!hit) return atmosphere ? t * media_transmittance(scene.media(), x, to_light, distance, ctx.rng) : t;
        const Material<S>& material = *hit->material;
        const Facing<S> f = facing(material, hit->hit.point, hit->hit.normal, to_light);
        const bool blocks = scene.objects()[hit->object].options.casts_shadow;
        if (blocks && is_black(material.params().transmission)) return Rgb<S>(S(0));
        if (blocks) t *= material.params().transmission;
        if (!f.entering) {
            t *= segment_transmittance(material, f, hit->hit.t);
            t *= media_transmittance(std::span<const Medium<S>>(material.params().media), x, to_light, hit->hit.t, ctx.rng);
        } else if (atmosphere) {
            t *= media_transmittance(scene.media(), x, to_light, hit->hit.t, ctx.rng);
        }
        if (is_black(t)) return t;
        const S error = intersection_error(hit->hit.point, x);
        x = offset_origin(hit->hit.point, -f.normal, error);
        distance -= hit->hit.t;
    }
    return t;
}

/// Where along the segment from `origin` along unit `direction` (length `length`) a point's
/// direction from `apex` lies within the cone about unit `axis` of half-angle cosine `cos_half`
/// (POV-Ray's ComputeSpotLightInterval). A cone of half-angle below 90 degrees is convex, so the
/// points inside form one interval: found between the roots of the quadratic that bounds it.
template <Scalar S>
[[nodiscard]] LitSpan<S> cone_span(const Vec3<S>& apex, const Vec3<S>& axis, S cos_half, const Vec3<S>& origin,
                                   const Vec3<S>& direction, S length) noexcept {
    if (!(cos_half > S(0))) return {S(0), length};
    const Vec3<double> v = Vec3<double>(origin - apex), d(direction), a(axis);
    const double c2 = double(cos_half) * double(cos_half);
    const double da = glm::dot(d, a), va = glm::dot(v, a);
    const double qa = da * da - c2, qb = 2 * (va * da - c2 * glm::dot(v, d)), qc = va * va - c2 * glm::dot(v, v);
    double cuts[4] = {0.0, double(length), 0.0, 0.0};
    int n = 2;
    if (std::abs(qa) > 1e-12) {
        const double disc = qb * qb - 4 * qa * qc;
        if (disc >= 0) {
            const double r = std::sqrt(disc);
            for (const double t : {(-qb - r) / (2 * qa), (-qb + r) / (2 * qa)})
                if (t > 0 && t < double(length)) cuts[n++] = t;
        }
    } else if (std::abs(qb) > 1e-30) {
        const double t = -qc / qb;
        if (t > 0 && t < double(length)) cuts[n++] = t;
    }
    std::sort(cuts, cuts + n);
    LitSpan<S> span;
    for (int i = 0; i + 1 < n; ++i) {
        const Vec3<double> w = v + d * (0.5 * (cuts[i] + cuts[i + 1]));
        if (glm::dot(w, a) < double(cos_half) * glm::length(w)) continue;
        if (span.empty()) span.start = S(cuts[i]);
        span.end = S(cuts[i + 1]);
    }
    return span;
}

/// Where each light of the scene reaches the segment: a point light's cone where it has one,
/// else all of it; nowhere for a light without media_interaction.
template <class SceneT, Scalar S>
[[nodiscard]] std::vector<LitSpan<S>> lit_spans(const SceneT& scene, const Vec3<S>& origin, const Vec3<S>& direction,
                                                S length) {
    std::vector<LitSpan<S>> spans;
    for (const Light<S>& light : scene.lights()) {
        if (!light_media_interaction(light) || !light_is_lit(light)) {
            spans.push_back({});
            continue;
        }
        const auto& cone = light_cone(light);
        if (cone && std::holds_alternative<PointLight<S>>(light))
            spans.push_back(cone_span(light_center(light), cone->axis(), cone->cos_half_angle(), origin, direction, length));
        else
            spans.push_back({S(0), length});
    }
    return spans;
}

/// What the media do to a camera, mirror or glass ray's segment that ends at `surface` (seen from
/// side `f`; none: the ray left the scene): nullopt where there are none.
template <class SceneT, Scalar S, class SurfaceT>
[[nodiscard]] std::optional<MediaEffect<S>> media_seen(const SceneT& scene, const Ray<S>& ray,
                                                       const std::optional<SurfaceT>& surface,
                                                       std::type_identity_t<const Facing<S>*> f, ShadingContext& ctx) {
    if constexpr (!requires { scene.media(); }) {
        return std::nullopt;
    } else {
        const std::span<const Medium<S>> media = media_on_segment<SceneT, S>(scene, surface, f);
        if (media.empty()) return std::nullopt;
        const Vec3<S> direction = glm::normalize(ray.direction);
        const S length = media_segment_length(ray, surface);
        const bool scatters = std::any_of(media.begin(), media.end(), [](const Medium<S>& m) { return m.scatters(); });
        const std::vector<LitSpan<S>> spans = scatters ? lit_spans(scene, ray.origin, direction, length)
                                                       : std::vector<LitSpan<S>>{};
        const auto lights_at = [&](const Vec3<S>& x, S t, auto&& visit) {
            const auto lights = scene.lights();
            for (std::size_t l = 0; l < lights.size(); ++l) {
                if (!spans[l].contains(t)) continue;
                const Light<S>& light = lights[l];
                const IncidentSampler<S> sampler(light, x);
                const auto incident = sampler.sample(sampler.is_area() ? ctx.rng.uniform2<S>() : Vec2<S>(S(0.5)));
                if (!incident || is_black(incident->irradiance)) continue;
                Rgb<S> arriving = incident->irradiance;
                if (light_casts_shadows(light))
                    arriving *= media_light_transmittance(scene, x, incident->direction, incident->distance,
                                                          light_media_attenuation(light), ctx);
                if (!is_black(arriving)) visit(incident->direction, arriving);
            }
        };
        return march_media(media, ray.origin, direction, length, std::span<const LitSpan<S>>(spans), ctx.rng, lights_at);
    }
}

/// What the scene's atmospheric media leave of `light` along an unoccluded shadow ray from a
/// surface (1 unless the light has media_attenuation, POV-Ray's ComputeShadowMedia).
template <class SceneT, Scalar S>
[[nodiscard]] Rgb<S> shadow_ray_media(const SceneT& scene, const Light<S>& light, const Vec3<S>& origin,
                                      const Vec3<S>& to_light, S distance, Pcg32& rng) {
    if constexpr (requires { scene.media(); }) {
        if (!light_media_attenuation(light) || scene.media().empty()) return Rgb<S>(S(1));
        return media_transmittance(scene.media(), origin, to_light, distance, rng);
    } else {
        return Rgb<S>(S(1));
    }
}

}  // namespace photon
