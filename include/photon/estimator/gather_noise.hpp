// SPDX-License-Identifier: MIT
#pragma once
// How noisy one stratified final gather is, and where, from its own samples. A gather takes one
// sample per (theta, phi) cell, so the spread within a cell is not observed; the difference of
// two neighbouring cells stands in for it. For cells a and b,
// E[(L_a - L_b)^2] = var_a + var_b + (mean_a - mean_b)^2 >= var_a + var_b, so the squared
// differences of disjoint pairs of neighbours over-estimate the variance of the gather's sum:
// the estimate errs towards gathering more (measured on room 1: 1.4x the noise of repeated
// gathers, median). The irradiance cache gathers a record again where it is above what it wants,
// with the new rays in the cells that vary (integrator/irradiance_cache_pass.hpp).

#include <algorithm>
#include <cmath>
#include <limits>
#include <span>
#include <vector>

#include "irradiance_gradients.hpp"

namespace photon {

template <Scalar S> [[nodiscard]] double gather_luminance(const Rgb<S>& l) {
    return 0.2126 * double(l[0]) + 0.7152 * double(l[1]) + 0.0722 * double(l[2]);
}

/// Each cell's variance (of luminance), from a pair of neighbours it belongs to: half the pair's
/// squared difference for each. `along_phi`: the pairs (0, 1), (2, 3), ... of each row (an odd
/// column out paired with the one before it); else the same down each column, in theta. Empty
/// when the samples are not one per cell of `strata` or no such pair exists.
template <Scalar S>
[[nodiscard]] std::vector<double> gather_cell_variances(std::span<const GatherSample<S>> samples,
                                                        GatherStrata strata, bool along_phi = true) {
    const unsigned m = strata.rows, n = strata.columns;
    const unsigned lines = along_phi ? m : n, length = along_phi ? n : m;
    if (samples.size() != std::size_t(m) * n || length < 2) return {};
    const auto index = [&](unsigned line, unsigned i) {
        return along_phi ? std::size_t(line) * n + i : std::size_t(i) * n + line;
    };
    std::vector<double> variance(samples.size(), 0.0);
    const auto at = [&](std::size_t c) { return gather_luminance(samples[c].radiance); };
    for (unsigned line = 0; line < lines; ++line) {
        for (unsigned i = 0; i + 1 < length; i += 2) {
            const double d = at(index(line, i)) - at(index(line, i + 1));
            variance[index(line, i)] = variance[index(line, i + 1)] = d * d / 2;
        }
        if (length % 2 == 1) {
            const double d = at(index(line, length - 1)) - at(index(line, length - 2));
            variance[index(line, length - 1)] = d * d / 2;
        }
    }
    return variance;
}

/// The relative standard error of the irradiance of one gather whose samples are stored row by
/// row (GatherStrata order): 0 for a gather that brought nothing (no light, nothing to refine),
/// infinity when there are too few cells to pair.
template <Scalar S>
[[nodiscard]] double gather_relative_noise(std::span<const GatherSample<S>> samples, GatherStrata strata) {
    // Pairs in phi miss an edge that runs along a row (a window's sill seen from below), pairs in
    // theta one down a column: both are over-estimates, so the larger is kept.
    double total_variance = 0;
    bool paired = false;
    for (const bool along_phi : {true, false}) {
        const std::vector<double> variance = gather_cell_variances<S>(samples, strata, along_phi);
        if (variance.empty()) continue;
        paired = true;
        double sum = 0;
        for (const double v : variance) sum += v;
        total_variance = std::max(total_variance, sum);
    }
    if (!paired) return std::numeric_limits<double>::infinity();
    double sum = 0;
    for (const GatherSample<S>& s : samples) sum += gather_luminance(s.radiance);
    if (!(sum > 0)) return 0;
    return std::sqrt(total_variance) / sum;
}

}  // namespace photon
