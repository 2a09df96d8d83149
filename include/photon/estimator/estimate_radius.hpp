// SPDX-License-Identifier: MIT
#pragma once
// The largest radius of a density estimate, derived from the photon map itself when the settings
// leave it automatic (EstimateSettings::max_radius == 0). A fixed cap in metres (0.25 m used to
// be the default) is right for one room and wrong for a scene a kilometre or a millimetre
// across; the photons' own spacing is not: at the map's typical density, k photons lie within
// the typical distance to the k-th nearest photon, so a cap a few times that distance lets
// regions several times sparser than typical still find their k photons, and it scales with the
// scene and with the photon count without the user's help.

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

#include "density_estimate.hpp"

namespace photon {

/// How automatic estimate radii are chosen (estimate_radius_from_density).
struct DensityRadiusRule {
    /// Photons sampled (evenly through the map's tree order, so the result does not depend on
    /// threads): their distances to their k-th nearest photon are the measurement.
    std::size_t samples = 1024;
    /// Which of the sampled distances (a quantile, 0.5: the median) the cap is measured on.
    float quantile = 0.5f;
    /// The cap, in units of that distance: 2 lets a region 4 times sparser still find k photons.
    float factor = 2.0f;
};

/// The global map's rule: twice the median spacing. Light on diffuse surfaces varies slowly, so
/// the typical photon's spacing describes the map.
inline constexpr DensityRadiusRule global_radius_rule{};
/// The caustic map's rule: twice the spacing that 90% of its photons are within. A caustic packs
/// most of its photons into a focus a thousand times denser than the broad, dim part of the same
/// caustic around it (a glass ball's shadow), where the median photon's spacing left a few
/// photons per estimate: a speckled disc.
inline constexpr DensityRadiusRule caustic_radius_rule{.quantile = 0.9f};

/// A photon map's spacing: the distance from a photon to its k-th nearest neighbour (itself
/// counted), at `quantile` of the sampled photons (0.5: the median). Photon-weighted, so it
/// describes where the photons (and the light) are rather than a few strays; 0 for a map with
/// fewer than k photons or all of them at one point.
[[nodiscard]] inline float kth_neighbor_distance(const PhotonMap& map, unsigned k, std::size_t samples = 1024,
                                                 float quantile = 0.5f) {
    if (map.size() < std::max<std::size_t>(k, 2) || samples == 0) return 0.0f;
    const auto& box = map.bounds();
    const float reach = glm::length(box.extent()) * 1.001f + 1e-30f;  // every photon is within it
    const std::size_t n = std::min(samples, map.size());
    std::vector<Neighbor<float>> buffer;
    std::vector<float> distances;
    distances.reserve(n);
    for (std::size_t s = 0; s < n; ++s) {
        const std::size_t i = (s * map.size()) / n + (map.size() / n) / 2;
        const auto found = map.k_nearest(map.position(std::min(i, map.size() - 1)), k, reach, buffer);
        if (found.neighbors.size() < k) continue;
        float d2 = 0.0f;
        for (const auto& nb : found.neighbors) d2 = std::max(d2, nb.distance2);
        distances.push_back(std::sqrt(d2));
    }
    if (distances.empty()) return 0.0f;
    const auto at = std::size_t(std::clamp(quantile, 0.0f, 1.0f) * float(distances.size() - 1) + 0.5f);
    const auto nth = distances.begin() + std::ptrdiff_t(at);
    std::nth_element(distances.begin(), nth, distances.end());
    return *nth;
}

/// The max radius for estimates of k photons from `map`: `rule.factor` times its k-th neighbour
/// distance at `rule.quantile`. `fallback` when the map cannot say (fewer than k photons, or
/// none apart).
[[nodiscard]] inline float estimate_radius_from_density(const PhotonMap& map, unsigned k, float fallback,
                                                        const DensityRadiusRule& rule = {}) {
    const float d = kth_neighbor_distance(map, k, rule.samples, rule.quantile);
    return d > 0.0f && std::isfinite(d) ? rule.factor * d : fallback;
}

}  // namespace photon
