// SPDX-License-Identifier: MIT
#pragma once
// The path tracer's image (--mode reference), with an error estimate and a budget. It renders in
// rounds of settings.samples_per_pixel samples per pixel (an n x n jittered grid): one round
// without a budget, as many as settings.time_limit / settings.target_error allow with one. Each
// sample goes to one of two half-images by the parity of its stratum's column + row + round (a
// checkerboard of the pixel's strata, flipped every round; with one sample per pixel, alternate
// rounds), so both halves cover every pixel evenly and are independent: their difference
// estimates the image's noise (film/error_estimate.hpp). With one sample per pixel and one round
// there is no second half and no estimate.
//
// Pixel p of round r draws from random stream p of a seed made from settings.seed and r (round 0:
// the seed path tracing has always used), so the film does not depend on the thread count.

#include <array>
#include <chrono>
#include <mutex>
#include <vector>

#include "../film/error_estimate.hpp"
#include "../film/film.hpp"
#include "../math/rng.hpp"
#include "../math/sampling.hpp"
#include "../parallel/parallel_for.hpp"
#include "../parallel/work_share.hpp"
#include "../scene/camera.hpp"
#include "path_tracer.hpp"
#include "../settings/render_settings.hpp"
#include "render_stats.hpp"
#include "shading_context.hpp"

namespace photon {

namespace detail {

constexpr std::uint64_t reference_pixel_salt = 0x706978656c73ULL;

/// Samples of half 0 and half 1 in round `round` of an n x n grid (the checkerboard's two colours).
[[nodiscard]] constexpr std::array<unsigned, 2> reference_half_counts(unsigned n, unsigned round) noexcept {
    const unsigned spp = n * n, first = (spp + 1) / 2;  // the colour of stratum (0, 0)
    return round % 2 == 0 ? std::array<unsigned, 2>{first, spp - first} : std::array<unsigned, 2>{spp - first, first};
}

}  // namespace detail

/// Renders the path tracer's image in rounds (see above). Fills stats.error, stats.stopped_by,
/// stats.partial, stats.rays and stats.render_seconds, and `*error_film` (if given) with the
/// per-pixel error estimate.
template <class SceneT>
[[nodiscard]] Film render_reference(const SceneT& scene, const Camera<typename SceneT::scalar_type>& camera,
                                    const RenderSettings& settings, RenderStats& stats, Film* error_film = nullptr) {
    using S = typename SceneT::scalar_type;
    const auto start = std::chrono::steady_clock::now();
    auto seconds_since = [](auto t) { return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count(); };
    const unsigned width = settings.width, height = settings.height;
    const PathTracer<SceneT> path_tracer(scene, settings);
    const unsigned spp = samples_per_round(settings), grid = strata_per_axis(spp);
    const bool budget = settings.time_limit > 0 || settings.target_error > 0;
    // Thousands of samples of a pixel would drift in float: sums in double, per half.
    std::array<std::vector<Rgb<double>>, 2> sums;
    for (auto& s : sums) s.assign(std::size_t(width) * height, Rgb<double>(0.0));
    std::vector<unsigned> rounds_of_row(height, 0);  // rows of a cancelled round have one round fewer
    const unsigned most_rounds = budget ? SettingsLimits::max_samples / spp : 1u;

    // Every rank's rows on every rank: the sums and the rounds each row has.
    auto share_sums = [&] {
        for (auto& s : sums) share_runs(settings.share, std::span(s), width, "reference sums");
        share_runs(settings.share, std::span(rounds_of_row), 1, "reference sums");
    };
    // The two half-images and their mean from the rounds each row has.
    auto images = [&](bool with_error_film) {
        struct {
            Film film;
            ErrorEstimate error;
            Film error_film;
        } out;
        Film a(width, height), b(width, height);
        out.film = Film(width, height);
        bool both = true;
        for (unsigned y = 0; y < height; ++y) {
            std::array<double, 2> count{0, 0};
            for (unsigned r = 0; r < rounds_of_row[y]; ++r) {
                const auto c = detail::reference_half_counts(grid, r);
                count[0] += c[0], count[1] += c[1];
            }
            both = both && count[0] > 0 && count[1] > 0;
            for (unsigned x = 0; x < width; ++x) {
                const std::size_t i = std::size_t(y) * width + x;
                if (count[0] > 0) a.pixels()[i] = Rgb<float>(sums[0][i] / count[0]);
                if (count[1] > 0) b.pixels()[i] = Rgb<float>(sums[1][i] / count[1]);
                if (count[0] + count[1] > 0) out.film.pixels()[i] = Rgb<float>((sums[0][i] + sums[1][i]) / (count[0] + count[1]));
            }
        }
        if (both && height > 0) {
            out.error = estimate_error(a, b);
            if (with_error_film) out.error_film = error_image(a, b);
        }
        return out;
    };

    stats.stopped_by = budget ? "rounds done" : "";
    double last_round_seconds = 0;
    unsigned round = 0;
    bool cancelled = false;
    while (round < most_rounds && !cancelled) {
        // Rank 0's clock decides for every rank (parallel/work_share.hpp).
        if (agree(settings.share, budget && settings.time_limit > 0 && round >= 2 &&
                                      seconds_since(start) + last_round_seconds > settings.time_limit,
                  "reference budget")) {
            stats.stopped_by = "time limit";
            break;
        }
        const auto round_start = std::chrono::steady_clock::now();
        const std::uint64_t seed = round == 0 ? settings.seed ^ detail::reference_pixel_salt
                                              : (settings.seed ^ detail::reference_pixel_salt) ^ mix64(round);
        std::mutex merge;
        std::size_t rows_done = 0;
        parallel_for(height, 1, settings.threads, [&](std::size_t y0, std::size_t y1) {
            ShadingContext ctx;
            for (std::size_t y = y0; y < y1; ++y) {
                if (settings.cancel && settings.cancel->load(std::memory_order_relaxed)) {
                    const std::lock_guard lock(merge);
                    cancelled = true;
                    break;
                }
                if (!owns(settings.share, y)) continue;  // another rank's row
                for (unsigned x = 0; x < width; ++x) {
                    const std::uint64_t pixel = std::uint64_t(y) * width + x;
                    ctx.rng = Pcg32(seed, pixel);
                    std::array<Rgb<double>, 2> sum{Rgb<double>(0.0), Rgb<double>(0.0)};
                    for (unsigned s = 0; s < spp; ++s) {
                        const Vec2<S> jitter = spp == 1 ? Vec2<S>(S(0.5)) : stratified(s, grid, ctx.rng.uniform2<S>());
                        const S u = (S(x) + jitter.x) / S(width);
                        const S v = (S(y) + jitter.y) / S(height);
                        ++ctx.rays.camera;
                        if (const auto ray = camera.ray(u, v, lens_sample(camera, ctx.rng)))
                            sum[(s % grid + s / grid + round) % 2] += Rgb<double>(path_tracer.radiance(*ray, ctx));
                    }
                    sums[0][pixel] += sum[0];
                    sums[1][pixel] += sum[1];
                }
                ++rounds_of_row[y];
                if (settings.progress && !budget) {
                    const std::lock_guard lock(merge);
                    settings.progress(RenderPhase::image, double(++rows_done) / double(owned_count(settings.share, height)));
                }
            }
            const std::lock_guard lock(merge);
            stats.rays += ctx.rays;
        });
        last_round_seconds = seconds_since(round_start);
        if (cancelled) break;
        ++round;
        if (!budget) break;
        const bool wants_error = settings.target_error > 0 || settings.on_pass;
        if (!agree(settings.share, wants_error, "reference budget")) continue;  // rank 0's callbacks decide for all
        share_sums();
        const auto now = images(false);
        if (settings.on_pass) settings.on_pass({round, most_rounds, seconds_since(start), now.error});
        if (settings.target_error > 0 && now.error.available && now.error.relative_rmse <= settings.target_error) {
            stats.stopped_by = "target error";
            break;
        }
    }
    if (cancelled) stats.stopped_by = budget ? "cancelled" : "";
    // A cancelled first round leaves rows unrendered: the image is partial (black there). A
    // later one leaves a whole image of fewer rounds on some rows: not partial, just less converged.
    stats.partial = cancelled && round == 0;
    share_sums();
    auto result = images(error_film != nullptr);
    stats.error = result.error;
    if (error_film) *error_film = std::move(result.error_film);
    stats.render_seconds = seconds_since(start);
    return std::move(result.film);
}

}  // namespace photon
