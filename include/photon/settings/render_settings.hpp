// SPDX-License-Identifier: MIT
#pragma once

#include <atomic>
#include <cmath>
#include <cstdint>
#include <functional>
#include <stdexcept>
#include <string>

#include "../estimator/density_estimate.hpp"
#include "../film/error_estimate.hpp"
#include "../light/light.hpp"
#include "../math/sampling.hpp"  // strata_per_axis
#include "../parallel/work_share.hpp"
#include "effect_switches.hpp"

namespace photon {

/// The paper's three ways to render.
enum class RenderMode {
    rt,         ///< Whitted ray tracing with soft shadows, no indirect light (the paper's Table 1)
    pm,         ///< two-pass photon mapping: shadow rays + caustic map + global map (Table 2)
    pm_direct,  ///< all light read from the photon maps at the first diffuse hit (Figure 3)
    reference,  ///< unbiased path tracing, to measure the others' error (slow; many samples)
    sppm,       ///< stochastic progressive photon mapping: consistent, sees every path (the judge)
};

[[nodiscard]] inline const char* to_string(RenderMode m) noexcept {
    switch (m) {
    case RenderMode::rt: return "rt";
    case RenderMode::pm: return "pm";
    case RenderMode::pm_direct: return "pm-direct";
    case RenderMode::reference: return "reference";
    case RenderMode::sppm: return "sppm";
    }
    return "?";
}

/// The stages of a render, as progress reports name them.
enum class RenderPhase { caustic_photons, global_photons, precompute, image, sppm_pass };

[[nodiscard]] inline const char* to_string(RenderPhase p) noexcept {
    switch (p) {
    case RenderPhase::caustic_photons: return "caustic photons";
    case RenderPhase::global_photons: return "global photons";
    case RenderPhase::precompute: return "precomputing irradiance";
    case RenderPhase::image: return "rendering";
    case RenderPhase::sppm_pass: return "sppm passes";
    }
    return "?";
}

/// What one pass of sppm, or one round of samples of reference, left: for progress lines and
/// budgets.
struct PassReport {
    unsigned pass = 0;        ///< passes or rounds done
    unsigned most = 0;        ///< the most there will be (the settings' or the budget's cap)
    double seconds = 0;       ///< since the render started
    ErrorEstimate error;      ///< of the image so far (not available after the first)
    const Film* image = nullptr;  ///< pm: the image so far, to write as the render goes
};

/// The most rays a cache record gathers in all, as a multiple of its first gather's, when that
/// one is noisier than RenderSettings::cache_gather_noise.
inline constexpr unsigned cache_gather_max_factor = 4;

/// Everything a render needs besides the scene and the camera. Defaults give a clean 800x600
/// Cornell box in well under a minute on two cores.
struct RenderSettings {
    RenderMode mode = RenderMode::pm;
    unsigned width = 800, height = 600;
    unsigned samples_per_pixel = 4;  ///< anti-aliasing; rounded up to a square n x n jittered grid
    /// rt, pm and pm-direct: adaptive anti-aliasing (film/adaptive_sampling.hpp). A pixel takes
    /// further rounds of `samples_per_pixel` samples while the standard error of its mean
    /// luminance is above this fraction of the mean, up to `aa_max_samples` samples (whole rounds
    /// only). 0: off, every pixel takes `samples_per_pixel` (the library's default; the command
    /// line uses 0.1 in rt and pm).
    float aa_threshold = 0.0f;
    unsigned aa_max_samples = 16;
    /// rt, pm and pm-direct: anti-aliasing by contrast, as POV-Ray's +A (its method 1). Every pixel
    /// takes its `samples_per_pixel`; one whose colour differs from a neighbour's by at least this
    /// (film/adaptive_sampling.hpp: colour_contrast, POV-Ray's Antialias_Threshold) takes rounds of
    /// `aa_samples` more, the first always, more while aa_threshold finds it noisy, up to
    /// `aa_max_samples` in all. 0: off (the library's default; the command line uses 0.3).
    float aa_contrast = 0.0f;
    unsigned aa_samples = 9;  ///< a supersampling round (POV-Ray's Antialias_Depth 3: 3 x 3)
    unsigned max_ray_depth = 4;      ///< primary ray = 1; a mirror seen in a mirror is depth 3
    /// rt and pm: a mirror or glass ray whose weight in its pixel (the largest channel of the
    /// product of the reflectances on its way) is below this is not traced, as POV-Ray's
    /// adc_bailout (trace.cpp); what it would bring is at most that fraction of the pixel's light.
    /// 0: every ray to max_ray_depth (the library's default; the command line uses POV-Ray's 1/255).
    float adc_bailout = 0.0f;
    unsigned shadow_samples = 16;    ///< per area light and shading point; rounded up to n x n strata

    std::size_t global_photons = 200'000;   ///< emitted for the global map
    std::size_t caustic_photons = 200'000;  ///< emitted towards caustic targets (skipped if none)
    /// Russian roulette ends photon paths; this cap is only a backstop (a path survives 100 bounces
    /// at albedo 0.8 with probability 2e-10). The paper's 10 cuts room 1's indirect light
    /// (docs/accuracy.md, 'Room 1 against sppm: the photon depth'); its scene files ask for 10.
    unsigned max_photon_depth = 100;
    EmissionSampler emission = EmissionSampler::direct;

    /// The estimates' max_radius 0 derives it from the map's photon density once the map is built
    /// (estimator/estimate_radius.hpp), so that it follows the scene's scale and the photon count.
    EstimateSettings global_estimate{.k = 100, .max_radius = 0.0f, .boundary_probes = 16};
    EstimateSettings caustic_estimate{.k = 60, .max_radius = 0.0f, .kernel = {Filter::cone, 1.1f}};
    /// pm: rays per final gather (0: read the global map directly at the first diffuse hit).
    unsigned final_gather_rays = 256;
    /// pm: final gathers are cached and interpolated with this error bound (Ward's a); 0 gathers
    /// at every camera sample instead (then use fewer rays, e.g. 16).
    float irradiance_cache_error = 0.2f;
    /// pm: the relative noise a cache record's final gather aims at. A record whose gather varies
    /// more from cell to cell (estimator/gather_noise.hpp) gathers again where its cells vary, up
    /// to `cache_gather_max_factor` times the rays in all; 0 (the default): every record takes
    /// final_gather_rays. It pays where a small bright patch lights a wall (the rooms' files ask
    /// for 0.015); where the first gather is good enough it only costs time (docs/design.md).
    float cache_gather_noise = 0.0f;
    /// Final gathering reads irradiance precomputed at every `irradiance_stride`-th global photon
    /// (Christensen 1999) instead of running a density estimate per gather ray; 0 turns it off.
    unsigned irradiance_stride = 4;
    /// reference: weigh light sampling against BSDF sampling for sphere lights (multiple
    /// importance sampling); false counts direct light by shadow rays alone (to measure the gain).
    bool reference_mis = true;

    /// sppm: passes of one camera ray per pixel and `sppm_photons_per_pass` photons each.
    unsigned sppm_passes = 64;
    std::size_t sppm_photons_per_pass = 200'000;
    /// sppm: first gathering radius in scene units; 0 chooses it per pixel from the pixel's
    /// footprint at its first visible point (integrator/sppm.hpp).
    float sppm_initial_radius = 0.0f;
    /// sppm: 1 renders every pixel; N > 1 one pixel of each N x N tile (in_pixel_subset,
    /// film/error_estimate.hpp), the rest left black: pm's error judge at a fraction of the cost.
    unsigned sppm_pixel_stride = 1;

    /// sppm and reference: a budget. Rendering stops after the pass (sppm) or round of
    /// `samples_per_pixel` samples (reference) at which `time_limit` seconds have passed or the
    /// estimated relative RMSE (film/error_estimate.hpp) is at most `target_error`, whichever comes
    /// first; 0 leaves that limit out. sppm still does at most `sppm_passes` passes; reference
    /// renders one round without a budget and as many as the budget takes with one.
    /// pm too: it renders again with twice the photons and gather rays until the budget is met
    /// (integrator/pm_error.hpp); its target error needs `pm_error_passes` > 0.
    double time_limit = 0;
    double target_error = 0;
    /// pm: its error is estimated against a short sppm run of at most this many passes (each of
    /// `sppm_photons_per_pass` photons) on a subset of the pixels, taking at most `pm_error_time`
    /// times pm's own render time after its first 2 passes, fewer once its noise is at most half
    /// the error it measures (integrator/pm_error.hpp). 0: no estimate (the library's default: it
    /// costs time; the command line turns it on).
    unsigned pm_error_passes = 0;
    double pm_error_time = 0.1;
    /// pm: the judge renders one pixel of each N x N tile; 0 chooses N from the image size
    /// (judge_pixel_stride, integrator/pm_error.hpp), 1 renders every pixel (for an error image).
    unsigned pm_error_stride = 0;

    /// Effects forced on or off against the light-path plan (plan/effects_plan.hpp); all automatic:
    /// the plan decides.
    EffectSwitches effects{};

    std::uint64_t seed = 1;
    unsigned threads = 0;  ///< 0: all hardware threads; the image does not depend on it
    /// Bytes the render may plan to use (integrator/memory_budget.hpp); 0: the memory available when it starts.
    std::uint64_t memory_limit = 0;

    /// Called from worker threads (serialised) with the phase and the fraction of it done.
    std::function<void(RenderPhase, double)> progress{};
    /// sppm and reference: called after every pass or round with what it gave (serialised, on
    /// the calling thread).
    std::function<void(const PassReport&)> on_pass{};
    /// When set to true during a render, the current pass stops soon, later passes are skipped,
    /// and the result is marked partial (pixels not rendered are black).
    const std::atomic<bool>* cancel = nullptr;
    /// The processes this render is shared among (parallel/work_share.hpp); null: this one alone.
    /// The image is the same either way; every rank returns the whole of it.
    WorkShare* share = nullptr;
};

/// Upper bounds of the settings (validate). Sample counts are rounded up to n x n grids, which must
/// not overflow; the ray depth is a recursion depth, which must not overflow a thread's stack.
struct SettingsLimits {
    static constexpr unsigned max_samples = 1'000'000;  ///< per pixel, shadow rays, final-gather rays
    static constexpr unsigned max_ray_depth = 256;      ///< POV-Ray's largest max_trace_level
    static constexpr unsigned max_photon_depth = 10'000;
    static constexpr unsigned max_sppm_passes = 1'000'000;
    static constexpr std::size_t max_sppm_photons_per_pass = std::size_t(1) << 31;  ///< kd-tree indices are 32-bit
};

/// Camera samples per pixel in one round (pass 2, and the path tracer's rounds): samples_per_pixel
/// rounded up to an n x n grid.
[[nodiscard]] inline unsigned samples_per_round(const RenderSettings& s) noexcept {
    const unsigned grid = s.samples_per_pixel == 1 ? 1u : strata_per_axis(s.samples_per_pixel);
    return grid * grid;
}

/// Throws std::invalid_argument naming the first setting out of range.
inline void validate(const RenderSettings& s) {
    auto fail = [](const std::string& what) { throw std::invalid_argument("render settings: " + what); };
    auto in_range = [&](unsigned v, unsigned hi, const char* what) {
        if (v == 0 || v > hi) fail(std::string(what) + " must be from 1 to " + std::to_string(hi) + ", found " + std::to_string(v));
    };
    if (s.width == 0 || s.height == 0) fail("width and height must be at least 1");
    in_range(s.samples_per_pixel, SettingsLimits::max_samples, "samples per pixel");
    if (!(s.aa_threshold >= 0.0f) || !std::isfinite(s.aa_threshold)) fail("aa threshold must be finite and >= 0 (0: off)");
    in_range(s.aa_max_samples, SettingsLimits::max_samples, "aa max samples");
    if (!(s.aa_contrast >= 0.0f) || !std::isfinite(s.aa_contrast)) fail("aa contrast must be finite and >= 0 (0: off)");
    in_range(s.aa_samples, SettingsLimits::max_samples, "aa samples");
    if (!(s.adc_bailout >= 0.0f) || !(s.adc_bailout <= 1.0f)) fail("adc bailout must be in [0, 1] (0: off)");
    in_range(s.max_ray_depth, SettingsLimits::max_ray_depth, "max ray depth");
    in_range(s.shadow_samples, SettingsLimits::max_samples, "shadow samples");
    in_range(s.max_photon_depth, SettingsLimits::max_photon_depth, "max photon depth");
    if (s.final_gather_rays > SettingsLimits::max_samples)
        fail("final gather rays must be at most " + std::to_string(SettingsLimits::max_samples) + ", found " +
             std::to_string(s.final_gather_rays));
    for (const EstimateSettings* e : {&s.global_estimate, &s.caustic_estimate}) {
        if (e->k == 0) fail("photons per estimate must be at least 1");
        if (!(e->max_radius >= 0.0f) || !std::isfinite(e->max_radius))
            fail("estimate radius must be finite and >= 0 (0: from the photon density)");
        if (!(e->flatten >= 1.0f) || !std::isfinite(e->flatten)) fail("flatten must be >= 1");
        if (e->kernel.filter == Filter::cone && !(e->kernel.cone_k >= 1.0f)) fail("cone filter k must be >= 1");
    }
    if (!(s.irradiance_cache_error >= 0.0f) || !(s.irradiance_cache_error <= 1.0f))
        fail("irradiance cache error must be in [0, 1]");
    if (!(s.cache_gather_noise >= 0.0f) || !(s.cache_gather_noise <= 1.0f))
        fail("cache gather noise must be in [0, 1] (0: no second gather)");
    in_range(s.sppm_passes, SettingsLimits::max_sppm_passes, "sppm passes");
    if (s.sppm_photons_per_pass == 0 || s.sppm_photons_per_pass > SettingsLimits::max_sppm_photons_per_pass)
        fail("sppm photons per pass must be from 1 to " + std::to_string(SettingsLimits::max_sppm_photons_per_pass) +
             ", found " + std::to_string(s.sppm_photons_per_pass));
    if (!(s.time_limit >= 0) || !std::isfinite(s.time_limit)) fail("time limit must be finite and >= 0 (0: none)");
    if (!(s.target_error >= 0) || !std::isfinite(s.target_error)) fail("target error must be finite and >= 0 (0: none)");
    if (s.pm_error_passes > SettingsLimits::max_sppm_passes)
        fail("pm error passes must be at most " + std::to_string(SettingsLimits::max_sppm_passes));
    if (!(s.pm_error_time >= 0) || !std::isfinite(s.pm_error_time)) fail("pm error time must be finite and >= 0");
    if (!(s.sppm_initial_radius >= 0.0f) || !std::isfinite(s.sppm_initial_radius))
        fail("sppm initial radius must be finite and >= 0 (0: automatic)");
    if (s.sppm_pixel_stride < 1 || s.sppm_pixel_stride > 64) fail("sppm pixel stride must be from 1 to 64");
    if (s.pm_error_stride > 64) fail("pm error stride must be from 0 to 64 (0: automatic)");
}

}  // namespace photon
