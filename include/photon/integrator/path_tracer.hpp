// SPDX-License-Identifier: MIT
#pragma once
// Reference solution: unbiased path tracing (Kajiya 1986) of the same light paths the photon
// mapper renders, to measure the photon mapper's error. Slow by design; not a rendering mode
// for pictures. At each diffuse vertex the lights are sampled by a shadow ray; a path continues
// by the same Russian roulette as photons. Lights stay invisible to camera and mirror rays (as
// in every other mode), but a path that reaches a sphere light through mirrors or glass after a
// diffuse vertex collects its radiance: that is how path tracing finds caustics (L S+ D E).

#include <limits>

#include "../geometry/offset.hpp"
#include "../material/scatter.hpp"
#include "direct_lighting.hpp"
#include "render_settings.hpp"

namespace photon {

template <class SceneT> class PathTracer {
public:
    using S = typename SceneT::scalar_type;

    static constexpr unsigned max_vertices = 256;  ///< a backstop; Russian roulette ends paths first

    PathTracer(const SceneT& scene, const RenderSettings& settings) noexcept : scene_(scene), settings_(settings) {}

    [[nodiscard]] Rgb<S> radiance(Ray<S> ray, ShadingContext& ctx) const {
        Rgb<S> result(S(0)), throughput(S(1));
        // Light met by a ray is counted only on a specular chain that follows a diffuse vertex:
        // a ray straight out of a diffuse vertex was already covered by that vertex's shadow ray.
        bool after_diffuse = false, specular_chain = false;
        for (unsigned vertex = 0; vertex < max_vertices; ++vertex) {
            const auto surface = scene_.intersect(ray);
            if (after_diffuse && specular_chain)
                result += throughput * light_radiance(ray, surface ? surface->hit.t : std::numeric_limits<S>::infinity());
            if (!surface) break;
            const Material<S>& material = *surface->material;
            const Facing<S> f = facing(surface->hit.normal, ray.direction);
            const S error = intersection_error(surface->hit.point, ray.origin);
            if (material.has_diffuse()) {
                const Vec3<S> above = offset_origin(surface->hit.point, f.normal, error);
                result += throughput * direct_lighting(scene_, surface->hit.point, above, f.normal, -ray.direction, material, 1, ctx);
            }
            const PhotonScatter<S> s = russian_roulette(material, f, ray.direction, ctx.rng);
            if (s.event == ScatterEvent::absorbed) break;
            throughput *= s.weight;
            if (s.event == ScatterEvent::diffuse) after_diffuse = true;
            specular_chain = s.event != ScatterEvent::diffuse;
            const Vec3<S> side = s.event == ScatterEvent::transmission ? -f.normal : f.normal;
            ray = Ray<S>{offset_origin(surface->hit.point, side, error), s.direction};
            if (s.event == ScatterEvent::diffuse) ++ctx.rays.gather; else if (s.event == ScatterEvent::transmission) ++ctx.rays.refraction; else ++ctx.rays.reflection;
        }
        return result;
    }

private:
    /// Radiance of the nearest sphere light the ray meets before distance t_hit (its emitted
    /// radiance, if the direction leaving the light is within its cone).
    [[nodiscard]] Rgb<S> light_radiance(const Ray<S>& ray, S t_hit) const {
        Rgb<S> found(S(0));
        S nearest = t_hit;
        for (const Light<S>& light : scene_.lights()) {
            const S r = light_radius(light);
            if (r == S(0)) continue;
            const Vec3<S> oc = ray.origin - light_center(light);
            const S b = glm::dot(oc, ray.direction);
            const Vec3<S> closest = oc - b * ray.direction;
            const S disc = r * r - glm::dot(closest, closest);
            if (disc < S(0)) continue;
            const S t = -b - std::sqrt(disc);
            if (!(t > S(0)) || !(t < nearest)) continue;
            const auto& cone = light_cone(light);
            if (cone && !cone->contains(-ray.direction)) continue;
            nearest = t;
            found = radiant_intensity(light) / (pi<S> * r * r);
        }
        return found;
    }

    const SceneT& scene_;
    const RenderSettings& settings_;
};

}  // namespace photon
