// SPDX-License-Identifier: MIT
#pragma once
// The photon maps pass 2 reads, and the estimate radii they are read with.

#include <initializer_list>
#include <optional>

#include "../estimator/estimate_radius.hpp"
#include "../estimator/irradiance_cache.hpp"
#include "../estimator/precomputed_irradiance.hpp"
#include "../settings/render_settings.hpp"

namespace photon {

/// The photon maps pass 2 reads, and what is derived from them: irradiance precomputed from the
/// global map and the irradiance cache of final gathers. Any may be absent.
struct PhotonMaps {
    std::optional<PhotonMap> global, caustic;
    /// L S+ D photons of the global pass from directions the caustic pass does not aim into (a
    /// mirror plane's reflection): caustics too, as sparse as the global map, read like it.
    std::optional<PhotonMap> unaimed_caustic;
    std::optional<PrecomputedIrradiance> irradiance;
    std::optional<IrradianceCache> irradiance_cache;  ///< final gathers, built by a pretrace
    /// The max radii the global estimate (global and unaimed caustic maps) and the caustic
    /// estimate use: the settings' own, or, where they ask for 0, derived from these maps'
    /// density (derive_estimate_radii). 0: not derived yet.
    float global_radius = 0, caustic_radius = 0;
};

namespace detail {
/// The automatic radius for estimates of `k` photons from the first of `maps` holding photons.
inline float automatic_radius(std::initializer_list<const std::optional<PhotonMap>*> maps, unsigned k,
                              const DensityRadiusRule& rule) {
    for (const auto* m : maps) {
        if (!*m || (*m)->empty()) continue;
        const PhotonMap& map = **m;
        // A map of fewer than k photons (or all at one point) has no spacing to measure: every
        // estimate then counts all of it, so the radius spans it.
        const float span = glm::length(map.bounds().extent());
        return estimate_radius_from_density(map, k, span > 0.0f ? span : 1e-6f * (1.0f + max_component(glm::abs(map.bounds().min))),
                                            rule);
    }
    return 0.0f;
}
}  // namespace detail

/// Fills maps.global_radius and maps.caustic_radius from `settings`: its max_radius where it
/// gives one, else from the density of the map it reads (global: the global map, or the unaimed
/// caustics where there is none; caustic: the caustic map). Deterministic, and cheap (about a
/// thousand k-nearest searches per map).
inline void derive_estimate_radii(PhotonMaps& maps, const RenderSettings& settings) {
    const EstimateSettings &g = settings.global_estimate, &c = settings.caustic_estimate;
    maps.global_radius = g.max_radius > 0.0f ? g.max_radius : detail::automatic_radius({&maps.global, &maps.unaimed_caustic}, g.k, global_radius_rule);
    maps.caustic_radius = c.max_radius > 0.0f ? c.max_radius : detail::automatic_radius({&maps.caustic}, c.k, caustic_radius_rule);
}

/// `settings` with the radii `maps` are read with in place of automatic (0) ones; maps whose
/// radii were not derived (built by a program's own code) are measured now.
[[nodiscard]] inline RenderSettings with_estimate_radii(RenderSettings settings, const PhotonMaps& maps) {
    if (settings.global_estimate.max_radius > 0.0f && settings.caustic_estimate.max_radius > 0.0f) return settings;
    float g = maps.global_radius, c = maps.caustic_radius;
    if (!(g > 0.0f) && !(settings.global_estimate.max_radius > 0.0f))
        g = detail::automatic_radius({&maps.global, &maps.unaimed_caustic}, settings.global_estimate.k, global_radius_rule);
    if (!(c > 0.0f) && !(settings.caustic_estimate.max_radius > 0.0f))
        c = detail::automatic_radius({&maps.caustic}, settings.caustic_estimate.k, caustic_radius_rule);
    if (!(settings.global_estimate.max_radius > 0.0f)) settings.global_estimate.max_radius = g;
    if (!(settings.caustic_estimate.max_radius > 0.0f)) settings.caustic_estimate.max_radius = c;
    return settings;
}

}  // namespace photon
