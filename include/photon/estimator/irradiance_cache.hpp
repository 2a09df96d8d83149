// SPDX-License-Identifier: MIT
#pragma once
// Irradiance caching (Ward, Rubinstein and Clear 1988): final gathering is expensive and noisy
// per pixel, but indirect irradiance changes slowly, so it is computed with many rays at sparse
// records and interpolated between them. A record at x_i with normal n_i and harmonic mean
// distance R_i to the surfaces its rays met is valid at x where Ward's weight
//   w_i(x) = 1 / (|x - x_i| / R_i + sqrt(1 - n . n_i))
// exceeds 1 / a (a: the allowed error): where none is, the renderer gathers anew. Where one is,
// the records blend a little further, out to w_i > 1 / (s a) with s = cache_blend_reach, with
// weight w_i - 1 / (s a), which falls to 0 at the edge of that reach. Ward's own weight jumps
// there from 1 / a to 0, so the records entering and leaving the sum drew their domains' edges
// on the walls; the wider reach averages more records, and so more of their own noise, which a
// weight falling to 0 alone would average less (docs/design.md). Each record carries Ward and
// Heckbert's (1992) rotation and translation gradients (irradiance_gradients.hpp) and contributes
// to first order, E_i + (n_i x n) . grad_r + (x - x_i) . grad_t: at zeroth order the interpolated
// irradiance is flat around each record and bends only between records, which shows as blotches
// on every wall. Practical limits after Krivanek et al. (2006): each R_i is clamped by its
// neighbours' R_j + |x_i - x_j| (R is a distance to geometry: a record next to one that sees a
// wall close by cannot see it much further), and grad_t is limited so that R_i |grad_t| <= E_i
// (a gradient from a few noisy cells must not extrapolate to negative light). The cache is
// immutable once built; the renderer builds it level by level (integrator/irradiance_cache_pass.hpp).

#include <algorithm>
#include <cmath>
#include <span>
#include <vector>

#include "../photonmap/kdtree.hpp"
#include "irradiance_gradients.hpp"

namespace photon {

/// How much further than its domain (w > 1/a) a record blends into the interpolation: out to
/// w > 1 / (cache_blend_reach a). Which records exist does not depend on it.
inline constexpr float cache_blend_reach = 1.5f;

/// One cached final gather.
struct IrradianceRecord {
    Vec3<float> position;
    Vec3<float> normal;
    Rgb<float> irradiance;
    float harmonic_distance;  ///< R_i, already clamped to the allowed range of validity
    IrradianceGradients gradients{};
};

/// Ward and Heckbert's gradient limit: each channel's translation gradient scaled down so that
/// R |grad_t| does not exceed that channel's irradiance.
inline void limit_translation_gradient(IrradianceRecord& r) noexcept {
    for (int c = 0; c < 3; ++c) {
        const float slope = glm::length(r.gradients.translation[c]) * r.harmonic_distance;
        const float e = std::max(0.0f, r.irradiance[c]);
        if (!(slope <= e)) r.gradients.translation[c] *= (slope > 0.0f && std::isfinite(slope)) ? e / slope : 0.0f;
    }
}

/// Neighbour clamping (Krivanek et al. 2006): R_i = min(R_i, R_j + |x_i - x_j|) over the records j
/// whose domains, a R, overlap record i's. Every new radius is computed from the old ones (one
/// Jacobi sweep), so the result does not depend on the records' order or on threads. Returns the
/// number of radii that shrank; never raises one.
inline std::size_t clamp_radii_to_neighbours(std::span<IrradianceRecord> records, float error) {
    if (records.size() < 2) return 0;
    const KdTree<IrradianceRecord> tree{std::span<const IrradianceRecord>(records)};
    float largest = 0.0f;
    for (const auto& r : records) largest = std::max(largest, r.harmonic_distance);
    std::vector<float> clamped(records.size());
    std::vector<Neighbor<float>> found;
    for (std::size_t i = 0; i < records.size(); ++i) {
        const IrradianceRecord& ri = records[i];
        float r = ri.harmonic_distance;
        for (const Neighbor<float>& c : tree.within_radius(ri.position, error * (ri.harmonic_distance + largest), found)) {
            const IrradianceRecord& rj = tree.payload(c.index);
            const float d = std::sqrt(c.distance2);
            if (d < error * (ri.harmonic_distance + rj.harmonic_distance)) r = std::min(r, rj.harmonic_distance + d);
        }
        clamped[i] = r;
    }
    std::size_t shrunk = 0;
    for (std::size_t i = 0; i < records.size(); ++i)
        if (clamped[i] < records[i].harmonic_distance) {
            records[i].harmonic_distance = clamped[i];
            ++shrunk;
        }
    return shrunk;
}

class IrradianceCache {
public:
    IrradianceCache() = default;
    /// A cache over `records` for error bound `error` (Ward's a, typically 0.1 to 0.3).
    IrradianceCache(std::span<const IrradianceRecord> records, float error) : error_(error), tree_(records) {
        for (const auto& r : records) {
            max_validity_ = std::max(max_validity_, error * r.harmonic_distance);
            max_reach_ = std::max(max_reach_, cache_blend_reach * error * r.harmonic_distance);
        }
    }

    [[nodiscard]] std::size_t size() const noexcept { return tree_.size(); }
    [[nodiscard]] float error() const noexcept { return error_; }
    [[nodiscard]] std::size_t memory_bytes() const noexcept { return tree_.memory_bytes(); }

    /// Interpolated irradiance at x with unit normal n, or nothing if no record is valid there.
    /// `relax` > 1 widens every record's domain and reach by that factor (an error bound of
    /// relax * a). `buffer` is per-thread scratch.
    [[nodiscard]] std::optional<Rgb<float>> interpolate(const Vec3<float>& x, const Vec3<float>& n,
                                                        std::vector<Neighbor<float>>& buffer, float relax = 1.0f) const {
        if (tree_.empty()) return std::nullopt;
        const auto found = tree_.within_radius(x, max_reach_ * relax, buffer);
        Rgb<float> sum(0.0f);
        float weights = 0.0f;
        bool valid = false;
        const float a = error_ * relax;
        const float domain = 1.0f / a, reach = 1.0f / (cache_blend_reach * a);
        for (const Neighbor<float>& c : found) {
            const IrradianceRecord& r = tree_.payload(c.index);
            const float w = ward_weight(r, x, n, c.distance2);
            valid = valid || w > domain;
            if (!(w > reach)) continue;
            const float wc = std::min(w, 1e6f) - reach;  // 0 at the edge of the reach: no step there
            const Vec3<float> turn = glm::cross(r.normal, n), move = x - r.position;
            const IrradianceGradients& g = r.gradients;
            const Rgb<float> e(r.irradiance.r + glm::dot(turn, g.rotation[0]) + glm::dot(move, g.translation[0]),
                               r.irradiance.g + glm::dot(turn, g.rotation[1]) + glm::dot(move, g.translation[1]),
                               r.irradiance.b + glm::dot(turn, g.rotation[2]) + glm::dot(move, g.translation[2]));
            sum += wc * glm::max(e, Rgb<float>(0.0f));  // extrapolated, so it may dip below 0
            weights += wc;
        }
        if (!valid || !(weights > 0.0f)) return std::nullopt;
        return sum / weights;
    }

    /// Whether some record is valid at x (Ward's weight above 1/a), that is, whether interpolate()
    /// gives a value there. The pretrace asks only this: it searches the records' domains, not
    /// their wider reach, and sums nothing.
    [[nodiscard]] bool covers(const Vec3<float>& x, const Vec3<float>& n, std::vector<Neighbor<float>>& buffer) const {
        if (tree_.empty()) return false;
        const float domain = 1.0f / error_;
        for (const Neighbor<float>& c : tree_.within_radius(x, max_validity_, buffer))
            if (ward_weight(tree_.payload(c.index), x, n, c.distance2) > domain) return true;
        return false;
    }

private:
    /// Ward's weight of record r at x (distance2 = |x - x_i|^2), 0 where r does not apply: normals
    /// too far apart, or r's surface in front of x.
    [[nodiscard]] static float ward_weight(const IrradianceRecord& r, const Vec3<float>& x, const Vec3<float>& n,
                                           float distance2) {
        const float cos_n = glm::dot(n, r.normal);
        if (cos_n <= 0.9f) return 0.0f;
        // Ward's "in front" test: a record whose surface lies in front of x sees other light.
        if (glm::dot(x - r.position, r.normal + n) < -0.02f * r.harmonic_distance) return 0.0f;
        const float denom = std::sqrt(distance2) / r.harmonic_distance + std::sqrt(std::max(0.0f, 1.0f - cos_n));
        return denom > 0.0f ? 1.0f / denom : 1e30f;
    }

    float error_ = 0.25f;
    float max_validity_ = 0.0f;  ///< the largest distance at which a record is still valid
    float max_reach_ = 0.0f;     ///< the largest distance at which a record still blends in
    KdTree<IrradianceRecord> tree_;
};

}  // namespace photon
