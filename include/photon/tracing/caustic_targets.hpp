// SPDX-License-Identifier: MIT
#pragma once
// Aiming caustic photons: instead of Jensen's projection maps, each light shoots into the cones
// that bound the caustic targets (mirror and glass objects) as seen from the whole light. A photon
// drawn from the mixture of cones is weighted by the mixture's density, so overlapping cones are
// counted once (a one-sample balance heuristic) and the caustic map stays unbiased.

#include <cmath>
#include <cstdint>
#include <vector>

#include "../light/light.hpp"
#include "../math/frame.hpp"
#include "../math/sampling.hpp"

namespace photon {

/// Directions from a light that can reach one target.
template <Scalar S> struct TargetCone {
    Vec3<S> axis;
    S cos_half_angle;  ///< -1: the whole sphere of directions
    S solid_angle;
    Frame<S> frame;

    [[nodiscard]] bool contains(const Vec3<S>& d) const noexcept { return glm::dot(d, axis) >= cos_half_angle; }
};

/// Cones from `light` to targets bounded by spheres (centre, radius). The cone is widened by the
/// light's own radius so that it covers rays leaving any point of a sphere light.
template <Scalar S>
[[nodiscard]] std::vector<TargetCone<S>> target_cones(const Light<S>& light,
                                                      const std::vector<std::pair<Vec3<S>, S>>& targets) {
    std::vector<TargetCone<S>> cones;
    const Vec3<S> origin = light_center(light);
    const S light_r = light_radius(light);
    for (const auto& [center, radius] : targets) {
        const Vec3<S> to = center - origin;
        const S d = glm::length(to);
        const S reach = radius + light_r;
        TargetCone<S> cone;
        if (!(d > reach)) {
            cone.axis = {S(0), S(0), S(1)};
            cone.cos_half_angle = S(-1);
        } else {
            cone.axis = to / d;
            cone.cos_half_angle = std::sqrt(std::max(S(0), S(1) - squared(reach / d)));
        }
        cone.solid_angle = cone_solid_angle(cone.cos_half_angle);
        cone.frame = Frame<S>::from_normal(cone.axis);
        cones.push_back(cone);
    }
    return cones;
}

/// A direction from the mixture of cones (each chosen in proportion to its solid angle) and its
/// density per steradian: (number of cones containing it) / (sum of solid angles).
template <Scalar S> struct ConeMixtureSample {
    Vec3<S> direction;
    S pdf;
};

template <Scalar S>
[[nodiscard]] ConeMixtureSample<S> sample_cone_mixture(const std::vector<TargetCone<S>>& cones, S total_solid_angle,
                                                       Pcg32& rng) noexcept {
    S pick = rng.uniform<S>() * total_solid_angle;
    std::size_t chosen = cones.size() - 1;
    for (std::size_t i = 0; i < cones.size(); ++i) {
        if (pick < cones[i].solid_angle) {
            chosen = i;
            break;
        }
        pick -= cones[i].solid_angle;
    }
    const TargetCone<S>& c = cones[chosen];
    const Vec3<S> d = c.frame.to_world(uniform_cone(rng.uniform2<S>(), c.cos_half_angle));
    unsigned covering = 0;
    for (const auto& cone : cones) covering += cone.contains(d) ? 1u : 0u;
    covering = std::max(covering, 1u);  // the chosen cone contains d up to rounding
    return {d, S(covering) / total_solid_angle};
}

}  // namespace photon
