// SPDX-License-Identifier: MIT
#pragma once
// pm's estimated error and its budgets. pm's photon maps and irradiance cache serve every pixel,
// so no split of its camera samples sees their noise or their bias (blur, interpolation, a map
// too sparse for a corner). Its error is measured instead against a short consistent run of
// sppm on the same scene and settings (Hachisuka, Jarosz and Jensen 2010 estimate the error of a
// progressive render; here the progressive render is the judge): sppm's two half-images give its
// mean and its own noise, and |pm - sppm|^2 minus that noise estimates pm's squared error, noise
// and bias together (film/error_estimate.hpp, estimate_error_against).
//
// The run's size: even passes until its own noise is at most half the error it measures (the
// subtraction is then of the smaller term), or it has taken `pm_error_time` times pm's own render
// time (after 2 passes, one per half: a first estimate), or `pm_error_passes` passes. On a large
// image it renders one pixel of each tile of a few pixels (judge_pixel_stride): the error's sums
// need thousands of pixels, not every one, and the judge then costs a tenth of pm. An estimate
// smaller than the subtraction resolves says so ("below X", film/error_estimate.hpp). What it
// cannot see: sppm's own bias at that many passes (its radii have not shrunk to zero), counted
// as pm's.
//
// Budgets (time_limit, target_error): pm renders again with twice the photons and twice the
// gather rays, each render compared with the same judge (run again, another seed, when pm's error
// falls below its noise or does not resolve it), until the target is met (by a resolved estimate,
// or by the bound "below X" of one the judge does not resolve), the estimate stalls above the
// target (two renders without a 10% fall: the judge's own error is reached), the next render would
// pass the time limit, or the photon counts reach their limits or the memory's. The image is the last render's, not an average: doubling
// the photons shrinks pm's bias, which averaging renders with the same counts cannot.

#include <algorithm>
#include <array>
#include <atomic>
#include <chrono>
#include <cmath>
#include <functional>
#include <limits>

#include "../film/error_estimate.hpp"
#include "sppm.hpp"

namespace photon {

/// Pixels of the image the judge of pm's error renders at the least: enough that the error's
/// sums over them resolve a tenth of a percent (docs/accuracy.md).
inline constexpr double pm_judge_pixels = 50'000;

/// One pixel of each N x N tile for the judge of a width x height image: N = 1 up to about
/// 4 x pm_judge_pixels, at most 8.
[[nodiscard]] inline unsigned judge_pixel_stride(unsigned width, unsigned height) noexcept {
    const double n = std::floor(std::sqrt(double(width) * double(height) / pm_judge_pixels));
    return unsigned(std::clamp(n, 1.0, 8.0));
}

/// The judge of pm's error: sppm half-images summed over its runs, weighted by their passes.
struct PmJudge {
    std::array<Film, 2> halves;
    unsigned passes = 0, runs = 0;
    unsigned stride = 1;  ///< the runs render one pixel of each stride x stride tile
    double seconds = 0;

    [[nodiscard]] bool empty() const noexcept { return passes == 0; }

    /// The estimate of `image`'s error against the judge.
    [[nodiscard]] ErrorEstimate estimate(const Film& image, Film* error_film = nullptr) const {
        return estimate_error_against(image, halves[0], halves[1], passes, 8, error_film, stride);
    }

    /// Adds `run` (its halves, of `passes` / 2 passes each) to the judge.
    void add(std::array<Film, 2>&& run, unsigned run_passes) {
        if (passes == 0) {
            halves = std::move(run);
        } else {
            const double w_old = double(passes) / double(passes + run_passes), w_new = 1.0 - w_old;
            for (int h = 0; h < 2; ++h)
                for (std::size_t i = 0; i < halves[h].pixels().size(); ++i)
                    halves[h].pixels()[i] =
                        Rgb<float>(Rgb<double>(halves[h].pixels()[i]) * w_old + Rgb<double>(run[h].pixels()[i]) * w_new);
        }
        passes += run_passes;
        ++runs;
    }
};

/// One more short sppm run for `judge`, compared with `image` after every pass: it stops after an
/// even pass at which its own noise is at most half the error it measures in `image`, or after
/// `seconds` (2 passes at least), or at settings.pm_error_passes. Statistics go to `stats.sppm`.
template <class SceneT>
void extend_pm_judge(const SceneT& scene, const Camera<typename SceneT::scalar_type>& camera, const RenderSettings& settings,
                     const Film& image, double seconds, PmJudge& judge, RenderStats& stats) {
    RenderSettings s = settings;
    s.mode = RenderMode::sppm;
    // Where a final-gather ray lands pm reads photons of up to max_photon_depth bounces, one
    // diffuse bounce more than sppm's photons make at the same setting: the judge's go one further
    // (at the paper's depth 10 the difference shows in room 2: docs/design.md, 'What room 2's
    // judge says').
    if (settings.final_gather_rays > 0 && s.max_photon_depth < SettingsLimits::max_photon_depth) ++s.max_photon_depth;
    s.sppm_passes = std::max(2u, settings.pm_error_passes + settings.pm_error_passes % 2);
    s.time_limit = 0;
    s.target_error = 0;
    s.on_pass = {};
    s.sppm_pixel_stride = judge.stride;
    s.seed = mix64(settings.seed ^ 0x706d6a75646765ULL) + judge.runs;  // independent of pm's and of earlier runs
    std::atomic<bool> stop{false};
    s.cancel = &stop;
    const auto start = std::chrono::steady_clock::now();
    // Each pass: first the image (its distance to pm's image), then the report (its own noise).
    double distance = 0;  // |image - J|^2 / |J|^2
    const SppmPassCallback measure = [&](unsigned, const Film& film) {
        double squared_difference = 0, squared_judge = 0;
        for (unsigned y = 0; y < film.height(); ++y)
            for (unsigned x = 0; x < film.width(); ++x) {
                if (!in_pixel_subset(x, y, judge.stride)) continue;
                const Rgb<double> j(film.at(x, y)), d = Rgb<double>(image.at(x, y)) - j;
                squared_difference += glm::dot(d, d);
                squared_judge += glm::dot(j, j);
            }
        distance = squared_judge > 0 ? squared_difference / squared_judge : 0;
    };
    s.on_pass = [&](const PassReport& r) {
        if (settings.cancel && settings.cancel->load(std::memory_order_relaxed)) stop = true;
        if (r.pass % 2 == 1 || r.pass < 2 || !r.error.available) return;
        const double spent = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        const double noise = r.error.normalised_mse;  // relative to J^2 less its noise: near enough to decide
        if (spent >= seconds || noise <= (distance - noise) / 2) stop = true;
    };
    RenderStats run_stats;
    std::array<Film, 2> halves;
    (void)render_sppm(scene, camera, s, run_stats, measure, nullptr, &halves);
    const unsigned passes = run_stats.sppm.passes - run_stats.sppm.passes % 2;
    if (passes < 2) return;  // cancelled before a pass of each half
    if (passes != run_stats.sppm.passes) return;  // an odd pass count only when cancelled: halves unequal
    judge.add(std::move(halves), passes);
    judge.seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    stats.sppm.passes += run_stats.sppm.passes;
    stats.sppm.emitted += run_stats.sppm.emitted;
    stats.sppm.photon_hits += run_stats.sppm.photon_hits;
    stats.sppm.photon_rays += run_stats.sppm.photon_rays;
    stats.sppm.photon_seconds += run_stats.sppm.photon_seconds;
    stats.sppm.gather_seconds += run_stats.sppm.gather_seconds;
    stats.sppm.mean_radius = run_stats.sppm.mean_radius;
}

/// pm with its error estimate and budget. `render_once(settings, stats)` renders pm once with
/// those settings (photon maps, cache, image) and fills its statistics; this calls it once
/// without a budget and with doubled photon counts and gather rays until the budget is met with
/// one. Fills stats.error (when settings.pm_error_passes > 0), stats.pm_steps, stats.stopped_by
/// (with a budget) and `*error_film`; settings.on_pass sees every render with its estimate.
template <class SceneT, class RenderOnce>
[[nodiscard]] Film render_pm_estimated(const SceneT& scene, const Camera<typename SceneT::scalar_type>& camera,
                                       const RenderSettings& settings, RenderStats& stats, Film* error_film,
                                       RenderOnce&& render_once) {
    const auto start = std::chrono::steady_clock::now();
    auto since_start = [&] { return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(); };
    // Decisions from a clock or a flag are rank 0's for every rank (parallel/work_share.hpp); those
    // from the estimate agree by themselves, every rank holding the same images.
    auto rank0 = [&](bool decision, const char* phase) { return agree(settings.share, decision, phase); };
    auto cancelled = [&] { return rank0(settings.cancel && settings.cancel->load(std::memory_order_relaxed), "pm cancel"); };
    const bool budget = settings.time_limit > 0 || settings.target_error > 0;
    const bool estimating = settings.pm_error_passes > 0;
    if (settings.target_error > 0 && !estimating)
        throw std::invalid_argument("render settings: a target error for pm needs its error estimate (pm error passes > 0)");
    RenderSettings step = settings;
    PmJudge judge;
    judge.stride = settings.pm_error_stride > 0 ? settings.pm_error_stride : judge_pixel_stride(settings.width, settings.height);
    Film image;
    unsigned steps = 0, stalled = 0;
    double lowest = std::numeric_limits<double>::infinity();
    const RenderStats base = stats;
    SppmStats judge_stats;
    for (;;) {
        const auto step_start = std::chrono::steady_clock::now();
        RenderStats step_stats = base;
        Film film;
        try {
            film = render_once(step, step_stats);
        } catch (const MemoryLimitError&) {
            if (steps == 0) throw;
            stats.stopped_by = "memory limit";  // the next doubling would not fit
            break;
        }
        const double step_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - step_start).count();
        if (step_stats.partial && steps > 0) {  // keep the last finished render
            stats.partial = true;
            stats.stopped_by = "cancelled";
            break;
        }
        image = std::move(film);
        stats = std::move(step_stats);
        stats.pm_steps = ++steps;
        stats.pm_global_photons = step.global_photons;
        stats.pm_gather_rays = step.final_gather_rays;
        if (stats.partial) {
            stats.stopped_by = "cancelled";
            break;
        }
        if (estimating) {
            // The first run, and another whenever the judge's noise is more than half pm's error
            // or the judge does not resolve it.
            const ErrorEstimate now = judge.empty() ? ErrorEstimate{} : judge.estimate(image);
            const bool coarse = now.at_floor || now.judge_noise > now.normalised_mse / 2;
            if (judge.empty() || (coarse && !budget) ||
                (budget && coarse &&
                 rank0(settings.time_limit == 0 || since_start() + settings.pm_error_time * step_seconds < settings.time_limit,
                       "pm budget"))) {
                RenderStats run_stats;
                run_stats.sppm = judge_stats;
                extend_pm_judge(scene, camera, settings, image, settings.pm_error_time * step_seconds, judge, run_stats);
                judge_stats = run_stats.sppm;
            }
            if (!judge.empty()) stats.error = judge.estimate(image);
        }
        stats.sppm = judge_stats;
        if (settings.on_pass) settings.on_pass({steps, 0, since_start(), stats.error, &image});
        if (!budget) break;
        if (cancelled()) {
            stats.stopped_by = "cancelled";
            break;
        }
        if (settings.target_error > 0 && stats.error.available && !stats.error.at_floor &&
            stats.error.relative_rmse <= settings.target_error) {
            stats.stopped_by = "target error";
            break;
        }
        // Unresolved, the estimate is a bound: met only when the bound is.
        if (settings.target_error > 0 && stats.error.available && stats.error.at_floor &&
            stats.error.relative_rmse <= settings.target_error) {
            stats.stopped_by = "target error (the bound below what the judge resolves)";
            break;
        }
        // The estimate cannot fall below the judge's own error (its bias, its noise estimate's
        // error): when two renders in a row did not bring it 10% below its lowest, more photons
        // are no longer seen to pay, and a target below that level would never be met.
        if (stats.error.available) {
            if (stats.error.relative_rmse < 0.9 * lowest) {
                lowest = stats.error.relative_rmse;
                stalled = 0;
            } else if (++stalled == 2 && settings.target_error > 0) {
                stats.stopped_by = "estimate stalled (at the short sppm run's resolution)";
                break;
            }
        }
        // The next render takes about twice this one (twice the photons and gather rays).
        if (rank0(settings.time_limit > 0 && since_start() + 2 * step_seconds > settings.time_limit, "pm budget")) {
            stats.stopped_by = "time limit";
            break;
        }
        if (2 * step.global_photons > SettingsLimits::max_sppm_photons_per_pass ||
            2 * std::size_t(step.final_gather_rays) > SettingsLimits::max_samples) {  // kd-tree indices are 32-bit
            stats.stopped_by = "photon limit";
            break;
        }
        step.global_photons *= 2;
        step.caustic_photons *= 2;
        step.final_gather_rays *= 2;
    }
    if (error_film && !judge.empty()) (void)judge.estimate(image, error_film);
    return image;
}

}  // namespace photon
