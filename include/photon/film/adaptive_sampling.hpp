// SPDX-License-Identifier: MIT
#pragma once
// Adaptive anti-aliasing's stopping rule: a pixel takes another round of samples while the
// standard error of its mean luminance, relative to that mean, is above a threshold. The rule
// reads the pixel's own samples only, so the decision (and the image) does not depend on how the
// pixels are shared among threads or processes.

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "../math/vec.hpp"

namespace photon {

/// Mean and variance of values seen one at a time (Welford): no cancellation when the values are
/// large and close, as a bright flat wall's are.
class RunningStats {
public:
    void add(double x) noexcept {
        ++n_;
        const double d = x - mean_;
        mean_ += d / double(n_);
        m2_ += d * (x - mean_);
    }
    [[nodiscard]] unsigned count() const noexcept { return n_; }
    [[nodiscard]] double mean() const noexcept { return mean_; }
    /// The unbiased sample variance (0 for fewer than two values).
    [[nodiscard]] double variance() const noexcept { return n_ > 1 ? m2_ / double(n_ - 1) : 0.0; }
    /// Of the mean.
    [[nodiscard]] double standard_error() const noexcept { return n_ > 0 ? std::sqrt(variance() / double(n_)) : 0.0; }

private:
    unsigned n_ = 0;
    double mean_ = 0, m2_ = 0;
};

struct AdaptiveRule {
    double threshold = 0;       ///< largest relative standard error of a pixel's mean; 0: never more
    unsigned max_samples = 16;  ///< a pixel's samples, base included
    /// Luminance below which the error is measured against this instead of the mean: a black pixel
    /// (no variance) stops at once, a nearly black one once its noise is below threshold * floor
    /// rather than chasing a vanishing mean (1/256: an 8-bit step of white).
    double floor = 1.0 / 256.0;
};

/// Whether a pixel whose samples gave `seen` should take a round of `round` more samples: while
/// the round fits under `rule.max_samples` and the relative standard error is above the
/// threshold. One sample says nothing of the noise: it takes another round.
[[nodiscard]] inline bool needs_more(const RunningStats& seen, const AdaptiveRule& rule, unsigned round) noexcept {
    if (!(rule.threshold > 0) || round == 0) return false;
    if (std::uint64_t(seen.count()) + round > rule.max_samples) return false;
    if (seen.count() < 2) return true;
    return seen.standard_error() > rule.threshold * std::max(std::abs(seen.mean()), rule.floor);
}

/// A colour as POV-Ray compares pixels for anti-aliasing (tracetask.cpp, Antialias_Gamma 2.5):
/// each channel encoded as v^(1/2.5), so that a step in the shadows counts about as much as an
/// equally visible one in the highlights.
[[nodiscard]] inline Rgb<float> contrast_encoded(const Rgb<float>& c) noexcept {
    Rgb<float> e;
    for (int i = 0; i < 3; ++i) e[i] = c[i] > 0.0f ? std::pow(c[i], 1.0f / 2.5f) : 0.0f;
    return e;
}

/// How much two pixels differ, encoded by contrast_encoded: POV-Ray's Colour_Distance, the sum
/// of the three channels' differences (its Antialias_Threshold, 0.3 by default, is a bound on it).
[[nodiscard]] inline float colour_contrast(const Rgb<float>& a, const Rgb<float>& b) noexcept {
    return std::abs(a[0] - b[0]) + std::abs(a[1] - b[1]) + std::abs(a[2] - b[2]);
}

}  // namespace photon
