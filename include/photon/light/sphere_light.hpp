// SPDX-License-Identifier: MIT
#pragma once

#include <cmath>
#include <optional>
#include <stdexcept>

#include "cone.hpp"
#include "falloff.hpp"

namespace photon {

/// Spherical area light: a Lambertian emitter sphere. It radiates the same intensity in every
/// direction as the point light of the same power (I = power / 4 pi without a cone), with
/// radiance L = I / (pi radius^2) from its surface, and casts soft shadows. Invisible to camera
/// rays (as POV-Ray's lights and the paper's "non-objects").
template <Scalar S> struct SphereLight {
    Vec3<S> center{};
    S radius = S(0.1);
    Rgb<S> power{S(0)};
    std::optional<Cone<S>> cone{};
    Falloff<S> falloff{};        ///< physical 1/d^2 unless set (POV-Ray's fades)
    bool casts_shadows = true;   ///< false: direct light without shadow rays or highlights (POV-Ray's `shadowless`)
    bool media_interaction = true;   ///< false: participating media scatter none of it (POV-Ray's `media_interaction off`)
    bool media_attenuation = false;  ///< true: atmospheric media dim its shadow rays (POV-Ray's `media_attenuation on`)

    void validate() const {
        if (!is_finite(center)) throw std::invalid_argument("light: position must be finite");
        if (!(radius > S(0)) || !std::isfinite(radius))
            throw std::invalid_argument("light: area light radius must be positive and finite");
        if (!is_finite(power) || min_component(power) < S(0))
            throw std::invalid_argument("light: power must be finite and >= 0 in every channel");
        falloff.validate();
    }
};

}  // namespace photon
