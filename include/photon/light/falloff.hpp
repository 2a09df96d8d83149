// SPDX-License-Identifier: MIT
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "../math/vec.hpp"

namespace photon {

/// How a light's irradiance falls off with the distance d from its centre. The irradiance on a
/// surface facing the light is E(d) = I g(d) for radiant intensity I:
/// - `inverse_square`: g = 1 / d^2, the physical light (the default);
/// - `constant`: g = 1 / D^2 at every distance: POV-Ray's light without `fade_distance` (D = 1);
/// - `fade`: g = 1 / (D^2 (1 + (d / D)^p)), POV-Ray's `fade_distance D fade_power p`, whose
///   brightness 2 / (1 + (d / D)^p) is this with I = 2 pi D^2 colour; for p = 2 it tends to the
///   physical I / d^2 far from the light (d >> D) and stays finite at the light.
/// The non-physical kinds are what POV-Ray computes, not energy-conserving: photons carry
/// relative_to_inverse_square(d) times their physical power at their first hit, so their first-hit
/// irradiance is E(d), and bounce physically after it.
template <Scalar S> struct Falloff {
    enum class Kind { inverse_square, constant, fade };
    Kind kind = Kind::inverse_square;
    S distance = S(1);  ///< D: the reference distance (constant) or POV-Ray's fade_distance (fade)
    S power = S(2);     ///< p: POV-Ray's fade_power (fade only)

    [[nodiscard]] static Falloff inverse_square() noexcept { return {}; }
    [[nodiscard]] static Falloff constant(S reference_distance = S(1)) noexcept {
        return {Kind::constant, reference_distance, S(2)};
    }
    [[nodiscard]] static Falloff fade(S fade_distance, S fade_power) noexcept {
        return {Kind::fade, fade_distance, fade_power};
    }

    [[nodiscard]] bool is_physical() const noexcept { return kind == Kind::inverse_square; }

    /// Throws std::invalid_argument unless D and p are positive and finite where they are used.
    void validate() const {
        if (kind == Kind::inverse_square) return;
        if (!(distance > S(0)) || !std::isfinite(distance))
            throw std::invalid_argument("light: falloff distance must be positive and finite");
        if (kind == Kind::fade && (!(power > S(0)) || !std::isfinite(power)))
            throw std::invalid_argument("light: fade power must be positive and finite");
    }

    /// g(d): irradiance per unit intensity on a surface facing the light at distance d > 0.
    /// Computed in double: finite for every d > 0 except g = 1/d^2 itself for d below ~1e-19 in float.
    [[nodiscard]] S irradiance_per_intensity(S d) const noexcept {
        const double dd = double(d), D = double(distance);
        switch (kind) {
            case Kind::inverse_square: return saturate(1.0 / (dd * dd));
            case Kind::constant: return saturate(1.0 / (D * D));
            case Kind::fade: return saturate(1.0 / (D * D * (1.0 + std::pow(dd / D, double(power)))));
        }
        return S(0);
    }

    /// g(d) d^2: this falloff over the physical one at distance d >= 0 (1 for inverse_square, 0 at
    /// the light for the others). Written for fade as 1 / ((D/d)^2 + (d/D)^(p-2)), which neither
    /// overflows nor divides 0 by 0 at d = 0 or d -> infinity.
    [[nodiscard]] S relative_to_inverse_square(S d) const noexcept {
        const double dd = double(d), D = double(distance);
        switch (kind) {
            case Kind::inverse_square: return S(1);
            case Kind::constant: return saturate((dd / D) * (dd / D));
            case Kind::fade: return saturate(1.0 / ((D / dd) * (D / dd) + std::pow(dd / D, double(power) - 2.0)));
        }
        return S(0);
    }

private:
    /// Clamped to S's largest finite value (a photon's power, or a light one float-ulp away).
    [[nodiscard]] static S saturate(double v) noexcept {
        return S(std::min(v, double(std::numeric_limits<S>::max())));
    }
};

}  // namespace photon
