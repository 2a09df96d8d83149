// SPDX-License-Identifier: MIT
#pragma once
// POV-Ray's parallel light (`light_source { L, C parallel point_at P }`): light from a distant
// source such as the sun, every ray travelling along the same unit `direction` (from L towards
// P). POV-Ray 3.7 (Trace::ComputeOneWhiteLightRay) lights a point x along -direction with a
// shadow ray as long as x's distance from the plane through L perpendicular to the direction,
// dot(x - L, direction); the irradiance does not fall off with distance (a fade, if any, is of
// that plane distance, Attenuate_Light). Its photons (photonshootingtask.cpp) leave that plane
// from a disc perpendicular to the direction around the target's projection.
//
// Here the plane is the light: it emits `irradiance` (W/m^2 on a surface facing the light) into
// the half-space in front of it. A point behind the plane gets nothing; POV-Ray lights it
// unshadowed ("parts of an object above the light plane still get illuminated ... but will not
// cast or receive shadows"), which no photon can carry: put the light's location beyond the
// scene. Photons leave uniformly from the beam: the disc in the plane, perpendicular to the
// direction, that covers the ball around the scene's bounded objects (the ball the sky's photons
// enter by), fitted by the scene on commit (fit_beam). The light's `power` is the irradiance
// times the beam's area, pi r^2: what its photons share, and 0 until fitted (or when the scene
// has only infinite shapes, which no finite beam covers: direct light still reaches them).
// A cone (a parallel `spotlight`) has no effect in POV-Ray 3.7: its spot attenuation sees the
// cosine between -direction and the axis, always 1; so this light has none.

#include <cmath>
#include <optional>
#include <stdexcept>

#include <glm/geometric.hpp>

#include "../geometry/bounding_ball.hpp"
#include "cone.hpp"
#include "falloff.hpp"

namespace photon {

template <Scalar S> struct ParallelLight {
    Vec3<S> position{};                  ///< a point of the emitting plane (POV-Ray's location)
    Vec3<S> direction{S(0), S(-1), S(0)};  ///< unit, the way the light travels
    Rgb<S> irradiance{S(0)};             ///< W/m^2 on a surface facing the light (before any falloff)
    Falloff<S> falloff{};        ///< physical (none) unless set; of the distance from the plane
    bool casts_shadows = true;   ///< false: direct light without shadow rays or highlights (POV-Ray's `shadowless`)
    bool media_interaction = true;   ///< false: participating media scatter none of it
    bool media_attenuation = false;  ///< true: atmospheric media dim its shadow rays

    /// The beam photons leave from (fit_beam): its centre on the plane and its radius.
    Vec3<S> beam_center{};
    S beam_radius = S(0);
    /// irradiance * pi beam_radius^2, set by fit_beam.
    Rgb<S> power{S(0)};

    /// Throws std::invalid_argument on a non-finite position, a direction that is not unit
    /// length (within 1e-3), or a negative or non-finite irradiance.
    void validate() const {
        if (!is_finite(position)) throw std::invalid_argument("light: position must be finite");
        if (!is_finite(direction) || !(std::abs(glm::length(direction) - S(1)) < S(1e-3)))
            throw std::invalid_argument("light: a parallel light's direction must be a unit vector");
        if (!is_finite(irradiance) || min_component(irradiance) < S(0))
            throw std::invalid_argument("light: irradiance must be finite and >= 0 in every channel");
        falloff.validate();
    }

    /// Signed distance of x in front of the emitting plane (along the direction).
    [[nodiscard]] S plane_distance(const Vec3<S>& x) const noexcept { return glm::dot(x - position, direction); }

    /// The irradiance at plane distance d over the unfaded one: 1 without a falloff or with a
    /// constant one; POV-Ray's fade 1 / (1 + (d / D)^p) (the 2 of its 2 / (1 + (d / D)^p) is in
    /// the irradiance the scene language sets), as D^2 g(d) of Falloff.
    [[nodiscard]] S falloff_factor(S d) const noexcept {
        if (falloff.kind != Falloff<S>::Kind::fade) return S(1);
        if (!(d > S(0))) return S(1);
        return falloff.irradiance_per_intensity(d) * falloff.distance * falloff.distance;
    }

    /// Fits the beam to `ball` (what photons must reach): the disc of its radius around the
    /// projection of its centre onto the plane; power becomes irradiance * pi r^2.
    void fit_beam(const Ball<S>& ball) noexcept {
        beam_center = ball.center - plane_distance(ball.center) * direction;
        beam_radius = ball.radius;
        power = irradiance * (pi<S> * beam_radius * beam_radius);
    }
};

}  // namespace photon
