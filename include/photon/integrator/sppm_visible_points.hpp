// SPDX-License-Identifier: MIT
#pragma once
// The camera side of stochastic progressive photon mapping (Hachisuka and Jensen 2009): per
// pass, one camera ray per pixel, followed through mirrors and glass to ONE diffuse "visible
// point" that gathers the pass's photons (sppm.hpp). Where a path could split (Fresnel
// reflection and refraction, a diffuse surface that is also a mirror), one branch is chosen with
// probability proportional to its channel-averaged reflectance and the weight divided by that
// probability, so every pass costs one path per pixel and the image stays unbiased in
// expectation. Direct light is taken by shadow rays at every diffuse vertex on the way (as pm
// does): deterministic, so it is not left to the choice. Fog fades every segment of the path,
// as it fades radiance()'s camera, mirror and glass rays; so do participating media (media_seen.hpp).

#include <bit>
#include <cstdint>
#include <optional>

#include "../geometry/offset.hpp"
#include "../material/scatter.hpp"
#include "../scene/camera.hpp"
#include "direct_lighting.hpp"
#include "fog_seen.hpp"
#include "media_seen.hpp"
#include "../settings/render_settings.hpp"

namespace photon {

/// Where a camera path of one pass ends: a diffuse point that collects photons.
template <Scalar S> struct VisiblePoint {
    Vec3<S> position;   ///< on the surface (not offset)
    Vec3<S> normal;     ///< unit, on the side the path arrived from
    Rgb<S> weight;      ///< path throughput * diffuse BRDF / probability of ending here
    S path_length;      ///< camera to here along the path (for the automatic radius)
};

/// One pass's camera path: its visible point (none if it left the scene or was absorbed) and the
/// direct light its diffuse vertices reflect towards the camera.
template <Scalar S> struct CameraPath {
    std::optional<VisiblePoint<S>> point;
    Rgb<S> direct{S(0)};
};

/// Sample `pass` of a (0,2)-sequence in [0,1)^2 (van der Corput and Sobol's second dimension,
/// Kollig and Keller 2002), XOR-scrambled per pixel: the first 2^m passes of every pixel are
/// stratified in each of its 2^m elementary intervals, and pixels do not share their pattern.
[[nodiscard]] inline Vec2<double> progressive_pixel_sample(std::uint32_t pass, std::uint32_t scramble_x,
                                                            std::uint32_t scramble_y) noexcept {
    std::uint32_t reversed = pass;
    reversed = (reversed << 16) | (reversed >> 16);
    reversed = ((reversed & 0x00ff00ffu) << 8) | ((reversed & 0xff00ff00u) >> 8);
    reversed = ((reversed & 0x0f0f0f0fu) << 4) | ((reversed & 0xf0f0f0f0u) >> 4);
    reversed = ((reversed & 0x33333333u) << 2) | ((reversed & 0xccccccccu) >> 2);
    reversed = ((reversed & 0x55555555u) << 1) | ((reversed & 0xaaaaaaaau) >> 1);
    std::uint32_t sobol = scramble_y;
    for (std::uint32_t v = 1u << 31, i = pass; i != 0; i >>= 1, v ^= v >> 1)
        if (i & 1u) sobol ^= v;
    return {double(reversed ^ scramble_x) * 0x1p-32, double(sobol) * 0x1p-32};
}

/// Follows the camera ray `ray` through mirrors and glass (up to settings.max_ray_depth, primary
/// ray = 1) to its visible point, adding the direct light (and the ambient radiance) of every
/// vertex on the way.
/// Lights stay invisible to the path, as to camera and mirror rays in every mode; the sky is
/// seen where the path leaves the scene.
template <class SceneT>
[[nodiscard]] CameraPath<typename SceneT::scalar_type> trace_camera_path(const SceneT& scene,
                                                                         Ray<typename SceneT::scalar_type> ray,
                                                                         const RenderSettings& settings,
                                                                         ShadingContext& ctx) {
    using S = typename SceneT::scalar_type;
    CameraPath<S> path;
    Rgb<S> throughput(S(1));
    S length = 0;
    for (unsigned depth = 1;; ++depth) {
        const auto surface = scene.intersect(ray);
        if (!surface) {  // left the scene: the sky, as radiance() sees it
            Rgb<S> sky = sky_seen(scene, ray.direction);
            if (const auto media = media_seen(scene, ray, surface, nullptr, ctx)) sky = media->apply(sky);
            const auto fog = fog_seen(scene, ray, surface, nullptr);
            path.direct += throughput * (fog ? fog->apply(sky) : sky);
            return path;
        }
        length += surface->hit.t;
        const Material<S>& material = *surface->material;
        const Facing<S> f = facing(material, surface->hit.point, surface->hit.normal, ray.direction);
        throughput *= segment_transmittance(material, f, surface->hit.t);  // absorbed inside coloured glass
        if (const auto media = media_seen(scene, ray, surface, &f, ctx)) {  // glow and light scattered, then dimming
            path.direct += throughput * media->added;
            throughput *= media->transmittance;
        }
        if (const auto fog = fog_seen(scene, ray, surface, &f)) {  // the fog's colour, then what shows through it
            path.direct += throughput * fog->added;
            throughput *= fog->transmittance;
        }
        const Vec3<S>& x = surface->hit.point;
        const S error = intersection_error(x, ray.origin);
        path.direct += throughput * material.ambient_at(x);  // as radiance() adds it: seen, lighting nothing
        const S gain = material.seen_gain();  // the surface as written, where it reflects over 1 (material.hpp)
        if (material.has_diffuse() || material.has_highlight()) {  // as radiance(): a highlight needs no diffuse
            const Vec3<S> above = offset_origin(x, f.normal, error);
            // The sky by as many shadow rays per pass as an area light: passes average them.
            path.direct += throughput * direct_lighting(scene, x, above, f.shading, f.normal, -ray.direction, material,
                                                        material.diffuse_at(x) * gain, settings.shadow_samples, ctx,
                                                        {.sky_samples = settings.shadow_samples});
        }
        const bool continues = depth < settings.max_ray_depth && material.is_specular();
        const Scattering<S> sc = material.scattering(x, f.shading_cos, f.entering);
        const S pd = material.has_diffuse() ? average(sc.diffuse) : S(0);
        const S ps = continues ? average(sc.specular) : S(0);
        const S pt = continues ? average(sc.transmission) : S(0);
        const S total = pd + ps + pt;
        if (!(total > S(0))) return path;
        const S psi = ctx.rng.uniform<S>() * total;
        if (psi < pd) {
            path.point = VisiblePoint<S>{x, f.normal, throughput * sc.diffuse * (gain * inv_pi<S> * total / pd), length};
            return path;
        }
        if (psi < pd + ps || pt == S(0)) {
            throughput *= sc.specular * (gain * total / ps);
            ++ctx.rays.reflection;
            ray = Ray<S>{offset_origin(x, f.normal, error), mirror_direction(ray.direction, f)};
            continue;
        }
        throughput *= sc.transmission * (gain * total / pt);
        if (const auto refracted = refraction_direction(ray.direction, f, relative_eta(material, f.entering))) {
            ++ctx.rays.refraction;
            ray = Ray<S>{offset_origin(x, -f.normal, error), *refracted};
        } else {  // total internal reflection: the transmitted share is reflected, as radiance() does
            ++ctx.rays.reflection;
            ray = Ray<S>{offset_origin(x, f.normal, error), mirror_direction(ray.direction, f)};
        }
    }
}

}  // namespace photon
