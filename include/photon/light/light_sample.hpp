// SPDX-License-Identifier: MIT
#pragma once
// One light sample with its density, the density of any direction, and the light a ray meets:
// what an integrator needs to weigh light sampling against BSDF sampling (multiple importance
// sampling, Veach 1997; integrator/path_tracer.hpp). Sphere lights are sampled as by
// IncidentSampler, uniformly in the solid angle they subtend.

#include <cmath>
#include <optional>

#include "light.hpp"

namespace photon {

/// Radiance leaving the surface of a sphere light (in the directions its cone lets out).
template <Scalar S> [[nodiscard]] Rgb<S> surface_radiance(const Light<S>& light) noexcept {
    if (!light_has_surface(light)) return Rgb<S>(S(0));
    const S r = light_radius(light);
    return radiant_intensity(light) / (pi<S> * r * r);
}

/// One sample of a light seen from a shading point.
template <Scalar S> struct LightSample {
    Vec3<S> direction;  ///< unit, from the shading point towards the light
    S distance;         ///< to the sampled point of the light (a shadow ray stops short of it)
    /// Sphere light: the radiance arriving along `direction`. Point or area light (`delta`): the
    /// irradiance I / d^2 on a surface facing it, as the delta distribution integrates to.
    Rgb<S> radiance;
    S pdf;       ///< per steradian; 1 for a point light
    bool delta;  ///< a point or area light (points): no other strategy can find its direction
};

/// One sample of `light` from `x` with u uniform in [0,1)^2; nothing when `x` is outside the
/// light's cone or inside the light. Estimate: f * radiance * cos(theta) / pdf.
template <Scalar S>
[[nodiscard]] std::optional<LightSample<S>> sample_light(const Light<S>& light, const Vec3<S>& x, Vec2<S> u) noexcept {
    const IncidentSampler<S> sampler(light, x);
    const auto incident = sampler.sample(u);
    if (!incident) return std::nullopt;
    if (sampler.is_delta()) return LightSample<S>{incident->direction, incident->distance, incident->irradiance, S(1), true};
    // The profile and falloff at x scale the sphere's radiance as they scale its irradiance.
    const S scale = sampler.falloff_scale() * intensity_profile(light, -incident->direction);
    return LightSample<S>{incident->direction, incident->distance, surface_radiance(light) * scale, sampler.sample_pdf(), false};
}

/// Density per steradian with which sample_light(light, x, .) draws unit `direction` (0 for a
/// point light and for directions that miss the sphere).
template <Scalar S>
[[nodiscard]] S light_pdf(const Light<S>& light, const Vec3<S>& x, const Vec3<S>& direction) noexcept {
    return IncidentSampler<S>(light, x).pdf(direction);
}

/// Where a ray meets a sphere light's surface from outside, and what it sees there.
template <Scalar S> struct LightHit {
    S t;              ///< ray parameter of the near intersection, > 0
    /// Emitted back along the ray, times the cone's profile for that direction (0 outside it) and
    /// the falloff at the ray's origin (as sample_light sees it from there).
    Rgb<S> radiance;
};

/// The near intersection of `ray` (unit direction) with a sphere light; nothing for a point or area
/// light, a miss, or a ray starting inside the light.
template <Scalar S> [[nodiscard]] std::optional<LightHit<S>> intersect_light(const Light<S>& light, const Ray<S>& ray) noexcept {
    if (!light_has_surface(light)) return std::nullopt;  // point and area lights are points
    const S r = light_radius(light);
    const Vec3<S> oc = ray.origin - light_center(light);
    const S b = glm::dot(oc, ray.direction);
    const Vec3<S> closest = oc - b * ray.direction;
    const S disc = r * r - glm::dot(closest, closest);
    if (disc < S(0)) return std::nullopt;
    const S t = -b - std::sqrt(disc);
    if (!(t > S(0))) return std::nullopt;
    const S profile = intensity_profile(light, -ray.direction);
    if (!(profile > S(0))) return LightHit<S>{t, Rgb<S>(S(0))};
    const Falloff<S>& falloff = light_falloff(light);
    const S scale = falloff.is_physical() ? S(1) : falloff.relative_to_inverse_square(glm::length(oc));
    return LightHit<S>{t, surface_radiance(light) * (profile * scale)};
}

}  // namespace photon
