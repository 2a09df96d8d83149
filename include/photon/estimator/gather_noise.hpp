// SPDX-License-Identifier: MIT
#pragma once
// How noisy one stratified final gather is, from its own samples. A gather takes one sample per
// (theta, phi) cell, so the spread within a cell is not observed; the difference of two
// neighbouring cells stands in for it. For cells a and b,
// E[(L_a - L_b)^2] = var_a + var_b + (mean_a - mean_b)^2 >= var_a + var_b, so the squared
// differences of disjoint pairs of neighbours over-estimate the variance of the gather's sum: the
// estimate errs towards gathering more (by how much: docs/design.md, 'Irradiance cache'). The
// irradiance cache gathers a record again where it is above what it wants (gather_record,
// integrator/irradiance_cache_pass.hpp).

#include <algorithm>
#include <cmath>
#include <limits>
#include <span>

#include "irradiance_gradients.hpp"

namespace photon {

/// The summed variance (of luminance) of a gather's cells, stored row by row, from disjoint pairs
/// of neighbours, half a pair's squared difference for each of its two cells. `along_phi`: the
/// pairs (0, 1), (2, 3), ... of each row, an odd column out paired with the one before it; else
/// the same down each column, in theta. Negative when there is no such pair.
template <Scalar S>
[[nodiscard]] double gather_pair_variance(std::span<const GatherSample<S>> samples, GatherStrata strata,
                                          bool along_phi) {
    const unsigned n = strata.columns;
    const unsigned lines = along_phi ? strata.rows : n, length = along_phi ? n : strata.rows;
    if (length < 2) return -1;
    const auto at = [&](unsigned line, unsigned i) {
        return luminance(samples[along_phi ? std::size_t(line) * n + i : std::size_t(i) * n + line].radiance);
    };
    double total = 0;
    for (unsigned line = 0; line < lines; ++line) {
        for (unsigned i = 0; i + 1 < length; i += 2) {
            const double d = at(line, i) - at(line, i + 1);
            total += d * d;  // d^2 / 2 for each of the two cells
        }
        if (length % 2 == 1) {
            const double d = at(line, length - 1) - at(line, length - 2);
            total += d * d / 2;
        }
    }
    return total;
}

/// The relative standard error of the irradiance of one gather whose samples are stored row by
/// row (GatherStrata order): 0 for a gather that brought nothing (no light, nothing to refine),
/// infinity when the samples are not one per cell or there are too few cells to pair.
template <Scalar S>
[[nodiscard]] double gather_relative_noise(std::span<const GatherSample<S>> samples, GatherStrata strata) {
    if (samples.size() != std::size_t(strata.count())) return std::numeric_limits<double>::infinity();
    // Pairs in phi miss an edge that runs along a row (a window's sill seen from below), pairs in
    // theta one down a column: both are over-estimates, so the larger is kept.
    const double variance = std::max(gather_pair_variance<S>(samples, strata, true),
                                     gather_pair_variance<S>(samples, strata, false));
    if (variance < 0) return std::numeric_limits<double>::infinity();
    double sum = 0;
    for (const GatherSample<S>& s : samples) sum += luminance(s.radiance);
    if (!(sum > 0)) return 0;
    return std::sqrt(variance) / sum;
}

}  // namespace photon
