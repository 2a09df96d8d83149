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

/// Pass 2: one radiance estimate per jittered sample, averaged per pixel. Pixel p draws from
/// random stream p, so the film does not depend on the thread count. When it samples adaptively
/// (samples_adaptively), a pixel takes further rounds of samples, the next points of its own
/// (0,2)-sequence, while its own samples say its mean is noisy (film/adaptive_sampling.hpp).
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
    const bool adaptive = samples_adaptively(settings);
    if (samples_taken) samples_taken->assign(std::size_t(settings.width) * settings.height, 0);
    std::mutex merge;
    std::size_t rows_done = 0;
    bool cancelled = false;
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
                        const S u = (S(x) + jitter.x) / S(settings.width);
                        const S v = (S(y) + jitter.y) / S(settings.height);
                        ++ctx.rays.camera;
                        Rgb<double> l(0.0);
                        if (const auto ray = camera.ray(u, v, lens_sample(camera, ctx.rng)))
                            l = Rgb<double>(integrator.radiance(*ray, 1, ctx));
                        sum += l;
                        seen.add(luminance(l));
                    }
                    taken += spp;
                } while (needs_more(seen, rule, spp));
                film.at(x, unsigned(y)) = Rgb<float>(sum / double(taken));
                counted += {.pixels = 1, .samples = taken, .most = taken};
                if (samples_taken) (*samples_taken)[pixel] = taken;
            }
            if (settings.progress) {
                const std::lock_guard lock(merge);
                settings.progress(RenderPhase::image, double(++rows_done) / double(owned_count(settings.share, settings.height)));
            }
        }
        const std::lock_guard lock(merge);
        stats.rays += ctx.rays;
        stats.estimates += ctx.estimates;
        stats.pixel_samples += counted;
    });
    share_runs(settings.share, std::span(film.pixels()), settings.width, "image");
    stats.partial = cancelled;
    stats.render_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return film;
}

}  // namespace photon
