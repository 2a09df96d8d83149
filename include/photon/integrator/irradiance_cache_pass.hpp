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
#include <cstdint>
#include <limits>
#include <mutex>
#include <optional>
#include <vector>

#include "../estimator/gather_noise.hpp"
#include "../parallel/parallel_for.hpp"
#include "../scene/camera.hpp"
#include "radiance.hpp"

namespace photon {

/// The image width whose pixels bound the irradiance cache's record radii, at the least.
inline constexpr unsigned cache_reference_width = 800;

/// One record's final gather: irradiance, harmonic mean distance of the hits, gradients.
template <Scalar S> struct RecordGather {
    Rgb<S> irradiance;
    S harmonic_distance;
    IrradianceGradients gradients;
    bool gathered_again = false;  ///< its first gather was noisier than wanted
};

/// Gathers again in the cells of a first gather (`samples`, one per cell of `strata`) that vary:
/// `extra` rays in all, on average. A cell's share is its spread: how much its 3 x 3 neighbours
/// differ among themselves (the range of their luminance; phi wraps around), so that an edge in
/// any direction, and a cell beside a bright one, draw rays (Neyman's allocation). The cell's own
/// first ray is left out of its share: a share chosen by the ray it replaces would favour the
/// cells whose ray happened to be bright or dark, and bias the mean (low on a patch few cells
/// see: docs/design.md, 'Irradiance cache'). A cell drawing two rays or more takes them in place
/// of its first, stratified in sub-cells (a sharp-edged light's error falls faster so than with
/// rays at random in the cell). Returns false, changing nothing, when no cell's neighbours differ.
template <class Integrator, Scalar S>
bool regather_varying_cells(const Integrator& integrator, const Vec3<S>& x, const Frame<S>& frame,
                            const std::optional<Vec3<S>>& below, GatherStrata strata, double extra,
                            ShadingContext& ctx, std::vector<GatherSample<S>>& samples) {
    const unsigned rows = strata.rows, columns = strata.columns;
    std::vector<double> lum(samples.size()), spread(samples.size(), 0.0);
    for (std::size_t c = 0; c < samples.size(); ++c) lum[c] = luminance(samples[c].radiance);
    double spread_sum = 0;
    for (unsigned j = 0; j < rows; ++j)
        for (unsigned k = 0; k < columns; ++k) {
            double lo = std::numeric_limits<double>::infinity(), hi = -lo;
            for (unsigned jj = j == 0 ? 0 : j - 1; jj <= std::min(j + 1, rows - 1); ++jj)
                for (unsigned kk : {(k + columns - 1) % columns, k, (k + 1) % columns})
                    if (jj != j || kk != k) {
                        lo = std::min(lo, lum[std::size_t(jj) * columns + kk]);
                        hi = std::max(hi, lum[std::size_t(jj) * columns + kk]);
                    }
            spread[std::size_t(j) * columns + k] = hi > lo ? hi - lo : 0.0;
            spread_sum += spread[std::size_t(j) * columns + k];
        }
    if (!(spread_sum > 0)) return false;
    for (unsigned c = 0; c < strata.count(); ++c) {
        // Whole rays: the fraction is rounded up with its own probability, so the count is right on average.
        const double share = extra * spread[c] / spread_sum;
        const unsigned fresh = unsigned(share) + (ctx.rng.uniform<double>() < share - std::floor(share) ? 1u : 0u);
        if (fresh < 2) continue;
        unsigned sub_rows = unsigned(std::sqrt(double(fresh)));
        while (fresh % sub_rows != 0) --sub_rows;  // exactly `fresh` sub-cells
        const GatherStrata within{sub_rows, fresh / sub_rows};
        Rgb<S> cell(S(0));
        for (unsigned r = 0; r < fresh; ++r)
            cell += integrator.gather_sample(x, frame, strata, c, ctx, below, within, r).radiance;
        samples[c].radiance = cell / S(fresh);
    }
    return true;
}

/// A record's final gather of `final_gather_rays` rays, one per cell. Where its cells say it is
/// noisier than `cache_gather_noise` (estimator/gather_noise.hpp), it gathers again in the cells
/// that vary (regather_varying_cells): as many rays as would meet the wanted noise were they
/// spread evenly (noise falls as one over the square root of the rays), at most
/// `cache_gather_max_factor` times the first gather in all. Irradiance and gradients then come
/// from each cell's value. A record is read over many pixels, so its noise shows as a blotch the
/// size of its radius: a wall lit by a small sunlit patch of floor needs the extra rays, and only
/// in the cells that see the patch's edges.
template <class Integrator, Scalar S>
[[nodiscard]] RecordGather<S> gather_record(const Integrator& integrator, const Vec3<S>& x, const Vec3<S>& n,
                                            const Vec3<S>& geometric_n, const RenderSettings& settings,
                                            ShadingContext& ctx, std::vector<GatherSample<S>>& samples) {
    const Frame<S> frame = Frame<S>::from_normal(n);
    const GatherStrata strata = GatherStrata::for_rays(settings.final_gather_rays);
    const auto first = integrator.gather(x, n, settings.final_gather_rays, ctx, geometric_n, &samples);
    RecordGather<S> result{first.irradiance, first.harmonic_distance, {}};
    const double wanted = settings.cache_gather_noise;
    if (wanted > 0) {
        const double noise = gather_relative_noise<S>(samples, strata), cells = strata.count();
        const double extra = std::min(double(cache_gather_max_factor - 1) * cells,
                                      cells * ((noise / wanted) * (noise / wanted) - 1));
        const std::optional<Vec3<S>> below = geometric_n == n ? std::nullopt : std::optional<Vec3<S>>(geometric_n);
        if (noise > wanted && extra >= 1 &&
            regather_varying_cells(integrator, x, frame, below, strata, extra, ctx, samples)) {
            Rgb<S> sum(S(0));
            for (const GatherSample<S>& s : samples) sum += s.radiance;
            result.irradiance = sum * (pi<S> / S(strata.count()));
            result.gathered_again = true;
        }
    }
    result.gradients = irradiance_gradients<S>(samples, strata, frame);
    return result;
}

template <class SceneT>
[[nodiscard]] IrradianceCache build_irradiance_cache(const SceneT& scene,
                                                     const Camera<typename SceneT::scalar_type>& camera,
                                                     const PhotonMaps& maps, const RenderSettings& settings,
                                                     RenderStats& stats, const std::vector<bool>& lights_reaching = {}) {
    using S = typename SceneT::scalar_type;
    const auto start = std::chrono::steady_clock::now();
    // The lights the image pass shadow-tests: a gather's near hits take direct light from them.
    const RadianceIntegrator<SceneT> integrator(scene, maps, settings, lights_reaching);
    const float error = settings.irradiance_cache_error;
    // Size of one pixel at unit distance; the validity radius a * R of a record is kept between
    // min and max pixels at the distance the camera sees it from (Tabellion and Lamorlette 2004).
    // The pixels are those of an image at least `cache_reference_width` wide: in a small image a
    // pixel spans much of the scene, and records valid over 1.5 to 24 of them smoothed indirect
    // light across corners, reading them dark (docs/design.md, 'Measurements behind the code's
    // choices'). Small images then gather more often, which they can afford.
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
            std::uint64_t regathered = 0;
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
                    if (cache.covers(xf, nf, ctx.nearest)) return;
                    if (!mine.empty() && IrradianceCache(mine, error).covers(xf, nf, ctx.nearest)) return;
                    const RecordGather<S> g = gather_record(integrator, x, n, geometric_n, settings, ctx, samples);
                    const S footprint = pixel.size + length * pixel.angle;
                    const S r = std::clamp(g.harmonic_distance, S(1.5) * footprint / S(error),
                                           S(24) * footprint / S(error));
                    IrradianceRecord record{xf, nf, Rgb<float>(g.irradiance), float(r), g.gradients};
                    if (g.gathered_again) ++regathered;
                    limit_translation_gradient(record);
                    mine.push_back(record);
                });
            }
            const std::lock_guard lock(merge);
            stats.rays += ctx.rays;
            stats.cache_regathered += regathered;
        });
        share_lists(settings.share, found, "irradiance cache", Deal::hashed);  // every rank sees every record
        for (auto& list : found) records.insert(records.end(), list.begin(), list.end());
        // Not after the last level: the radii it would shrink there leave holes that no level
        // fills, and every image sample landing in one gathers in full (more gather rays for the
        // same picture: docs/design.md, 'Irradiance cache').
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
