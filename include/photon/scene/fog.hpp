// SPDX-License-Identifier: MIT
#pragma once
// POV-Ray's fog (Trace::ComputeFog, ComputeConstantFogDepth, ComputeGroundFogDepth): a colour
// that a ray's segment of length w fades into, by att = exp(-w / distance) for constant fog and
// exp(-w mean_density / distance) for ground fog, whose density is 1 below `offset` along `up`
// and 1 / (1 + h^2) at h = (height - offset) / altitude above it. What the segment delivers is
//   seen = (1 - att) colour + att ((1 - filter) + filter colour) behind,  att >= transmit.
// It is not light transport: the fog's colour shows whatever lights it, and it casts nothing.
// photon applies it where POV-Ray does by default: to the segments of camera, mirror and glass
// rays outside transmissive objects, not to shadow rays, photons or gathers (the integrators
// say where; docs/scene-language.md).

#include <algorithm>
#include <cmath>
#include <optional>
#include <span>
#include <stdexcept>

#include "../geometry/ray.hpp"
#include "../math/vec.hpp"
#include "../texture/noise.hpp"

namespace photon {

/// POV-Ray's fog turbulence: the noise point is the segment's midpoint scaled by `scale` per
/// axis, and the segment's length is shortened by up to `depth` of its noise where it is short
/// (the farther, the less turbulence shows).
struct FogTurbulence {
    Vec3<double> scale{0.0};
    TurbulenceParams params{};
    double depth = 0.5;  ///< POV-Ray's turb_depth
};

template <Scalar S> struct Fog {
    enum class Kind { constant, ground };  ///< POV-Ray's fog_type 1 and 2
    Kind kind = Kind::constant;
    S distance = S(1);  ///< the length over which constant fog fades to 1/e
    Rgb<S> colour{S(0)};
    S filter = S(0), transmit = S(0);  ///< the colour's filter (tints what shows through) and transmit (minimum att)
    Vec3<S> up{S(0), S(1), S(0)};      ///< ground fog's vertical (unit)
    /// Ground fog: density 1 below `offset`, halved `altitude` above it (altitude 0: a layer with
    /// a flat top at `offset`, the limit POV-Ray's formula reaches where it is defined).
    S offset = S(0), altitude = S(1);
    std::optional<FogTurbulence> turbulence;
    NoiseGenerator noise = NoiseGenerator::range_corrected;

    /// Throws std::invalid_argument for values no fog can have.
    void validate() const {
        if (!(distance > S(0)) || !std::isfinite(distance))
            throw std::invalid_argument("fog: distance must be positive and finite");
        if (!is_finite(colour) || !std::isfinite(filter) || !std::isfinite(transmit))
            throw std::invalid_argument("fog: colour, filter and transmit must be finite");
        if (kind == Kind::ground && !(altitude >= S(0) && std::isfinite(altitude)))
            throw std::invalid_argument("fog: a ground fog's altitude must be >= 0 and finite");
        if (kind == Kind::ground && !(std::abs(glm::length(up) - S(1)) < S(1e-3)))
            throw std::invalid_argument("fog: up must be a unit vector");
    }
};

/// What fog does to one ray segment: seen = added + transmittance * behind, per channel.
template <Scalar S> struct FogEffect {
    Rgb<S> transmittance{S(1)};
    Rgb<S> added{S(0)};
    [[nodiscard]] Rgb<S> apply(const Rgb<S>& behind) const noexcept { return added + transmittance * behind; }
};

/// The segment length POV-Ray gives a ray that meets nothing (BOUND_HUGE): constant fog then
/// shows its colour alone, ground fog what the density above the ray's start integrates to.
template <Scalar S> inline constexpr S fog_unbounded_length = S(2e10);

namespace fog_detail {

/// POV-Ray's mean ground-fog density over heights from `start` to `end` (in altitudes above the
/// offset): 1 at and below 0, 1 / (1 + h^2) above, whose integral is atan h.
template <Scalar S> [[nodiscard]] S mean_ground_density(S start, S end) noexcept {
    if (start <= S(0)) return end <= S(0) ? S(1) : (std::atan(end) - start) / (end - start);
    if (end <= S(0)) return (std::atan(start) - end) / (start - end);
    const S delta = start - end;
    return std::abs(delta) > S(1e-10) ? (std::atan(start) - std::atan(end)) / delta : S(1) / (start * start + S(1));
}

/// The limit of altitude 0, a fog layer with a flat top: the share of the segment from height
/// `start` to `end` (above the offset) that lies at or below 0.
template <Scalar S> [[nodiscard]] S share_below(S start, S end) noexcept {
    if (start <= S(0) && end <= S(0)) return S(1);
    if (start > S(0) && end > S(0)) return S(0);
    return (start <= S(0) ? -start : -end) / std::abs(end - start);
}

}  // namespace fog_detail

/// Fraction att of what lies behind that shows through one fog along the segment from `origin`
/// along unit `direction` of length `length` (before the fog's transmit floor).
template <Scalar S>
[[nodiscard]] S fog_attenuation(const Fog<S>& fog, const Vec3<S>& origin, const Vec3<S>& direction, S length) noexcept {
    S width = length;
    S density = S(1);
    if (fog.kind == Fog<S>::Kind::ground) {
        const S start = glm::dot(origin, fog.up) - fog.offset;
        const S end = glm::dot(origin + direction * length, fog.up) - fog.offset;
        density = fog.altitude > S(0) ? fog_detail::mean_ground_density(start / fog.altitude, end / fog.altitude)
                                      : fog_detail::share_below(start, end);
    }
    if (fog.turbulence) {
        const FogTurbulence& turb = *fog.turbulence;
        const Vec3<double> mid = Vec3<double>(origin + direction * (length * S(0.5))) * turb.scale;
        const double near_weight = std::exp(-double(length) / double(fog.distance));
        width *= S(1.0 - near_weight * std::min(1.0, pov_turbulence(mid, turb.params, fog.noise) * turb.depth));
    }
    return std::exp(-width * density / fog.distance);
}

/// All `fogs` along one segment, composed as POV-Ray composes them (Trace::ComputeFog).
template <Scalar S>
[[nodiscard]] FogEffect<S> fog_along(std::span<const Fog<S>> fogs, const Vec3<S>& origin, const Vec3<S>& direction,
                                     S length) noexcept {
    FogEffect<S> effect;
    for (const Fog<S>& fog : fogs) {
        const S att = std::max(fog_attenuation(fog, origin, direction, length), fog.transmit);
        effect.transmittance *= att * ((S(1) - fog.filter) + fog.filter * fog.colour);
        effect.added += (S(1) - att) * fog.colour;
    }
    return effect;
}

}  // namespace photon
