// SPDX-License-Identifier: MIT
#pragma once

#include <cmath>
#include <optional>
#include <stdexcept>

#include "cone.hpp"
#include "falloff.hpp"

namespace photon {

/// Isotropic point light of total radiant power `power` (watts per RGB channel), optionally
/// emitting only into a cone. Radiant intensity I = power / solid angle emitted into; irradiance
/// at distance d is I cos(theta) / d^2 (inverse-square falloff).
template <Scalar S> struct PointLight {
    Vec3<S> position{};
    Rgb<S> power{S(0)};
    std::optional<Cone<S>> cone{};
    Falloff<S> falloff{};        ///< physical 1/d^2 unless set (POV-Ray's fades)
    bool casts_shadows = true;   ///< false: direct light without shadow rays or highlights (POV-Ray's `shadowless`)
    bool media_interaction = true;   ///< false: participating media scatter none of it (POV-Ray's `media_interaction off`)
    bool media_attenuation = false;  ///< true: atmospheric media dim its shadow rays (POV-Ray's `media_attenuation on`)

    /// Throws std::invalid_argument on a non-finite position or a negative or non-finite power.
    void validate() const {
        if (!is_finite(position)) throw std::invalid_argument("light: position must be finite");
        if (!is_finite(power) || min_component(power) < S(0))
            throw std::invalid_argument("light: power must be finite and >= 0 in every channel");
        falloff.validate();
    }
};

}  // namespace photon
