// SPDX-License-Identifier: MIT
#pragma once
// Precomputed irradiance (Christensen 1999, "Faster Photon Map Global Illumination"): the global
// map's irradiance estimate is computed once at a fraction of the photon positions, with the
// surface normal there. A final-gather ray then costs one nearest-neighbour lookup instead of a
// k-nearest density estimate.

#include <algorithm>
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include "../math/octahedral.hpp"
#include "../photonmap/kdtree.hpp"

namespace photon {

/// One precomputed estimate: where, on which surface orientation, how much irradiance.
struct IrradianceSample {
    Vec3<float> position;
    Rgb<float> irradiance;
    std::uint16_t normal;  ///< octahedral
};

/// What the tree keeps beside each position.
struct IrradiancePayload {
    Rgb<float> irradiance;
    std::uint16_t normal;
};

template <> struct point_traits<IrradianceSample> {
    using payload_type = IrradiancePayload;
    [[nodiscard]] static Vec3<float> position(const IrradianceSample& s) noexcept { return s.position; }
    [[nodiscard]] static IrradiancePayload payload(const IrradianceSample& s) noexcept {
        return {s.irradiance, s.normal};
    }
};

class PrecomputedIrradiance {
public:
    PrecomputedIrradiance() = default;
    explicit PrecomputedIrradiance(std::span<const IrradianceSample> samples) : tree_(samples) {}

    [[nodiscard]] std::size_t size() const noexcept { return tree_.size(); }
    [[nodiscard]] std::size_t memory_bytes() const noexcept { return tree_.memory_bytes(); }

    /// Irradiance of the nearest sample within `max_radius` whose normal is within about 25
    /// degrees of `n` and that `visible(sample_position, sample_normal)` accepts, among the
    /// `candidates` nearest such samples; nothing if there is none (the caller then estimates
    /// from the photon map itself: a lit point must not read black). The normal test rejects
    /// samples on other surfaces (the far face of a thin wall, a perpendicular wall at a corner);
    /// the visibility test rejects samples on the same plane behind a wall standing on it.
    template <class Visible>
    [[nodiscard]] std::optional<Rgb<float>> find(const Vec3<float>& x, const Vec3<float>& n, float max_radius,
                                                 std::vector<Neighbor<float>>& buffer, Visible&& visible,
                                                 unsigned candidates = 4) const {
        if (tree_.empty()) return std::nullopt;
        const auto same_surface = [&](std::uint32_t i, float) {
            return glm::dot(decode_octahedral(tree_.payload(i).normal), n) > min_normal_cosine;
        };
        // The nearest alone first: it nearly always passes, and a one-nearest search is cheaper.
        // Where it does not, the `candidates` nearest give the same answer as if searched at once.
        const auto nearest = tree_.k_nearest(x, 1, max_radius, buffer, same_surface);
        if (nearest.neighbors.empty()) return std::nullopt;
        const std::uint32_t first = nearest.neighbors.front().index;
        if (visible(tree_.position(first), decode_octahedral(tree_.payload(first).normal))) return tree_.payload(first).irradiance;
        if (candidates < 2) return std::nullopt;
        auto found = tree_.k_nearest(x, candidates, max_radius, buffer, same_surface);
        std::sort(buffer.begin(), buffer.begin() + std::ptrdiff_t(found.neighbors.size()),
                  [](const Neighbor<float>& a, const Neighbor<float>& b) { return a.distance2 < b.distance2; });
        for (const Neighbor<float>& c : found.neighbors) {
            if (c.index == first) continue;  // already seen hidden
            const IrradiancePayload& p = tree_.payload(c.index);
            if (visible(tree_.position(c.index), decode_octahedral(p.normal))) return p.irradiance;
        }
        return std::nullopt;
    }
    /// find(), or zero where no sample qualifies.
    template <class Visible>
    [[nodiscard]] Rgb<float> lookup(const Vec3<float>& x, const Vec3<float>& n, float max_radius,
                                    std::vector<Neighbor<float>>& buffer, Visible&& visible,
                                    unsigned candidates = 4) const {
        return find(x, n, max_radius, buffer, visible, candidates).value_or(Rgb<float>(0.0f));
    }
    /// Irradiance of the nearest matching sample, without a visibility test.
    [[nodiscard]] Rgb<float> lookup(const Vec3<float>& x, const Vec3<float>& n, float max_radius,
                                    std::vector<Neighbor<float>>& buffer) const {
        return lookup(x, n, max_radius, buffer, [](const Vec3<float>&, const Vec3<float>&) { return true; }, 1);
    }

    /// Samples whose normal is further than this from the query's (about 25 degrees) belong to
    /// another surface. It also bounds the curvature between a query and a sample on one curved
    /// surface, which the visibility test relies on (visibility_lift).
    static constexpr float min_normal_cosine = 0.9f;

private:
    KdTree<IrradianceSample> tree_;
};

}  // namespace photon
