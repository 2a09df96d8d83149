// SPDX-License-Identifier: MIT
#pragma once
// Pass 2 of the photon map modes and rt: the image, one radiance estimate per camera sample,
// averaged per pixel.

#include <chrono>
#include <mutex>
#include <vector>

#include "../film/adaptive_sampling.hpp"
#include "../film/film.hpp"
#include "../parallel/parallel_for.hpp"
#include "../scene/camera.hpp"
#include "radiance.hpp"
#include "reference_render.hpp"

namespace photon {

/// Whether pass 2 samples adaptively: a threshold, and room under aa_max_samples for a second round.
[[nodiscard]] inline bool samples_adaptively(const RenderSettings& s) noexcept {
    return s.aa_threshold > 0 && 2 * std::uint64_t(samples_per_round(s)) <= s.aa_max_samples;
}

/// Whether pass 2 anti-aliases by contrast (POV-Ray's way): a threshold, and room under
/// aa_max_samples for a supersampling round.
[[nodiscard]] inline bool samples_by_contrast(const RenderSettings& s) noexcept {
    return s.aa_contrast > 0 && samples_per_round(s) < s.aa_max_samples && s.aa_samples > 0;
}

/// Pass 2: one radiance estimate per jittered sample, averaged per pixel. Pixel p draws from
/// random stream p, so the film does not depend on the thread count.
/// - By contrast (samples_by_contrast; photon render's default, as POV-Ray's +A): every pixel
///   takes its first round, then a pixel whose colour differs from one of its four neighbours'
///   by aa_contrast or more (colour_contrast) takes rounds of aa_samples, the points of its own
///   (0,2)-sequence, the first always and further ones while its samples say its mean is noisy.
/// - Otherwise, when it samples adaptively (samples_adaptively), a pixel takes further rounds of
///   samples, the next points of its own (0,2)-sequence, while its own samples say its mean is
///   noisy (film/adaptive_sampling.hpp).
/// `samples_taken`, when given, receives each pixel's count (row-major; 0 for another rank's
/// rows). Lights with `lights_reaching[l] == false` get no shadow rays
/// (EffectsPlan::light_emits; empty: all do).
template <class SceneT>
[[nodiscard]] Film render_image(const SceneT& scene, const Camera<typename SceneT::scalar_type>& camera,
                                const PhotonMaps& maps, const RenderSettings& settings, RenderStats& stats,
                                const std::vector<bool>& lights_reaching = {},
                                std::vector<std::uint32_t>* samples_taken = nullptr) {
    using S = typename SceneT::scalar_type;
    const auto start = std::chrono::steady_clock::now();
    Film film(settings.width, settings.height);
    if (settings.mode == RenderMode::reference) return render_reference(scene, camera, settings, stats);
    const RadianceIntegrator<SceneT> integrator(scene, maps, settings, lights_reaching);
    const unsigned spp = samples_per_round(settings), grid = strata_per_axis(spp);
    const AdaptiveRule rule{.threshold = settings.aa_threshold, .max_samples = settings.aa_max_samples};
    const bool by_contrast = samples_by_contrast(settings);
    const bool adaptive = !by_contrast && samples_adaptively(settings);
    const std::size_t pixels = std::size_t(settings.width) * settings.height;
    if (samples_taken) samples_taken->assign(pixels, 0);
    std::mutex merge;
    std::size_t rows_done = 0;
    const double rows_total = double(owned_count(settings.share, settings.height)) * (by_contrast ? 2.0 : 1.0);
    bool cancelled = false;
    // Radiance along the camera ray through film point (x + jitter.x, y + jitter.y).
    auto sample = [&](unsigned x, std::size_t y, const Vec2<S>& jitter, ShadingContext& ctx) {
        const S u = (S(x) + jitter.x) / S(settings.width);
        const S v = (S(y) + jitter.y) / S(settings.height);
        ++ctx.rays.camera;
        if (const auto ray = camera.ray(u, v, lens_sample(camera, ctx.rng)))
            return Rgb<double>(integrator.radiance(*ray, 1, ctx));
        return Rgb<double>(0.0);
    };
    // Runs shade_row(y, ctx, counted) over this rank's rows, in parallel; false if cancelled.
    auto for_each_row = [&](auto&& shade_row) {
        parallel_for(settings.height, 1, settings.threads, [&](std::size_t y0, std::size_t y1) {
            ShadingContext ctx;
            PixelSampleStats counted;
            for (std::size_t y = y0; y < y1; ++y) {
                if (settings.cancel && settings.cancel->load(std::memory_order_relaxed)) {
                    const std::lock_guard lock(merge);
                    cancelled = true;
                    return;
                }
                if (!owns(settings.share, y)) continue;  // another rank's row
                shade_row(y, ctx, counted);
                if (settings.progress) {
                    const std::lock_guard lock(merge);
                    settings.progress(RenderPhase::image, double(++rows_done) / rows_total);
                }
            }
            const std::lock_guard lock(merge);
            stats.rays += ctx.rays;
            stats.estimates += ctx.estimates;
            stats.pixel_samples += counted;
        });
        return !cancelled;
    };
    auto finish = [&] {
        share_runs(settings.share, std::span(film.pixels()), settings.width, "image");
        stats.partial = cancelled;
        stats.render_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        return film;
    };
    if (!by_contrast) {
        for_each_row([&](std::size_t y, ShadingContext& ctx, PixelSampleStats& counted) {
            for (unsigned x = 0; x < settings.width; ++x) {
                const std::uint64_t pixel = std::uint64_t(y) * settings.width + x;
                ctx.rng = Pcg32(settings.seed ^ 0x706978656c73ULL, pixel);
                Rgb<double> sum(0.0);
                RunningStats seen;
                unsigned taken = 0;
                // Adaptive: the pixel's samples are the next points of one scrambled (0,2)-sequence,
                // so those of all its rounds together are as well spread as one grid of as many.
                // Off: an n x n jittered grid, its one sample centred when n is 1.
                std::uint32_t scramble[2] = {0, 0};
                if (adaptive) scramble[0] = ctx.rng.next_u32(), scramble[1] = ctx.rng.next_u32();
                do {
                    for (unsigned s = 0; s < spp; ++s) {
                        const Vec2<S> jitter = adaptive  ? scrambled_sobol02<S>(taken + s, scramble[0], scramble[1])
                                               : spp == 1 ? Vec2<S>(S(0.5))
                                                          : stratified(s, grid, ctx.rng.uniform2<S>());
                        const Rgb<double> l = sample(x, y, jitter, ctx);
                        sum += l;
                        seen.add(luminance(l));
                    }
                    taken += spp;
                } while (needs_more(seen, rule, spp));
                film.at(x, unsigned(y)) = Rgb<float>(sum / double(taken));
                counted += {.pixels = 1, .samples = taken, .most = taken};
                if (samples_taken) (*samples_taken)[pixel] = taken;
            }
        });
        return finish();
    }
    // By contrast: every pixel's first round (an n x n jittered grid, its one sample centred when
    // n is 1), then the supersampling where neighbours differ.
    struct PixelSamples {
        Rgb<double> sum{0.0};
        RunningStats seen;
    };
    std::vector<PixelSamples> first(pixels);
    const bool all_first = for_each_row([&](std::size_t y, ShadingContext& ctx, PixelSampleStats&) {
        for (unsigned x = 0; x < settings.width; ++x) {
            const std::uint64_t pixel = std::uint64_t(y) * settings.width + x;
            ctx.rng = Pcg32(settings.seed ^ 0x706978656c73ULL, pixel);
            PixelSamples& p = first[pixel];
            for (unsigned s = 0; s < spp; ++s) {
                const Rgb<double> l =
                    sample(x, y, spp == 1 ? Vec2<S>(S(0.5)) : stratified(s, grid, ctx.rng.uniform2<S>()), ctx);
                p.sum += l;
                p.seen.add(luminance(l));
            }
            film.at(x, unsigned(y)) = Rgb<float>(p.sum / double(spp));
        }
    });
    if (!all_first) return finish();
    // Every rank needs its neighbours' rows of the first round; the encoding is done once.
    share_runs(settings.share, std::span(film.pixels()), settings.width, "image");
    std::vector<Rgb<float>> encoded(pixels);
    for (std::size_t i = 0; i < pixels; ++i) encoded[i] = contrast_encoded(film.pixels()[i]);
    const unsigned aa_round = settings.aa_samples;
    for_each_row([&](std::size_t y, ShadingContext& ctx, PixelSampleStats& counted) {
        for (unsigned x = 0; x < settings.width; ++x) {
            const std::uint64_t pixel = std::uint64_t(y) * settings.width + x;
            const Rgb<float>& here = encoded[pixel];
            const bool differs =
                (x > 0 && colour_contrast(here, encoded[pixel - 1]) >= settings.aa_contrast) ||
                (x + 1 < settings.width && colour_contrast(here, encoded[pixel + 1]) >= settings.aa_contrast) ||
                (y > 0 && colour_contrast(here, encoded[pixel - settings.width]) >= settings.aa_contrast) ||
                (y + 1 < settings.height && colour_contrast(here, encoded[pixel + settings.width]) >= settings.aa_contrast);
            PixelSamples& p = first[pixel];
            unsigned taken = spp;
            if (differs) {
                // A stream of its own: the first round's may have been drawn from already.
                ctx.rng = Pcg32(settings.seed ^ 0x73757065726161ULL, pixel);
                const std::uint32_t scramble0 = ctx.rng.next_u32(), scramble1 = ctx.rng.next_u32();
                unsigned points = 0;
                do {
                    const unsigned round = std::min(aa_round, settings.aa_max_samples - taken);
                    for (unsigned s = 0; s < round; ++s) {
                        const Rgb<double> l = sample(x, y, scrambled_sobol02<S>(points++, scramble0, scramble1), ctx);
                        p.sum += l;
                        p.seen.add(luminance(l));
                    }
                    taken += round;
                } while (needs_more(p.seen, rule, aa_round));
                film.at(x, unsigned(y)) = Rgb<float>(p.sum / double(taken));
            }
            counted += {.pixels = 1, .samples = taken, .most = taken};
            if (samples_taken) (*samples_taken)[pixel] = taken;
        }
    });
    return finish();
}

}  // namespace photon
