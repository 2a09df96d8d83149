// SPDX-License-Identifier: MIT
#pragma once
// Building the irradiance cache by pretrace, coarse to fine (as POV-Ray's radiosity pretrace):
// level by level, camera rays through a grid of pixel centres (spacing 32, 16, ..., 1 pixels)
// find the diffuse points the image will shade, directly or through mirrors and glass. A point
// that no record covers yet gets a new record: a final gather with many rays. Records made within
// one level do not see each other, only those of earlier levels, and each pixel draws from its own
// random stream, so the cache is the same for any thread count. Each record keeps the gradients
// of its own gather, limited so that they cannot extrapolate to negative light. After each level
// but the last, every radius is clamped by its neighbours' (clamp_radii_to_neighbours, one
// order-independent sweep, so still the same for any thread count): a coarse record that reached
// past a corner gives way, and the finer levels fill in around it.

#include <algorithm>
#include <cmath>
#include <chrono>
#include <mutex>
#include <vector>

#include "../parallel/parallel_for.hpp"
#include "../scene/camera.hpp"
#include "radiance.hpp"

namespace photon {

/// The image width whose pixels bound the irradiance cache's record radii, at the least.
inline constexpr unsigned cache_reference_width = 800;

template <class SceneT>
[[nodiscard]] IrradianceCache build_irradiance_cache(const SceneT& scene,
                                                     const Camera<typename SceneT::scalar_type>& camera,
                                                     const PhotonMaps& maps, const RenderSettings& settings,
                                                     RenderStats& stats) {
    using S = typename SceneT::scalar_type;
    const auto start = std::chrono::steady_clock::now();
    const RadianceIntegrator<SceneT> integrator(scene, maps, settings);
    const float error = settings.irradiance_cache_error;
    // Size of one pixel at unit distance; the validity radius a * R of a record is kept between
    // min and max pixels at the distance the camera sees it from (Tabellion and Lamorlette 2004).
    // The pixels are those of an image at least `cache_reference_width` wide: in a small image a
    // pixel spans much of the scene, and records valid over 1.5 to 24 of them smoothed indirect
    // light across corners (a 48 x 36 room read 18-23% dark near the floor's corners, 2-6% with a
    // gather at every pixel). Small images then gather more often, which they can afford.
    const unsigned reference_width = std::max(settings.width, cache_reference_width);
    const PixelSpread<S> pixel = camera.pixel_spread(
        reference_width, unsigned(std::lround(double(reference_width) * settings.height / settings.width)));
    std::vector<IrradianceRecord> records;
    IrradianceCache cache(records, error);
    unsigned spacing = 1;
    while (spacing * 2 <= std::min(32u, std::max(settings.width, settings.height))) spacing *= 2;
    unsigned levels = 0, done_levels = 0;
    for (unsigned s = spacing; s >= 1; s /= 2) ++levels;
    for (; spacing >= 1; spacing /= 2) {
        const unsigned cols = (settings.width + spacing - 1) / spacing, rows = (settings.height + spacing - 1) / spacing;
        std::vector<std::vector<IrradianceRecord>> found(std::size_t(cols) * rows);
        std::mutex merge;
        parallel_for(found.size(), 64, settings.threads, [&](std::size_t b, std::size_t e) {
            if (settings.cancel && settings.cancel->load(std::memory_order_relaxed)) return;
            ShadingContext ctx;
            std::vector<GatherSample<S>> samples;
            for (std::size_t i = b; i < e; ++i) {
                if (!owns(settings.share, i, Deal::hashed)) continue;  // another rank's
                const unsigned px = unsigned(i % cols) * spacing + spacing / 2, py = unsigned(i / cols) * spacing + spacing / 2;
                if (px >= settings.width || py >= settings.height) continue;
                ctx.rng = Pcg32(settings.seed ^ (0x70726574ULL + spacing), std::uint64_t(py) * settings.width + px);
                ++ctx.rays.camera;
                const auto ray = camera.ray((S(px) + S(0.5)) / S(settings.width), (S(py) + S(0.5)) / S(settings.height));
                if (!ray) continue;
                auto& mine = found[i];
                integrator.for_each_diffuse_hit(*ray, 1, S(0), [&](const Vec3<S>& x, const Vec3<S>& n, const Vec3<S>& geometric_n, S length) {
                    const Vec3<float> xf(x), nf(n);
                    if (cache.interpolate(xf, nf, ctx.nearest)) return;
                    if (!mine.empty() && IrradianceCache(mine, error).interpolate(xf, nf, ctx.nearest)) return;
                    const auto g = integrator.gather(x, n, settings.final_gather_rays, ctx, geometric_n, &samples);
                    const S footprint = pixel.size + length * pixel.angle;
                    const S r = std::clamp(g.harmonic_distance, S(1.5) * footprint / S(error),
                                           S(24) * footprint / S(error));
                    IrradianceRecord record{xf, nf, Rgb<float>(g.irradiance), float(r),
                                            irradiance_gradients<S>(samples, GatherStrata::for_rays(settings.final_gather_rays),
                                                                    Frame<S>::from_normal(n))};
                    limit_translation_gradient(record);
                    mine.push_back(record);
                });
            }
            const std::lock_guard lock(merge);
            stats.rays += ctx.rays;
        });
        share_lists(settings.share, found, "irradiance cache", Deal::hashed);  // every rank sees every record
        for (auto& list : found) records.insert(records.end(), list.begin(), list.end());
        // Not after the last level: the radii it would shrink there leave holes that no level
        // fills, and every image sample landing in one gathers in full (room 1 at 320 x 240:
        // 45% more gather rays for the same picture).
        if (spacing > 1) clamp_radii_to_neighbours(records, error);
        cache = IrradianceCache(records, error);
        if (settings.progress) settings.progress(RenderPhase::precompute, double(++done_levels) / double(levels));
        if (spacing == 1) break;
    }
    stats.cache_records = records.size();
    stats.cache_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return cache;
}

}  // namespace photon
