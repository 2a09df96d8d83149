// SPDX-License-Identifier: MIT
#pragma once
// Region statistics of two linear renders of one scene, shared by photon-compare
// (tools/compare_renders.cpp) and the scene-class gallery test (tests/classes): means over a grid
// of image blocks, the RMSE of block means, and the worst relative bias of region means. Per-pixel
// noise averages away in a region; low-frequency bias (light lost or gained) does not.

#include <photon/film/film.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <stdexcept>
#include <string>
#include <vector>

namespace photon::regions {

/// The mean of the three channels: the brightness a region's bias is measured on.
[[nodiscard]] inline double channel_mean(const Rgb<double>& c) noexcept { return (c.x + c.y + c.z) / 3.0; }

/// Mean radiance of each block of a `columns` x `rows` grid over the image, row by row from the
/// top left. Block (i, j) covers pixel columns [i W / columns, (i + 1) W / columns) and likewise
/// for rows, so every pixel is in exactly one block even when the sizes do not divide.
[[nodiscard]] inline std::vector<Rgb<double>> grid_means(const Film& film, unsigned columns, unsigned rows) {
    if (columns == 0 || rows == 0 || columns > film.width() || rows > film.height())
        throw std::invalid_argument("grid_means: a " + std::to_string(columns) + " x " + std::to_string(rows) +
                                    " grid does not fit a " + std::to_string(film.width()) + " x " +
                                    std::to_string(film.height()) + " image");
    std::vector<Rgb<double>> means(std::size_t(columns) * rows, Rgb<double>(0.0));
    for (unsigned j = 0; j < rows; ++j) {
        const unsigned y0 = j * film.height() / rows, y1 = (j + 1) * film.height() / rows;
        for (unsigned i = 0; i < columns; ++i) {
            const unsigned x0 = i * film.width() / columns, x1 = (i + 1) * film.width() / columns;
            Rgb<double> sum(0.0);
            for (unsigned y = y0; y < y1; ++y)
                for (unsigned x = x0; x < x1; ++x) sum += Rgb<double>(film.at(x, y));
            means[std::size_t(j) * columns + i] = sum / (double(x1 - x0) * double(y1 - y0));
        }
    }
    return means;
}

/// RMSE over channels of the means of whole `n` x `n` blocks of A and B (same size; a partial
/// block at the right or bottom edge is left out).
[[nodiscard]] inline double block_rmse(const Film& a, const Film& b, unsigned n) {
    double squared = 0.0;
    std::size_t blocks = 0;
    for (unsigned by = 0; by + n <= a.height(); by += n)
        for (unsigned bx = 0; bx + n <= a.width(); bx += n) {
            Rgb<double> d(0.0);
            for (unsigned y = by; y < by + n; ++y)
                for (unsigned x = bx; x < bx + n; ++x) d += Rgb<double>(a.at(x, y)) - Rgb<double>(b.at(x, y));
            d /= double(n) * double(n);
            squared += glm::dot(d, d);
            ++blocks;
        }
    return blocks == 0 ? 0.0 : std::sqrt(squared / (3.0 * double(blocks)));
}

/// The region whose mean is furthest from the reference's, as a / b - 1 of the channel means.
struct WorstBias {
    int region = -1;     ///< -1: no region qualified
    double bias = 0.0;   ///< signed: negative when A is darker
};

/// Regions that hold more than `min_light_fraction` of the reference's light (its channel means,
/// weighted by `sizes`: the pixels in each region; all 1 for equal blocks).
[[nodiscard]] inline std::vector<bool> lit_regions(const std::vector<Rgb<double>>& reference,
                                                   const std::vector<double>& sizes, double min_light_fraction) {
    double total = 0.0;
    for (std::size_t r = 0; r < reference.size(); ++r) total += channel_mean(reference[r]) * sizes[r];
    std::vector<bool> lit(reference.size(), false);
    for (std::size_t r = 0; r < reference.size(); ++r)
        lit[r] = total > 0.0 && channel_mean(reference[r]) * sizes[r] > min_light_fraction * total;
    return lit;
}

/// The largest |a / b - 1| over the regions marked in `counted` (all when empty) whose reference
/// mean is positive.
[[nodiscard]] inline WorstBias worst_bias(const std::vector<Rgb<double>>& a, const std::vector<Rgb<double>>& b,
                                          const std::vector<bool>& counted = {}) {
    WorstBias worst;
    for (std::size_t r = 0; r < a.size(); ++r) {
        const double mb = channel_mean(b[r]);
        if ((!counted.empty() && !counted[r]) || !(mb > 0.0)) continue;
        const double bias = channel_mean(a[r]) / mb - 1.0;
        if (worst.region < 0 || std::abs(bias) > std::abs(worst.bias)) worst = {int(r), bias};
    }
    return worst;
}

/// Noise of the mean of two independent renders A and B of equal variance, relative to it, from
/// their difference: (a - b) / 2 has the variance of (a + b) / 2, so (a - b) / (a + b) is one draw
/// of the mean's relative error. Returns the root mean square over the counted regions (the
/// noise's standard deviation) and the largest value (what the worst of them showed).
struct RelativeNoise {
    double rms = 0.0, max = 0.0;
};

[[nodiscard]] inline RelativeNoise noise_of_mean(const std::vector<Rgb<double>>& a, const std::vector<Rgb<double>>& b,
                                                 const std::vector<bool>& counted) {
    RelativeNoise noise;
    double squared = 0.0;
    std::size_t n = 0;
    for (std::size_t r = 0; r < a.size(); ++r) {
        const double sum = channel_mean(a[r]) + channel_mean(b[r]);
        if (!counted[r] || !(sum > 0.0)) continue;
        const double d = std::abs(channel_mean(a[r]) - channel_mean(b[r])) / sum;
        squared += d * d;
        noise.max = std::max(noise.max, d);
        ++n;
    }
    noise.rms = n == 0 ? 0.0 : std::sqrt(squared / double(n));
    return noise;
}

}  // namespace photon::regions
