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
#include <cstdio>
#include <stdexcept>
#include <string>
#include <vector>

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
    bool at_floor = false;
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

/// The error of `image`, noise and bias alike, against a consistent judge that is the mean of
/// two independent halves A and B (a short sppm run, integrator/pm_error.hpp): with J = (A + B) / 2
/// and truth T, E|image - J|^2 = |image - T|^2 + E|J - T|^2, and ((A - B) / 2)^2 estimates the last
/// term, so their difference estimates the image's squared error. Summed over the image and over
/// each block's mean as estimate_error does; a sum left below 1% of the judge's noise (the
/// subtraction cannot resolve less) is clamped there and marked. `*error_film`, if given: per
/// pixel and channel sqrt(max(0, (image - J)^2 - ((A - B) / 2)^2)), noisy where the judge is.
[[nodiscard]] inline ErrorEstimate estimate_error_against(const Film& image, const Film& a, const Film& b,
                                                          unsigned judge_passes, unsigned grid = 8,
                                                          Film* error_film = nullptr) {
    if (a.width() != b.width() || a.height() != b.height() || image.width() != a.width() || image.height() != a.height())
        throw std::invalid_argument("estimate_error_against: the images differ in size");
    ErrorEstimate e;
    e.available = true;
    e.judge_passes = judge_passes;
    if (error_film) *error_film = Film(a.width(), a.height());
    double squared_difference = 0, squared_noise = 0, squared_judge = 0;
    for (std::size_t i = 0; i < a.pixels().size(); ++i) {
        const Rgb<double> pa(a.pixels()[i]), pb(b.pixels()[i]), p(image.pixels()[i]);
        const Rgb<double> judge = (pa + pb) * 0.5, noise = (pa - pb) * 0.5, difference = p - judge;
        const double n2 = glm::dot(noise, noise);
        squared_difference += glm::dot(difference, difference);
        squared_noise += n2;
        squared_judge += glm::dot(judge, judge) - n2;
        if (error_film) {
            const Rgb<double> left = glm::max(difference * difference - noise * noise, Rgb<double>(0.0));
            error_film->pixels()[i] = Rgb<float>(glm::sqrt(left));
        }
    }
    if (squared_judge > 0) {
        e.judge_noise = squared_noise / squared_judge;
        const double floor = e.judge_noise / 100;
        e.normalised_mse = (squared_difference - squared_noise) / squared_judge;
        if (e.normalised_mse < floor) e.normalised_mse = floor, e.at_floor = true;
        e.relative_rmse = std::sqrt(e.normalised_mse);
    }

    e.grid = std::min({grid, a.width(), a.height()});
    if (e.grid == 0) return e;
    const std::size_t blocks = std::size_t(e.grid) * e.grid;
    std::vector<double> sum_image(blocks, 0.0), sum_a(blocks, 0.0), sum_b(blocks, 0.0);
    for (unsigned y = 0; y < a.height(); ++y) {
        const unsigned row = y * e.grid / a.height();
        for (unsigned x = 0; x < a.width(); ++x) {
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
        std::snprintf(line, sizeof line, "; against a short sppm run of %u passes, whose own noise, normalised MSE %.3g, is subtracted",
                      e.judge_passes, e.judge_noise);
        text += line;
    }
    return text;
}

}  // namespace photon
