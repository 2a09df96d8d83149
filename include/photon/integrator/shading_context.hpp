// SPDX-License-Identifier: MIT
#pragma once

#include <optional>
#include <vector>

#include "../estimator/density_estimate.hpp"
#include "../math/rng.hpp"
#include "area_light_adaptive.hpp"
#include "render_stats.hpp"

namespace photon {

/// Mutable state of one worker while it shades: the pixel's random stream, scratch buffers and
/// counters. Never shared between threads.
struct ShadingContext {
    Pcg32 rng{0, 0};
    EstimateScratch scratch{};
    std::vector<Neighbor<float>> nearest{};  ///< for precomputed-irradiance lookups
    std::vector<std::uint32_t> occluders{};  ///< objects that may shadow one area light sample set
    /// One adaptive area light's grid at one point (area_light_adaptive.hpp).
    std::vector<std::optional<GridSample<double>>> area_grid{};
    RayCounts rays{};
    std::uint64_t estimates = 0;
};

}  // namespace photon
