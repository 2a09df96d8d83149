// SPDX-License-Identifier: MIT
#pragma once
// Irradiance caching (Ward, Rubinstein and Clear 1988): final gathering is expensive and noisy
// per pixel, but indirect irradiance changes slowly, so it is computed with many rays at sparse
// records and interpolated between them. A record at x_i with normal n_i and harmonic mean
// distance R_i to the surfaces its rays met contributes at x with weight
//   w_i(x) = 1 / (|x - x_i| / R_i + sqrt(1 - n . n_i)),
// and is used where w_i > 1 / a (a: the allowed error). The cache is immutable once built; the
// renderer builds it level by level (integrator/irradiance_cache_pass.hpp).

#include <cmath>
#include <span>
#include <vector>

#include "../photonmap/kdtree.hpp"

namespace photon {

/// One cached final gather.
struct IrradianceRecord {
    Vec3<float> position;
    Vec3<float> normal;
    Rgb<float> irradiance;
    float harmonic_distance;  ///< R_i, already clamped to the allowed range of validity
};

class IrradianceCache {
public:
    IrradianceCache() = default;
    /// A cache over `records` for error bound `error` (Ward's a, typically 0.1 to 0.3).
    IrradianceCache(std::span<const IrradianceRecord> records, float error) : error_(error), tree_(records) {
        for (const auto& r : records) max_validity_ = std::max(max_validity_, error * r.harmonic_distance);
    }

    [[nodiscard]] std::size_t size() const noexcept { return tree_.size(); }
    [[nodiscard]] float error() const noexcept { return error_; }
    [[nodiscard]] std::size_t memory_bytes() const noexcept { return tree_.memory_bytes(); }

    /// Interpolated irradiance at x with unit normal n, or nothing if no record is valid there.
    /// `buffer` is per-thread scratch.
    [[nodiscard]] std::optional<Rgb<float>> interpolate(const Vec3<float>& x, const Vec3<float>& n,
                                                        std::vector<Neighbor<float>>& buffer) const {
        if (tree_.empty()) return std::nullopt;
        const auto found = tree_.within_radius(x, max_validity_, buffer);
        Rgb<float> sum(0.0f);
        float weights = 0.0f;
        const float threshold = 1.0f / error_;
        for (const Neighbor<float>& c : found) {
            const IrradianceRecord& r = tree_.payload(c.index);
            const float cos_n = glm::dot(n, r.normal);
            if (cos_n <= 0.9f) continue;
            // Ward's "in front" test: a record whose surface lies in front of x sees other light.
            if (glm::dot(x - r.position, r.normal + n) < -0.02f * r.harmonic_distance) continue;
            const float denom = std::sqrt(c.distance2) / r.harmonic_distance + std::sqrt(std::max(0.0f, 1.0f - cos_n));
            const float w = denom > 0.0f ? 1.0f / denom : 1e30f;
            if (!(w > threshold)) continue;
            const float wc = std::min(w, 1e6f);
            sum += wc * r.irradiance;
            weights += wc;
        }
        if (!(weights > 0.0f)) return std::nullopt;
        return sum / weights;
    }

private:
    float error_ = 0.25f;
    float max_validity_ = 0.0f;
    KdTree<IrradianceRecord> tree_;
};

}  // namespace photon
