// SPDX-License-Identifier: MIT
#pragma once
// How far a stochastic render is from converged, estimated from two independent half-images A
// and B of the same scene (disjoint samples, passes or photon sets; Cycles' half buffers, the
// noise term of Hachisuka, Jarosz and Jensen 2010). The image is their mean M = (A + B) / 2;
// (A - B) / 2 has the variance of M's noise, so ((A - B) / 2)^2 is an unbiased draw of each
// pixel's squared error, and its sums over pixels estimate the image's. Bias shared by both
// halves (a photon map's blur, a radius not yet shrunk) is not seen: the estimate is of noise.
//
// Figures, all relative, so they read the same at any exposure and scene scale:
// * normalised MSE: sum over pixels and channels of the squared error, over the sum of M^2 (the
//   image's mean square, its own noise taken out); the relative RMSE is its square root;
// * blocks: the image cut into a grid (8 x 8 by default) whose blocks holding more than 1% of the
//   light count; each block's mean has relative error (mean(A) - mean(B)) / (mean(A) + mean(B)),
//   whose root mean square over the blocks and largest value are reported (the low-frequency
//   error that per-pixel noise hides, as tools/region_statistics.hpp measures against a judge).

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <stdexcept>
#include <string>
#include <vector>

#include "../math/rng.hpp"
#include "film.hpp"

namespace photon {

/// The estimated error of the mean of two half-images.
struct ErrorEstimate {
    bool available = false;      ///< false: the render had no two independent halves
    double normalised_mse = 0;   ///< squared error over the image's squared radiance
    double relative_rmse = 0;    ///< sqrt(normalised_mse)
    double block_rms = 0;        ///< rms relative error of the counted blocks' means
    double worst_block = 0;      ///< largest relative error of a counted block's mean
    unsigned worst_block_column = 0, worst_block_row = 0;  ///< its place in the grid, from the top left
    unsigned blocks_counted = 0;
    unsigned grid = 8;  ///< the grid is grid x grid blocks (fewer when the image is smaller)
    /// Against a judge (estimate_error_against): its sppm passes (0: the estimate is of the
    /// image's own halves), its own noise's normalised MSE, subtracted, and whether the error
    /// left was smaller than the floor (judge_noise / 100) it was clamped to.
    unsigned judge_passes = 0;
    double judge_noise = 0;
    /// Against a judge: twice the standard error of the normalised MSE, the least it resolves;
    /// at_floor: the error was below it, and normalised_mse holds the upper bound ("below").
    double resolution = 0;
    bool at_floor = false;
    unsigned judge_stride = 1;  ///< the judge rendered one pixel of each judge_stride^2 (in_pixel_subset)
};

/// The half-images' mean, the rendered image: weighted by the samples (passes) each holds.
[[nodiscard]] inline Film combine_halves(const Film& a, const Film& b, double weight_a = 1, double weight_b = 1) {
    if (a.width() != b.width() || a.height() != b.height())
        throw std::invalid_argument("combine_halves: the half-images differ in size");
    Film m(a.width(), a.height());
    const double wa = weight_a / (weight_a + weight_b), wb = weight_b / (weight_a + weight_b);
    for (std::size_t i = 0; i < m.pixels().size(); ++i)
        m.pixels()[i] = Rgb<float>(Rgb<double>(a.pixels()[i]) * wa + Rgb<double>(b.pixels()[i]) * wb);
    return m;
}

namespace detail {
/// The block figures of `e` (rms, worst, blocks counted) from the halves' light per block: blocks
/// with more than 1% of the light count, each with the relative error `relative(k, light)`.
template <class Relative>
void summarise_blocks(ErrorEstimate& e, const std::vector<double>& sum_a, const std::vector<double>& sum_b,
                      Relative&& relative) {
    double total = 0;
    for (std::size_t k = 0; k < sum_a.size(); ++k) total += sum_a[k] + sum_b[k];
    double squared = 0;
    for (std::size_t k = 0; k < sum_a.size(); ++k) {
        const double light = sum_a[k] + sum_b[k];
        if (!(total > 0) || !(light > 0.01 * total)) continue;
        const double r = relative(k, light);
        squared += r * r;
        ++e.blocks_counted;
        if (r >= e.worst_block) {
            e.worst_block = r;
            e.worst_block_column = unsigned(k % e.grid);
            e.worst_block_row = unsigned(k / e.grid);
        }
    }
    if (e.blocks_counted > 0) e.block_rms = std::sqrt(squared / double(e.blocks_counted));
}
}  // namespace detail

/// The error estimate of (A + B) / 2 from its halves A and B.
[[nodiscard]] inline ErrorEstimate estimate_error(const Film& a, const Film& b, unsigned grid = 8) {
    if (a.width() != b.width() || a.height() != b.height())
        throw std::invalid_argument("estimate_error: the half-images differ in size");
    ErrorEstimate e;
    e.available = true;
    double squared_error = 0, squared_mean = 0;
    for (std::size_t i = 0; i < a.pixels().size(); ++i) {
        const Rgb<double> pa(a.pixels()[i]), pb(b.pixels()[i]);
        const Rgb<double> half_difference = (pa - pb) * 0.5, mean = (pa + pb) * 0.5;
        const double d2 = glm::dot(half_difference, half_difference);
        squared_error += d2;
        squared_mean += glm::dot(mean, mean) - d2;  // E[M^2] = truth^2 + noise variance
    }
    if (squared_mean > 0) {
        e.normalised_mse = squared_error / squared_mean;
        e.relative_rmse = std::sqrt(e.normalised_mse);
    }

    e.grid = std::min({grid, a.width(), a.height()});
    if (e.grid == 0) return e;
    std::vector<double> sum_a(std::size_t(e.grid) * e.grid, 0.0), sum_b(sum_a.size(), 0.0);
    for (unsigned y = 0; y < a.height(); ++y) {
        const unsigned row = y * e.grid / a.height();
        for (unsigned x = 0; x < a.width(); ++x) {
            const std::size_t block = std::size_t(row) * e.grid + x * e.grid / a.width();
            const Rgb<float>& pa = a.at(x, y);
            const Rgb<float>& pb = b.at(x, y);
            sum_a[block] += double(pa.x) + pa.y + pa.z;
            sum_b[block] += double(pb.x) + pb.y + pb.z;
        }
    }
    detail::summarise_blocks(e, sum_a, sum_b, [&](std::size_t k, double light) {
        return std::abs(sum_a[k] - sum_b[k]) / light;
    });
    return e;
}

/// Whether pixel (x, y) is the one of its `stride` x `stride` tile that a judge on a subset of
/// the pixels renders (sppm's sppm_pixel_stride): one per tile, at a place hashed from the tile,
/// so that the subset follows no row, column or diagonal of the scene. Every pixel for stride 1.
[[nodiscard]] inline bool in_pixel_subset(unsigned x, unsigned y, unsigned stride) noexcept {
    if (stride <= 1) return true;
    const std::uint64_t tile = (std::uint64_t(y / stride) << 32) | (x / stride);
    const std::uint64_t pick = mix64(tile ^ 0x7375627365747069ULL) % (std::uint64_t(stride) * stride);
    return x % stride == pick % stride && y % stride == pick / stride;
}

/// Pixels per side of the tiles whose sums give the estimate's own uncertainty: wider than the
/// judge's photon radius (2 pixels at its start), so that noise shared by neighbours stays in one.
inline constexpr unsigned error_resolution_tile = 8;

/// The error of `image`, noise and bias alike, against a consistent judge that is the mean of
/// two independent halves A and B (a short sppm run, integrator/pm_error.hpp): with J = (A + B) / 2
/// and truth T, E|image - J|^2 = |image - T|^2 + E|J - T|^2, and ((A - B) / 2)^2 estimates the last
/// term, so their difference estimates the image's squared error. Only the pixels of the judge's
/// subset count (in_pixel_subset, `stride`). Summed over the image and over each block's mean as
/// estimate_error does.
///
/// The difference of two sums is itself uncertain: it is resolved only when it is more than twice
/// its standard error. Per pixel, D = (image - A)^2 - (image - B)^2 has mean zero and, for
/// Gaussian noise, four times the variance of the estimate's own term (with image - T = b and
/// the halves' noises of variance s^2: 8 b^2 s^2 + 4 s^4 against 2 b^2 s^2 + s^4), so the sum of
/// D over each tile of error_resolution_tile^2 subset pixels, squared and summed over the tiles,
/// is four times the estimate's variance: neighbours that share the judge's photons stay in one
/// tile, and the error's own variation over the image does not enter. An unresolved estimate is
/// marked at_floor and reports its upper bound, max(0, difference) plus twice the standard error:
/// "below X". `*error_film`, if given: per pixel and channel
/// sqrt(max(0, (image - J)^2 - ((A - B) / 2)^2)), noisy where the judge is; zero off the subset.
[[nodiscard]] inline ErrorEstimate estimate_error_against(const Film& image, const Film& a, const Film& b,
                                                          unsigned judge_passes, unsigned grid = 8,
                                                          Film* error_film = nullptr, unsigned stride = 1) {
    if (a.width() != b.width() || a.height() != b.height() || image.width() != a.width() || image.height() != a.height())
        throw std::invalid_argument("estimate_error_against: the images differ in size");
    ErrorEstimate e;
    e.available = true;
    e.judge_passes = judge_passes;
    e.judge_stride = std::max(1u, stride);
    if (error_film) *error_film = Film(a.width(), a.height());
    const unsigned tile = error_resolution_tile * std::max(1u, stride);
    const unsigned tile_columns = (a.width() + tile - 1) / tile, tile_rows = (a.height() + tile - 1) / tile;
    std::vector<double> tile_split(std::size_t(tile_columns) * tile_rows, 0.0);  // sums of D
    double squared_difference = 0, squared_noise = 0, squared_judge = 0;
    for (unsigned y = 0; y < a.height(); ++y)
        for (unsigned x = 0; x < a.width(); ++x) {
            if (!in_pixel_subset(x, y, stride)) continue;
            const std::size_t i = std::size_t(y) * a.width() + x;
            const Rgb<double> pa(a.pixels()[i]), pb(b.pixels()[i]), p(image.pixels()[i]);
            const Rgb<double> judge = (pa + pb) * 0.5, noise = (pa - pb) * 0.5, difference = p - judge;
            const double n2 = glm::dot(noise, noise), d2 = glm::dot(difference, difference);
            squared_difference += d2;
            squared_noise += n2;
            squared_judge += glm::dot(judge, judge) - n2;
            const Rgb<double> from_a = p - pa, from_b = p - pb;
            tile_split[std::size_t(y / tile) * tile_columns + x / tile] += glm::dot(from_a, from_a) - glm::dot(from_b, from_b);
            if (error_film) {
                const Rgb<double> left = glm::max(difference * difference - noise * noise, Rgb<double>(0.0));
                error_film->pixels()[i] = Rgb<float>(glm::sqrt(left));
            }
        }
    if (squared_judge > 0) {
        e.judge_noise = squared_noise / squared_judge;
        const double net = (squared_difference - squared_noise) / squared_judge;
        // Twice the standard error: 2 sqrt(sum D^2 / 4).
        double split_squared = 0;
        for (const double t : tile_split) split_squared += t * t;
        e.resolution = std::sqrt(split_squared) / squared_judge;
        const double resolution = e.resolution;
        e.normalised_mse = net;
        if (net < resolution) e.normalised_mse = std::max(0.0, net) + resolution, e.at_floor = true;
        e.relative_rmse = std::sqrt(e.normalised_mse);
    }

    e.grid = std::min({grid, a.width(), a.height()});
    if (e.grid == 0) return e;
    const std::size_t blocks = std::size_t(e.grid) * e.grid;
    std::vector<double> sum_image(blocks, 0.0), sum_a(blocks, 0.0), sum_b(blocks, 0.0);
    for (unsigned y = 0; y < a.height(); ++y) {
        const unsigned row = y * e.grid / a.height();
        for (unsigned x = 0; x < a.width(); ++x) {
            if (!in_pixel_subset(x, y, stride)) continue;
            const std::size_t block = std::size_t(row) * e.grid + x * e.grid / a.width();
            auto sum = [](const Rgb<float>& p) { return double(p.x) + p.y + p.z; };
            sum_image[block] += sum(image.at(x, y));
            sum_a[block] += sum(a.at(x, y));
            sum_b[block] += sum(b.at(x, y));
        }
    }
    detail::summarise_blocks(e, sum_a, sum_b, [&](std::size_t k, double light) {
        const double difference = (2 * sum_image[k] - light) / light, noise = (sum_a[k] - sum_b[k]) / light;
        return std::sqrt(std::max(0.0, difference * difference - noise * noise));
    });
    return e;
}

/// Each pixel's estimated error |A - B| / 2 per channel: where the noise is.
[[nodiscard]] inline Film error_image(const Film& a, const Film& b) {
    if (a.width() != b.width() || a.height() != b.height())
        throw std::invalid_argument("error_image: the half-images differ in size");
    Film e(a.width(), a.height());
    for (std::size_t i = 0; i < e.pixels().size(); ++i)
        e.pixels()[i] = glm::abs(a.pixels()[i] - b.pixels()[i]) * 0.5f;
    return e;
}

/// "1.23% (normalised MSE 1.5e-04); 8x8 blocks: rms 0.41%, worst 1.1% at block 3,5", or why
/// there is no estimate.
[[nodiscard]] inline std::string format_error_estimate(const ErrorEstimate& e) {
    if (!e.available) return "not estimated (no two independent half-images: one pass, or one sample per pixel)";
    char line[200];
    std::snprintf(line, sizeof line, "relative RMSE %s%.3g%% (normalised MSE %.3g); %ux%u blocks: rms %.3g%%, worst %.3g%% at %u,%u",
                  e.at_floor ? "below " : "", 100 * e.relative_rmse, e.normalised_mse, e.grid, e.grid, 100 * e.block_rms,
                  100 * e.worst_block, e.worst_block_column, e.worst_block_row);
    std::string text = line;
    if (e.judge_passes > 0) {
        std::snprintf(line, sizeof line, "; against a short sppm run of %u passes", e.judge_passes);
        text += line;
        if (e.judge_stride > 1) {
            std::snprintf(line, sizeof line, " on one pixel in %u", e.judge_stride * e.judge_stride);
            text += line;
        }
        std::snprintf(line, sizeof line, ", whose own noise, normalised MSE %.3g, is subtracted (resolving %.3g)",
                      e.judge_noise, e.resolution);
        text += line;
    }
    return text;
}

}  // namespace photon
