// SPDX-License-Identifier: MIT
#pragma once
// The two passes composed. Each step is a function of its own (photon tracing, map building,
// image rendering) so that programs can reorder or replace them; render() is the usual order.

#include <chrono>
#include <mutex>

#include "../film/film.hpp"
#include "../parallel/parallel_for.hpp"
#include "../plan/effects_plan.hpp"
#include "../scene/camera.hpp"
#include "../tracing/photon_tracer.hpp"
#include "image_pass.hpp"
#include "irradiance_cache_pass.hpp"
#include "memory_budget.hpp"
#include "path_tracer.hpp"
#include "pm_error.hpp"
#include "radiance.hpp"
#include "reference_render.hpp"
#include "sppm.hpp"

namespace photon {

struct RenderResult {
    Film film;
    RenderStats stats;
    /// sppm and reference: each pixel's estimated error |A - B| / 2 from the two half-images
    /// (film/error_estimate.hpp); pm: its error against a short sppm run (pm_error.hpp); empty
    /// when the render had no two halves, no estimate, or another mode.
    Film error_image;
};

/// Which paths the global map must hold for `settings`: direct and caustic photons only when
/// something reads them from it (final gathering, pm-direct). Caustics at the first diffuse hit
/// always come from the caustic map, which the global pass completes where the caustic pass
/// does not aim.
[[nodiscard]] inline PathKinds global_map_contents(const RenderSettings& s) noexcept {
    const bool gathering = s.mode == RenderMode::pm && s.final_gather_rays > 0;
    const bool all_light = s.mode == RenderMode::pm_direct;
    return {.direct = gathering || all_light, .caustic = gathering, .indirect = true};
}

[[nodiscard]] inline bool uses_irradiance_cache(const RenderSettings& s) noexcept {
    return s.mode == RenderMode::pm && s.final_gather_rays > 0 && s.irradiance_cache_error > 0.0f;
}

[[nodiscard]] inline bool uses_precomputed_irradiance(const RenderSettings& s) noexcept {
    return s.mode == RenderMode::pm && s.final_gather_rays > 0 && s.irradiance_stride > 0;
}

/// Irradiance at every `settings.irradiance_stride`-th photon of `photons` (in trace order, with
/// their surface normals), estimated from `global` as a camera ray would, thin-wall probes
/// included. Deterministic: sample i is computed from photon i * stride alone.
template <class SceneT>
[[nodiscard]] PrecomputedIrradiance precompute_irradiance(const SceneT& scene, const PhotonMap& global,
                                                          std::span<const Photon> photons,
                                                          std::span<const std::uint16_t> normals,
                                                          const RenderSettings& settings, RayCounts& rays) {
    using S = typename SceneT::scalar_type;
    const std::size_t stride = settings.irradiance_stride;
    std::vector<IrradianceSample> samples((photons.size() + stride - 1) / stride);
    const Vec3<S> scene_scale(scene.bounds().is_finite() ? scene.bounds().magnitude() : S(0));
    const EstimateSettings& es = settings.global_estimate;
    std::mutex report;
    std::size_t done = 0;
    constexpr std::size_t grain = 4096;
    parallel_for(samples.size(), grain, settings.threads, [&](std::size_t b, std::size_t e) {
        if (settings.cancel && settings.cancel->load(std::memory_order_relaxed)) return;
        if (!owns(settings.share, b / grain)) return;
        ShadingContext ctx;
        for (std::size_t i = b; i < e; ++i) {
            const Photon& p = photons[i * stride];
            const Vec3<S> n(decode_octahedral(normals[i * stride]));
            const Vec3<S> x = offset_origin(Vec3<S>(p.position), n, stored_point_error(Vec3<S>(p.position), scene_scale));
            Rgb<S> e_x;
            if (es.boundary_probes > 0) {
                const VisibleDisc disc = probe_visible_disc(scene, x, n, es.max_radius, es.boundary_probes, ctx);
                e_x = estimate_irradiance(global, x, n, es, ctx.scratch, &disc);
            } else {
                e_x = estimate_irradiance(global, x, n, es, ctx.scratch);
            }
            samples[i] = {p.position, Rgb<float>(e_x), normals[i * stride]};
        }
        if (settings.progress) {
            const std::lock_guard lock(report);
            done += e - b;
            settings.progress(RenderPhase::precompute,
                              double(done) / double(owned_count(settings.share, (samples.size() + grain - 1) / grain) * grain));
        }
        const std::lock_guard lock(report);
        rays += ctx.rays;
    });
    share_runs(settings.share, std::span(samples), grain, "precompute");
    return PrecomputedIrradiance(samples);
}

/// Pass 1: traces and balances the photon maps the mode needs and `plan` keeps (plan_effects():
/// a map the scene cannot show is not built, a light hidden from the image shoots no photons).
/// `rt` needs none. Caustics come from two maps: the caustic pass's photons (aimed at the
/// caustic targets), and the global pass's L S+ D photons from every direction the caustic pass
/// does not aim into, with the caustic pass's photons aimed at infinite mirror planes, kept
/// apart because they are spread like the global map's and are read with its estimate settings (unaimed_specular_objects() lists the mirrors and glass only they
/// serve, with a warning).
template <class SceneT>
[[nodiscard]] PhotonMaps build_photon_maps(const SceneT& scene, const EffectsPlan& plan, const RenderSettings& settings,
                                           RenderStats& stats) {
    PhotonMaps maps;
    if (!plan.planned) return maps;  // rt, reference and sppm build no photon maps here
    auto settle = [](std::optional<PhotonMap>& map, std::span<const Photon> photons, PhotonMapStats& st) {
        const auto start = std::chrono::steady_clock::now();
        map.emplace(photons);
        st.build_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        st.stored = map->size();
        st.memory_bytes = map->memory_bytes();
    };
    auto count = [](const TracedPhotons& traced, PhotonMapStats& st) {
        st.emitted = traced.emitted;
        st.rays = traced.rays;
        st.trace_seconds = traced.seconds;
    };
    auto report = [&](RenderPhase phase) -> std::function<void(double)> {
        if (!settings.progress) return {};
        return [&settings, phase](double f) { settings.progress(phase, f); };
    };
    auto cancelled = [&] { return settings.cancel && settings.cancel->load(std::memory_order_relaxed); };
    PhotonTracingSettings pass{.photons = settings.caustic_photons,
                               .max_depth = settings.max_photon_depth,
                               .sampler = settings.emission,
                               .seed = settings.seed,
                               .threads = settings.threads,
                               .progress = report(RenderPhase::caustic_photons),
                               .cancel = settings.cancel,
                               .share = settings.share};
    pass.light_emits = plan.light_emits();
    const bool caustics = plan.caustics.present && settings.effects.caustics != EffectSwitch::off;
    const auto aim = caustic_aim(scene, plan.hidden_caustic_objects);
    const bool caustic_pass = plan.caustic_pass;
    std::vector<Photon> caustic_photons, broad_caustics;  // broad: a mirror plane's
    if (caustic_pass) {
        TracedPhotons traced = trace_caustic_photons(scene, pass, aim);
        count(traced, stats.caustic);
        caustic_photons = std::move(traced.photons);
        broad_caustics = std::move(traced.unaimed_caustics);
        stats.caustic.from_mirror_planes = broad_caustics.size();
    }
    if (caustics)
        for (std::uint32_t id : unaimed_specular_objects(scene))
            stats.warnings.push_back({unaimed_caustics_warning, id});
    if (plan.global_pass && !cancelled()) {
        pass.photons = plan.global_photons;
        pass.light_shares = plan.global_light_shares;  // by visible power (the caustic pass aims instead)
        pass.progress = report(RenderPhase::global_photons);
        pass.store = plan.global_store;
        pass.keep_normals = plan.precomputed_irradiance;
        pass.collect_unaimed_caustics = plan.global_collects_caustics;
        TracedPhotons traced = trace_global_photons(scene, pass, caustic_pass ? aim : decltype(aim){});
        count(traced, stats.global);
        stats.caustic.from_global = traced.unaimed_caustics.size();
        broad_caustics.insert(broad_caustics.end(), traced.unaimed_caustics.begin(), traced.unaimed_caustics.end());
        settle(maps.global, traced.photons, stats.global);  // photons stay in trace order for the precomputation
        if (pass.keep_normals && !cancelled()) {
            derive_estimate_radii(maps, settings);  // the precomputation reads the global radius
            const auto start = std::chrono::steady_clock::now();
            maps.irradiance = precompute_irradiance(scene, *maps.global, traced.photons, traced.normals,
                                                    with_estimate_radii(settings, maps), stats.rays);
            stats.precompute_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        }
    }
    if (!caustic_photons.empty()) settle(maps.caustic, caustic_photons, stats.caustic);
    if (!broad_caustics.empty()) maps.unaimed_caustic.emplace(std::span<const Photon>(broad_caustics));
    if (maps.unaimed_caustic) {
        stats.caustic.stored += maps.unaimed_caustic->size();
        stats.caustic.memory_bytes += maps.unaimed_caustic->memory_bytes();
    }
    derive_estimate_radii(maps, settings);
    stats.global.radius = maps.global_radius;
    stats.caustic.radius = maps.caustic_radius;
    stats.global.radius_derived = settings.global_estimate.max_radius == 0.0f;
    stats.caustic.radius_derived = settings.caustic_estimate.max_radius == 0.0f;
    return maps;
}

/// Pass 1 under the plan for `scene` and `settings` without a camera (the inferences that need
/// one are not made).
template <class SceneT>
[[nodiscard]] PhotonMaps build_photon_maps(const SceneT& scene, const RenderSettings& settings, RenderStats& stats) {
    return build_photon_maps(scene, plan_effects(scene, std::nullopt, settings), settings, stats);
}

/// Both passes: photon maps for the mode, then the image, with statistics.
template <class SceneT>
[[nodiscard]] RenderResult render(const SceneT& scene, const Camera<typename SceneT::scalar_type>& camera,
                                  const RenderSettings& settings) {
    validate(settings);
    const auto start = std::chrono::steady_clock::now();
    RenderResult result;
    RenderStats& stats = result.stats;
    stats.width = settings.width;
    stats.height = settings.height;
    stats.threads = resolve_threads(settings.threads);
    stats.mode = to_string(settings.mode);
    auto count_every_rank = [&] {  // each rank counted the rays of its own share of the work
        stats.rays = sum_over_ranks(settings.share, stats.rays, "statistics");
        stats.estimates = sum_over_ranks(settings.share, stats.estimates, "statistics");
        stats.cache_regathered = sum_over_ranks(settings.share, stats.cache_regathered, "statistics");
        stats.pixel_samples = sum_over_ranks(settings.share, stats.pixel_samples, "statistics");
    };
    if (settings.mode == RenderMode::reference)
        if (std::string blind = reference_blind_spot(scene); !blind.empty()) stats.warnings.push_back({std::move(blind)});
    if (settings.mode == RenderMode::sppm || settings.mode == RenderMode::reference)
        check_memory(estimate_memory(settings, max_albedo(scene), requested_passes(settings)), double(settings.memory_limit));
    if (settings.mode == RenderMode::sppm) {  // passes of its own (integrator/sppm.hpp)
        result.film = render_sppm(scene, camera, settings, stats, {}, &result.error_image);
        count_every_rank();
        stats.total_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        return result;
    }
    if (settings.mode == RenderMode::reference) {  // no photon maps; rounds of its own (reference_render.hpp)
        result.film = render_reference(scene, camera, settings, stats, &result.error_image);
        count_every_rank();
        stats.total_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        return result;
    }
    // The photon map modes: photon maps, then the image, under the plan for these settings.
    auto render_once = [&](const RenderSettings& s, RenderStats& st) {
        const EffectsPlan plan = plan_effects(scene, camera, s);
        // The maps the plan builds, not those the settings ask for: a pass it drops allocates nothing.
        const PhotonPasses passes = plan.planned ? PhotonPasses{plan.global_photons, plan.caustic_photons, plan.precomputed_irradiance}
                                                 : requested_passes(s);
        check_memory(estimate_memory(s, max_albedo(scene), passes), double(s.memory_limit));
        st.plan = {plan.photons_not_shot, plan.photons_moved, plan.passes_skipped};
        // Pass 2 obeys the plan too: without final gathering, pm reads the global map (absent or
        // empty when the plan dropped indirect light) instead of gathering from it.
        RenderSettings obeyed = s;
        if (plan.planned && !plan.final_gather) obeyed.final_gather_rays = 0;
        PhotonMaps maps = build_photon_maps(scene, plan, s, st);
        if (s.cancel && s.cancel->load()) {
            st.partial = true;
            return Film(s.width, s.height);  // nothing rendered yet
        }
        if (plan.irradiance_cache)
            maps.irradiance_cache = build_irradiance_cache(scene, camera, maps, obeyed, st,
                                                           plan.planned ? plan.light_emits() : std::vector<bool>{});
        // A light the plan silenced sends nothing the camera sees: no shadow rays to it either.
        return render_image(scene, camera, maps, obeyed, st, plan.planned ? plan.light_emits() : std::vector<bool>{});
    };
    if (settings.mode == RenderMode::pm)  // with its error estimate and budgets (pm_error.hpp)
        result.film = render_pm_estimated(scene, camera, settings, stats, &result.error_image, render_once);
    else
        result.film = render_once(settings, stats);
    count_every_rank();
    stats.total_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return result;
}

}  // namespace photon

// extern declarations of render() and its passes for DefaultScene<float|double> under
// PHOTON_SEPARATE_COMPILATION (photon::compiled).
#include "render_instantiations.hpp"
