// SPDX-License-Identifier: MIT
#pragma once
// Kernels that weight photons by their distance in a density estimate (Jensen 2001, section
// 7.2.1). Each is normalised so that its mean over the disc is 1: a uniform photon density
// gives the same estimate with any filter, only the blur differs.

#include <cmath>

namespace photon {

enum class Filter {
    none,      ///< box: every photon in the disc counts fully (the paper's estimate)
    cone,      ///< w = 1 - d / (k r) with k = cone_k (Jensen's cone filter)
    gaussian,  ///< Pavicic's Gaussian, alpha = 0.918, beta = 1.953
};

struct FilterKernel {
    Filter filter = Filter::none;
    float cone_k = 1.1f;  ///< >= 1; 1 gives a weight of 0 at the rim

    /// Weight of a photon at squared relative distance t2 = (d / r)^2 in [0, 1], before
    /// normalisation.
    [[nodiscard]] float weight(float t2) const noexcept {
        switch (filter) {
        case Filter::cone: return 1.0f - std::sqrt(t2) / cone_k;
        case Filter::gaussian: return alpha * (1.0f - (1.0f - std::exp(-beta * t2 * 0.5f)) / (1.0f - std::exp(-beta)));
        case Filter::none: break;
        }
        return 1.0f;
    }
    /// Mean of weight() over the unit disc, in closed form.
    [[nodiscard]] float mean_weight() const noexcept {
        switch (filter) {
        case Filter::cone: return 1.0f - 2.0f / (3.0f * cone_k);
        case Filter::gaussian: {
            const float mean_exp = (1.0f - std::exp(-beta * 0.5f)) / (beta * 0.5f);  // mean of e^(-beta t2 / 2)
            return alpha * (1.0f - (1.0f - mean_exp) / (1.0f - std::exp(-beta)));
        }
        case Filter::none: break;
        }
        return 1.0f;
    }

    static constexpr float alpha = 0.918f, beta = 1.953f;
};

}  // namespace photon
