// SPDX-License-Identifier: MIT
#pragma once
// Pass 1: photon tracing (paper, sections 3.1 and 4). Photons leave the lights, bounce by Russian
// roulette and are stored at every diffuse hit. Two independent passes fill the two maps: the
// global pass emits over all directions; the caustic pass aims at mirrors and glass and keeps
// only L S+ D paths. The caustic pass covers only the directions it aims into, so the global
// pass hands its L S+ D photons from every other direction to the caustic map too: together
// they carry every caustic path once. Photon i of a pass draws from random stream i, and photons
// are gathered in fixed blocks kept in block order: the maps are bit-identical for any thread
// count.

#include <atomic>
#include <chrono>
#include <functional>
#include <mutex>
#include <cstdint>
#include <vector>

#include "../geometry/offset.hpp"
#include "../light/light.hpp"
#include "../material/scatter.hpp"
#include "../math/octahedral.hpp"
#include "../parallel/parallel_for.hpp"
#include "../parallel/work_share.hpp"
#include "../photonmap/photon.hpp"
#include "../scene/media_segment.hpp"
#include "caustic_targets.hpp"
#include "photon_hit.hpp"
#include "light_allocation.hpp"

namespace photon {

/// Which path kinds a pass stores (a set of PathKind).
struct PathKinds {
    bool direct = true, caustic = true, indirect = true;
    [[nodiscard]] bool contains(PathKind k) const noexcept {
        return k == PathKind::direct ? direct : (k == PathKind::caustic ? caustic : indirect);
    }
};

struct PhotonTracingSettings {
    std::size_t photons = 200'000;  ///< photons emitted by this pass (not stored)
    unsigned max_depth = 10;        ///< surface hits followed per photon path
    EmissionSampler sampler = EmissionSampler::direct;
    PathKinds store{};            ///< global pass: which paths it stores (caustic pass: only L S+ D)
    bool keep_normals = false;    ///< also return each stored photon's surface normal
    /// Global pass: also return the L S+ D photons the caustic pass does not cover
    /// (TracedPhotons::unaimed_caustics), whatever `store` says.
    bool collect_unaimed_caustics = false;
    /// Per light, whether it emits photons (photons_per_light); empty: every light does.
    std::vector<bool> light_emits{};
    /// Per light, its relative share of the photons (photons_per_light); empty: by power.
    std::vector<double> light_shares{};
    std::uint64_t seed = 1;
    unsigned threads = 0;         ///< 0: all hardware threads
    std::function<void(double)> progress{};  ///< fraction of photons emitted; serialised calls
    const std::atomic<bool>* cancel = nullptr;  ///< true: stop soon, the result is incomplete
    WorkShare* share = nullptr;  ///< ranks tracing the blocks between them (parallel/work_share.hpp)
};

/// Output of one pass.
struct TracedPhotons {
    std::vector<Photon> photons;
    std::vector<std::uint16_t> normals;  ///< octahedral, facing the photon's side; if keep_normals
    /// Global pass: L S+ D photons emitted outside the caustic pass's cones (collect_unaimed_caustics).
    std::vector<Photon> unaimed_caustics;
    std::size_t emitted = 0;             ///< photons emitted, the count their power was divided by
    std::uint64_t rays = 0;              ///< photon rays traced
    double seconds = 0;
    bool cancelled = false;              ///< stopped early by PhotonTracingSettings::cancel
};

namespace detail {

constexpr std::size_t photon_block = 1024;  ///< photons per work unit, fixed for determinism

struct PhotonBlock {
    std::vector<Photon> photons;
    std::vector<std::uint16_t> normals;
    std::vector<Photon> unaimed_caustics;
    std::uint64_t rays = 0;
};

/// Photon index -> (light, power per photon) from the per-light counts. With a sky of power
/// `environment_power` > 0 its photons come last (light index lights.size()), and its scale is
/// 1 / their count: each sky photon's own power comes from Environment::sample_photon.
template <Scalar S> struct EmissionPlan {
    std::vector<std::size_t> first;  // first photon index of each light
    std::vector<Rgb<S>> scale;       // power carried by each photon of a light, before any weighting
    std::size_t emitting = 0;        // photons given to lights: 0 when no light may emit

    template <class Lights>
    EmissionPlan(const Lights& lights, std::size_t count, const std::vector<bool>& emits = {},
                 const std::vector<double>& shares = {}, double environment_power = 0) {
        const auto counts = photons_per_light<S>(lights, count, emits, shares, environment_power);
        std::size_t at = 0;
        for (std::size_t l = 0; l < counts.size(); ++l) {
            first.push_back(at);
            const Rgb<S> power = l < lights.size() ? light_power(lights[l]) : Rgb<S>(S(1));
            scale.push_back(counts[l] ? power / S(counts[l]) : Rgb<S>(S(0)));
            at += counts[l];
        }
        emitting = at;
    }
    [[nodiscard]] std::size_t light_of(std::size_t photon) const noexcept {
        std::size_t l = 0;
        while (l + 1 < first.size() && first[l + 1] <= photon) ++l;
        return l;
    }
};

/// Whether any light has power to emit.
template <class Lights> [[nodiscard]] bool has_emitting_light(const Lights& lights) noexcept {
    for (const auto& l : lights)
        if (max_component(light_power(l)) > 0) return true;
    return false;
}

/// Runs `per_photon(index, rng, block)` for every photon in fixed blocks, in parallel, and
/// concatenates the blocks in order.
template <class PerPhoton>
TracedPhotons run_blocks(const PhotonTracingSettings& settings, std::uint64_t salt, PerPhoton&& per_photon) {
    const auto start = std::chrono::steady_clock::now();
    const std::size_t n = settings.photons;
    const std::size_t blocks = (n + photon_block - 1) / photon_block;
    std::vector<PhotonBlock> out(blocks);
    std::atomic<bool> cancelled{false};
    std::mutex report;
    std::size_t blocks_done = 0;
    parallel_for(blocks, 1, settings.threads, [&](std::size_t b0, std::size_t b1) {
        for (std::size_t b = b0; b < b1; ++b) {
            if (settings.cancel && settings.cancel->load(std::memory_order_relaxed)) {
                cancelled = true;
                return;
            }
            if (!owns(settings.share, b)) continue;
            const std::size_t end = std::min(n, (b + 1) * photon_block);
            for (std::size_t i = b * photon_block; i < end; ++i) {
                Pcg32 rng(settings.seed ^ salt, i);
                per_photon(i, rng, out[b]);
            }
            if (settings.progress) {
                const std::lock_guard lock(report);
                settings.progress(double(++blocks_done) / double(owned_count(settings.share, blocks)));
            }
        }
    });
    if (!single(settings.share)) {  // every rank's blocks, in block order on every rank
        std::vector<std::vector<Photon>> photons(blocks), unaimed(blocks);
        std::vector<std::vector<std::uint16_t>> normals(blocks);
        std::vector<std::vector<std::uint64_t>> rays(blocks);
        for (std::size_t b = 0; b < blocks; ++b)
            if (owns(settings.share, b)) {
                photons[b] = std::move(out[b].photons), normals[b] = std::move(out[b].normals);
                unaimed[b] = std::move(out[b].unaimed_caustics), rays[b] = {out[b].rays};
            }
        share_lists(settings.share, photons, "photons");
        share_lists(settings.share, normals, "photons");
        share_lists(settings.share, unaimed, "photons");
        share_lists(settings.share, rays, "photons");
        for (std::size_t b = 0; b < blocks; ++b) {
            out[b].photons = std::move(photons[b]), out[b].normals = std::move(normals[b]);
            out[b].unaimed_caustics = std::move(unaimed[b]), out[b].rays = rays[b].empty() ? 0 : rays[b][0];
        }
    }
    TracedPhotons result;
    result.cancelled = cancelled;
    std::size_t total = 0;
    for (const auto& b : out) total += b.photons.size();
    result.photons.reserve(total);
    if (settings.keep_normals) result.normals.reserve(total);
    for (auto& b : out) {
        result.photons.insert(result.photons.end(), b.photons.begin(), b.photons.end());
        result.normals.insert(result.normals.end(), b.normals.begin(), b.normals.end());
        result.unaimed_caustics.insert(result.unaimed_caustics.end(), b.unaimed_caustics.begin(),
                                       b.unaimed_caustics.end());
        result.rays += b.rays;
        std::vector<Photon>().swap(b.photons);
    }
    result.emitted = n;
    result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return result;
}

/// Follows one photon of `light` (null: of the sky) from `ray` with `power`, rescaled at its
/// first hit by the light's falloff (first_hit_scale; 1 for a physical light and the sky). `caustic_only` stops at the first diffuse event
/// and stores only after a specular bounce (L S+ D); otherwise paths are stored per `store`, and
/// when `unaimed` (the caustic pass cannot emit along this photon's first ray) its L S+ D hits
/// also go to block.unaimed_caustics.
template <class SceneT, Scalar S>
void trace_photon_path(const SceneT& scene, const Light<S>* light, Ray<S> ray, Rgb<S> power,
                       const PhotonTracingSettings& settings, bool caustic_only, bool unaimed, Pcg32& rng,
                       PhotonBlock& block) {
    bool specular_only = true;
    for (unsigned depth = 0; depth < settings.max_depth; ++depth) {
        const auto surface = photon_intersect(scene, ray, block.rays);
        ++block.rays;
        if (!surface) return;
        if (depth == 0 && light) power *= first_hit_scale(*light, surface->hit.point, ray.origin);
        const Material<S>& material = *surface->material;
        const Facing<S> f = facing(material, surface->hit.point, surface->hit.normal, ray.direction);
        // The transmittance is carried exactly (no roulette on it): absorbing glass is usually
        // pale, and a roulette would add noise to the tinted caustics for little gain.
        power *= segment_transmittance(material, f, surface->hit.t);
        power *= media_transmittance_seen(scene, ray, surface, &f, rng);  // dimmed by media, scattered light not carried
        if (caustic_only && depth == 0 && !material.is_specular()) return;
        if (material.has_diffuse()) {
            const PathKind kind = depth == 0 ? PathKind::direct : (specular_only ? PathKind::caustic : PathKind::indirect);
            const bool keep = caustic_only ? kind == PathKind::caustic : settings.store.contains(kind);
            // The direction slot holds -f.normal, the side the photon arrived on, not its
            // travel direction: the estimate's backfacing test compares it with the shading
            // normal, and on a curved shell a photon travelling nearly tangentially on the
            // inside has a travel direction that faces the outside's normal a few centimetres
            // away (a light inside a closed sphere lit its outside at 0.45 W/m^2/sr).
            // Under a normal field the stored power is the photon's share of the irradiance the
            // shading normal sees (shading_ratio), so density estimates need no direction.
            const Photon photon{Vec3<float>(surface->hit.point),
                                PackedPhoton(Rgb<float>(power * shading_ratio(f)), Vec3<float>(-f.normal), kind)};
            if (keep) {
                block.photons.push_back(photon);
                if (settings.keep_normals) block.normals.push_back(encode_octahedral(Vec3<float>(f.normal)));
            }
            if (unaimed && kind == PathKind::caustic) block.unaimed_caustics.push_back(photon);
        }
        const PhotonScatter<S> s = russian_roulette(material, surface->hit.point, f, ray.direction, rng);
        if (s.event == ScatterEvent::absorbed) return;
        if (s.event == ScatterEvent::diffuse) {
            if (caustic_only) return;
            specular_only = false;
        }
        power *= s.weight;
        const Vec3<S> side = s.event == ScatterEvent::transmission ? -f.normal : f.normal;
        const S error = intersection_error(surface->hit.point, ray.origin);
        ray = Ray<S>{offset_origin(surface->hit.point, side, error), s.direction};
    }
}

}  // namespace detail

/// Global pass: `settings.photons` photons shared among the lights (and the sky) by power,
/// emitted uniformly over each light's directions (the sky's by Environment::sample_photon), stored at diffuse hits whose path kind is in `settings.store`.
/// With `settings.collect_unaimed_caustics`, the L S+ D photons emitted outside `aim` (the caustic
/// pass's cones; empty: there is no caustic pass) are returned in `unaimed_caustics` as well.
template <class SceneT>
[[nodiscard]] TracedPhotons trace_global_photons(const SceneT& scene, const PhotonTracingSettings& settings,
                                                 const CausticAim<typename SceneT::scalar_type>& aim = {}) {
    using S = typename SceneT::scalar_type;
    const auto lights = scene.lights();
    // The sky emits through the ball around the objects (none: no photon can hit one).
    const Ball<S> ball = scene.environment_ball();
    const bool sky = scene.has_environment_light() && ball.radius > S(0);
    const double sky_power = sky ? double(scene.environment()->power_into(ball)) : 0.0;
    // No light, or none with power: nothing to emit. (Emitting anyway traced photons of zero
    // power, and without lights read lights[0] out of range.)
    if (!detail::has_emitting_light(lights) && !(sky_power > 0)) return {};
    const detail::EmissionPlan<S> plan(lights, settings.photons, settings.light_emits, settings.light_shares, sky_power);
    if (plan.emitting == 0) return {};
    return detail::run_blocks(settings, 0x676c6f62616cULL, [&](std::size_t i, Pcg32& rng, detail::PhotonBlock& block) {
        const std::size_t l = plan.light_of(i);
        if (l == lights.size()) {  // the sky's: never aimed by the caustic pass, so its caustics are unaimed
            const Vec2<S> u_direction = rng.uniform2<S>();
            const EnvironmentPhoton<S> p = scene.environment()->sample_photon(ball, u_direction, rng.uniform2<S>());
            detail::trace_photon_path(scene, static_cast<const Light<S>*>(nullptr), p.ray, plan.scale[l] * p.power,
                                      settings, false, settings.collect_unaimed_caustics, rng, block);
            return;
        }
        const Light<S>& light = lights[l];
        const Vec3<S> dir = sample_emission_direction(light, settings.sampler, rng);
        const Vec3<S> origin = leaving_light(sample_emission_origin(light, dir, rng.uniform2<S>()), dir);
        const bool unaimed = settings.collect_unaimed_caustics && !aim.covers(l, dir);
        detail::trace_photon_path(scene, &light, Ray<S>{origin, dir}, plan.scale[l] * emission_weight(light, dir), settings,
                                  false, unaimed, rng, block);
    });
}

/// Whether the scene can form caustics at all: a mirror or glass surface, a diffuse one for the
/// light to land on, and a light with power.
template <class SceneT> [[nodiscard]] bool scene_has_caustics(const SceneT& scene) {
    bool specular = false, diffuse = false;
    for (std::uint32_t i = 0; i < scene.objects().size(); ++i) {
        specular = specular || scene.any_material_of(i, is_specular_material);
        diffuse = diffuse || scene.any_material_of(i, has_diffuse_material);
    }
    return specular && diffuse && detail::has_emitting_light(scene.lights());
}

/// Caustic pass: photons aimed into `aim`'s cones (the caustic targets' bounding balls), stored
/// only at the end of L S+ D paths; those aimed at an infinite mirror plane come back in
/// `unaimed_caustics` (spread like the global map's, they are read with its settings). Empty (and free) when the scene has no caustics or nothing
/// to aim at.
template <class SceneT>
[[nodiscard]] TracedPhotons trace_caustic_photons(const SceneT& scene, const PhotonTracingSettings& settings,
                                                  const CausticAim<typename SceneT::scalar_type>& aim) {
    using S = typename SceneT::scalar_type;
    if (aim.empty() || !scene_has_caustics(scene)) return {};
    const auto lights = scene.lights();
    // A light with nothing to aim at (its cone reaches no target) shoots no caustic photon.
    const detail::EmissionPlan<S> plan(lights, settings.photons, aim.aiming_lights(lights.size(), settings.light_emits));
    if (plan.emitting == 0) return {};
    return detail::run_blocks(settings, 0x636175737469ULL, [&](std::size_t i, Pcg32& rng, detail::PhotonBlock& block) {
        const std::size_t l = plan.light_of(i);
        const Light<S>& light = lights[l];
        const auto sample = sample_cone_mixture(aim.cones[l], aim.total_solid_angle[l], rng);
        const S profile = intensity_profile(light, sample.direction);
        if (!(profile > S(0))) return;
        // The photon carries I / (pdf * n): intensity along its direction over the density it was
        // drawn with, where plan.scale = power / n and I = profile * power / emission solid angle.
        const Rgb<S> power = plan.scale[l] * (profile / (emission_solid_angle(light) * sample.pdf));
        const Vec3<S> origin =
            leaving_light(sample_emission_origin(light, sample.direction, rng.uniform2<S>()), sample.direction);
        const std::size_t before = block.photons.size();
        detail::trace_photon_path(scene, &light, Ray<S>{origin, sample.direction}, power, settings, true, false, rng, block);
        if (sample.broad) {  // a mirror plane's: kept apart, read like the global map
            block.unaimed_caustics.insert(block.unaimed_caustics.end(), block.photons.begin() + std::ptrdiff_t(before),
                                          block.photons.end());
            block.photons.resize(before);
        }
    });
}

/// Caustic pass aimed at the scene's own caustic targets.
template <class SceneT>
[[nodiscard]] TracedPhotons trace_caustic_photons(const SceneT& scene, const PhotonTracingSettings& settings) {
    return trace_caustic_photons(scene, settings, caustic_aim(scene));
}

}  // namespace photon
