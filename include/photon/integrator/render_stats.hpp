// SPDX-License-Identifier: MIT
#pragma once
// What a render did: the columns of the paper's Tables 1 and 2 and more.

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <optional>
#include <string>
#include <vector>

#include "../film/error_estimate.hpp"

namespace photon {

/// Rays traced in pass 2, by purpose.
struct RayCounts {
    std::uint64_t camera = 0, shadow = 0, reflection = 0, refraction = 0, gather = 0, probe = 0;
    /// Not rays: (shading point, area light) pairs given no shadow ray, since a wall lies across
    /// every ray between them (separating_wall.hpp).
    std::uint64_t walled_lights = 0;

    [[nodiscard]] std::uint64_t total() const noexcept { return camera + shadow + reflection + refraction + gather + probe; }
    RayCounts& operator+=(const RayCounts& o) noexcept {
        camera += o.camera, shadow += o.shadow, reflection += o.reflection;
        refraction += o.refraction, gather += o.gather, probe += o.probe;
        walled_lights += o.walled_lights;
        return *this;
    }
};

struct PhotonMapStats {
    std::uint64_t emitted = 0;  ///< photons shot
    std::uint64_t stored = 0;   ///< photons in the map
    /// Caustics: of the stored photons, the global pass's L S+ D photons from directions the
    /// caustic pass does not aim into (a map of their own, PhotonMaps::unaimed_caustic)
    std::uint64_t from_global = 0;
    /// Caustics: of the stored photons, the caustic pass's aimed at infinite mirror planes, kept
    /// with the global pass's in the same map (their light spreads like the global map's)
    std::uint64_t from_mirror_planes = 0;
    std::uint64_t rays = 0;     ///< photon rays traced
    std::uint64_t memory_bytes = 0;
    double trace_seconds = 0, build_seconds = 0;
    float radius = 0;             ///< the estimates' max radius (0: no map)
    bool radius_derived = false;  ///< derived from the photon density, not set by the settings
};

/// Something a render approximated or could not do well, for the user to read.
struct RenderWarning {
    std::string message;
    std::optional<std::uint32_t> object{};  ///< the scene object it is about, if any
};

/// What a stochastic progressive photon mapping render did (integrator/sppm.hpp).
struct SppmStats {
    unsigned passes = 0;              ///< passes completed
    std::uint64_t emitted = 0;        ///< photons emitted over all passes
    std::uint64_t photon_hits = 0;    ///< diffuse photon hits (after the first bounce) over all passes
    std::uint64_t photon_rays = 0;    ///< photon rays traced over all passes
    double mean_radius = 0;           ///< gathering radius at the end, averaged over pixels that have one
    double photon_seconds = 0, gather_seconds = 0;  ///< photon tracing and tree building; camera pass and gathering
};

/// Pass 2's camera samples per pixel (rt, pm, pm-direct): adaptive anti-aliasing spends more of
/// them where a pixel is noisy.
struct PixelSampleStats {
    std::uint64_t pixels = 0;   ///< pixels rendered
    std::uint64_t samples = 0;  ///< camera samples over them
    unsigned most = 0;          ///< the most one pixel took

    [[nodiscard]] double mean() const noexcept { return pixels > 0 ? double(samples) / double(pixels) : 0.0; }
    /// Merges another thread's or rank's pixels (so sum_over_ranks merges the ranks').
    PixelSampleStats& operator+=(const PixelSampleStats& o) noexcept {
        pixels += o.pixels, samples += o.samples;
        most = std::max(most, o.most);
        return *this;
    }
};

/// What the light-path plan saved against the settings (plan/effects_plan.hpp).
struct PlanSavings {
    std::uint64_t photons_not_shot = 0;  ///< asked for by the settings, not emitted
    std::uint64_t photons_moved = 0;     ///< global photons given to other lights than power alone would (EffectsPlan)
    std::vector<std::string> passes_skipped;
};

struct RenderStats {
    unsigned width = 0, height = 0, threads = 0;
    std::string mode;
    PhotonMapStats global, caustic;
    SppmStats sppm;
    RayCounts rays;
    std::uint64_t estimates = 0;  ///< photon map density estimates
    PixelSampleStats pixel_samples;
    std::uint64_t cache_records = 0;  ///< final gathers in the irradiance cache
    std::uint64_t cache_regathered = 0;  ///< of them, gathered again for being noisy (cache_gather_noise)
    double precompute_seconds = 0, cache_seconds = 0, render_seconds = 0, total_seconds = 0;
    bool partial = false;  ///< cancelled before every pixel was rendered
    /// What the user should know about this render's result (light the mode cannot see, objects
    /// it serves less well), one sentence each; the CLI prints them as "photon: warning: ...".
    std::vector<RenderWarning> warnings;
    PlanSavings plan;
    /// sppm and reference: the image's estimated error, from two independent half-images; pm:
    /// against a short sppm run (integrator/pm_error.hpp), whose passes are in `sppm`.
    ErrorEstimate error;
    /// pm: renders done (more than one under a budget) and the last one's global photons and
    /// final gather rays.
    unsigned pm_steps = 0;
    std::uint64_t pm_global_photons = 0;
    unsigned pm_gather_rays = 0;
    /// Why a progressive render (or pm under a budget) stopped: "passes done", "time limit", "target
    /// error", "cancelled"; pm also "photon limit", "memory limit", "estimate stalled ...".
    std::string stopped_by;
};

/// The statistics as an aligned plain-text table.
[[nodiscard]] inline std::string format_stats(const RenderStats& s) {
    std::string out;
    char line[160];
    auto row = [&](const char* name, const char* fmt, auto... v) {
        std::snprintf(line, sizeof line, "  %-28s", name);
        out += line;
        std::snprintf(line, sizeof line, fmt, v...);
        out += line;
        out += '\n';
    };
    auto mib = [](std::uint64_t b) { return double(b) / (1024.0 * 1024.0); };
    row("image", "%u x %u, mode %s, %u threads%s", s.width, s.height, s.mode.c_str(), s.threads,
        s.partial ? " (PARTIAL)" : "");
    row("global map", "%llu emitted, %llu stored, %.1f MiB, trace %.2f s, build %.2f s",
        (unsigned long long)s.global.emitted, (unsigned long long)s.global.stored, mib(s.global.memory_bytes),
        s.global.trace_seconds, s.global.build_seconds);
    row("caustic map", "%llu emitted, %llu stored (%llu from the global pass, %llu aimed at mirror planes), %.1f MiB, trace %.2f s, build %.2f s",
        (unsigned long long)s.caustic.emitted, (unsigned long long)s.caustic.stored,
        (unsigned long long)s.caustic.from_global, (unsigned long long)s.caustic.from_mirror_planes, mib(s.caustic.memory_bytes), s.caustic.trace_seconds,
        s.caustic.build_seconds);
    if (s.global.radius > 0 || s.caustic.radius > 0) {
        auto radius = [](const PhotonMapStats& m) {
            char text[64];
            if (m.radius > 0)
                std::snprintf(text, sizeof text, "%.4g%s", double(m.radius), m.radius_derived ? " (from the photon density)" : "");
            else
                std::snprintf(text, sizeof text, "none (no map)");
            return std::string(text);
        };
        row("estimate radius", "global %s, caustic %s", radius(s.global).c_str(), radius(s.caustic).c_str());
    }
    if (s.pm_steps > 1)
        row("pm budget", "%u renders, the last with %llu global photons and %u gather rays", s.pm_steps,
            (unsigned long long)s.pm_global_photons, s.pm_gather_rays);
    if (s.sppm.passes > 0)
        row(s.mode == "pm" ? "sppm (the error's judge)" : "sppm", "%u passes, %llu photons emitted, %llu hits, mean radius %.4g, photons %.2f s, camera %.2f s",
            s.sppm.passes, (unsigned long long)s.sppm.emitted, (unsigned long long)s.sppm.photon_hits,
            s.sppm.mean_radius, s.sppm.photon_seconds, s.sppm.gather_seconds);
    row("photon rays", "%llu", (unsigned long long)(s.global.rays + s.caustic.rays + s.sppm.photon_rays));
    row("rays (pass 2)", "%llu total: camera %llu, shadow %llu, reflection %llu,", (unsigned long long)s.rays.total(),
        (unsigned long long)s.rays.camera, (unsigned long long)s.rays.shadow, (unsigned long long)s.rays.reflection);
    row("", "refraction %llu, gather %llu, probe %llu", (unsigned long long)s.rays.refraction,
        (unsigned long long)s.rays.gather, (unsigned long long)s.rays.probe);
    if (s.rays.walled_lights > 0)
        row("walled lights", "%llu times a wall lay across every shadow ray from a point to an area light: none traced",
            (unsigned long long)s.rays.walled_lights);
    if (s.pixel_samples.pixels > 0)
        row("samples per pixel", "mean %.2f, most %u", s.pixel_samples.mean(), s.pixel_samples.most);
    row("density estimates", "%llu", (unsigned long long)s.estimates);
    row("irradiance cache", "%llu records, %llu gathered again for noise", (unsigned long long)s.cache_records,
        (unsigned long long)s.cache_regathered);
    if (s.plan.photons_not_shot > 0 || s.plan.photons_moved > 0 || !s.plan.passes_skipped.empty()) {
        std::string skipped;
        for (const std::string& p : s.plan.passes_skipped) skipped += (skipped.empty() ? "" : ", ") + p;
        row("plan saved", "%llu photons not shot, %llu moved between lights; skipped: %s",
            (unsigned long long)s.plan.photons_not_shot, (unsigned long long)s.plan.photons_moved,
            skipped.empty() ? "nothing" : skipped.c_str());
    }
    if (s.error.available || s.mode == "sppm" || s.mode == "reference") {  // pm: when estimated
        std::snprintf(line, sizeof line, "  %-28s", "estimated error");
        out += line + format_error_estimate(s.error) + '\n';  // longer than a row's buffer
    }
    if (!s.stopped_by.empty()) row("stopped by", "%s", s.stopped_by.c_str());
    row("time", "precompute %.2f s, cache %.2f s, render %.2f s, total %.2f s", s.precompute_seconds,
        s.cache_seconds, s.render_seconds, s.total_seconds);
    return out;
}

}  // namespace photon
