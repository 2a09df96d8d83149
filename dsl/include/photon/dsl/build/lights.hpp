// SPDX-License-Identifier: MIT
#pragma once
// POV-Ray's light_source as photon's lights: the light-unit rule (a light's colour and fade give its
// radiant intensity), the spotlight profile as a cone of the same power, area lights as spheres.

#include <algorithm>
#include <cmath>
#include <optional>
#include <stdexcept>
#include <string>

#include <glm/geometric.hpp>

#include <photon/light/light.hpp>
#include <photon/scene/scene.hpp>

#include "../description.hpp"
#include "../physical_ranges.hpp"
#include "../value.hpp"
#include "warnings.hpp"

namespace photon::dsl {

/// POV-Ray 3.7's spotlight intensity relative to its axis (Attenuate_Light): cos^tightness in
/// the front hemisphere, times a smooth step from cos(falloff) up to cos(radius) when
/// cos(radius) > 0. A negative or 90-degree radius therefore means "no soft edge", the cosine
/// lobe of `radius -90 falloff 90 tightness 1` in POV-Ray's radiosity Cornell box.
[[nodiscard]] inline double pov_spotlight_profile(double cos_theta, const Spotlight& sp) {
    constexpr double deg = 3.14159265358979323846 / 180.0;
    if (!(cos_theta > 0)) return 0;
    double a = std::pow(cos_theta, sp.tightness);
    const double cos_radius = std::cos(sp.radius * deg), cos_falloff = std::cos(sp.falloff * deg);
    if (cos_radius > 0 && cos_theta < cos_radius) {
        if (cos_theta < cos_falloff) return 0;  // POV-Ray's cubic_spline: 0 below low, 1 from high
        const double t = (cos_theta - cos_falloff) / (cos_radius - cos_falloff);
        a *= (3 - 2 * t) * t * t;
    }
    return a;
}

/// Half-angle in degrees of the sharp cone that carries a POV-Ray spotlight's power at its axial
/// intensity: 1 - cos(half) = the integral of the profile over cos(theta) in [0, 1] (midpoint
/// rule; the profile is smooth but for at most two kinks, so 2^14 points are within 1e-6).
[[nodiscard]] inline double pov_spotlight_cone_half_angle(const Spotlight& sp) {
    constexpr int n = 1 << 14;
    double integral = 0;
    for (int i = 0; i < n; ++i) integral += pov_spotlight_profile((i + 0.5) / n, sp);
    integral /= n;
    return std::acos(std::clamp(1 - integral, -1.0, 1.0)) * 180.0 / 3.14159265358979323846;
}

/// Radiant intensity (W/sr per channel) of a POV-Ray light. With `fade_power 2` and
/// `fade_distance D`, POV-Ray's brightness at distance d >> D is colour * 2 D^2 / d^2, which is
/// a point light of intensity I = 2 pi D^2 colour (docs/scene-language.md). Without a fade,
/// POV-Ray's light does not fall off; photon's light does, and matches POV-Ray at distance 1:
/// I = pi colour, with a warning.
[[nodiscard]] inline Vector3 radiant_intensity(const LightSource& l, Warnings* warn = nullptr) {
    constexpr double pi_d = 3.14159265358979323846;
    const auto item = [&](const char* k) {
        const auto it = l.written.find(k);
        return it != l.written.end() ? it->second : l.at;
    };
    const double d = l.fade_distance;
    if (d > 0 && l.fade_power == 2) return 2 * pi_d * d * d * l.color.rgb;
    if (d > 0 && l.fade_power > 0) {
        if (warn)
            (*warn)(item("fade_power"),
                    "fade_power " + format_number(l.fade_power) +
                        ": photon's lights fall off as 1/d^2; the colour is read as for fade_power 2 "
                        "(intensity 2 pi fade_distance^2 colour)");
        return 2 * pi_d * d * d * l.color.rgb;
    }
    if (warn)
        (*warn)(l.at,
                "light_source without `fade_distance` and `fade_power 2`: POV-Ray's light does not fall off with "
                "distance, photon's falls off as 1/d^2; photon reads the colour as the intensity pi * colour W/sr "
                "(POV-Ray's brightness at distance 1). Write `fade_distance D fade_power 2` with colour "
                "I / (2 pi D^2) for an intensity I");
    return pi_d * l.color.rgb;
}

/// Adds POV-Ray's `light_source` `l`, placed by `t`, to `scene`: a point light, or a sphere light
/// for an area light; a spotlight becomes a sharp cone of the same power. Says what it
/// approximates or ignores; a value the library rejects is a dsl::Error at `at`.
template <Scalar S>
void add_pov_light(DefaultScene<S>& scene, const LightSource& l, const Transform& t, const SourceLocation& at,
                   Warnings& warn) {
    constexpr double pi_d = 3.14159265358979323846;
    const auto item = [&](const char* k) {
        const auto it = l.written.find(k);
        return it != l.written.end() ? it->second : l.at;
    };
    const Vector3 position = t.point(l.position);
    const Clamped<Vector3> physical = physical_light(radiant_intensity(l, &warn), l.color.rgb);
    if (!physical.message.empty()) {
        warn(l.at, physical.message, "approximated light", "light_source");
        if (physical.value == Vector3(0.0)) return;
    }
    const Vector3 intensity = physical.value;
    try {
        std::optional<Cone<S>> cone;
        if (l.spotlight) {
            const Spotlight& sp = *l.spotlight;
            const Vector3 axis = t.point(sp.point_at) - position;
            if (glm::length(axis) == 0.0)
                throw Error(item("point_at"), "spotlight point_at equals the light's position");
            // POV-Ray's profile becomes a sharp cone with the same power, exact when the
            // profile is one (radius = falloff, tightness 0, radius within the front hemisphere).
            const bool sharp = sp.radius == sp.falloff && sp.tightness == 0 && sp.radius > 0 && sp.radius <= 90;
            const double half = sharp ? sp.radius : pov_spotlight_cone_half_angle(sp);
            if (!sharp)
                warn(sp.at.known() ? sp.at : l.at,
                     "photon's spotlight has a sharp edge: POV-Ray's soft edge (`radius` " +
                         format_number(sp.radius) + ", `falloff` " + format_number(sp.falloff) +
                         ", `tightness` " + format_number(sp.tightness) +
                         ") becomes a cone of half-angle " + format_number(std::round(half * 100) / 100) +
                         " degrees carrying the same power. Write `radius A falloff A tightness 0` for an exact "
                         "cone");
            if (!(half > 0)) {  // POV-Ray renders it, dark: photon leaves it out
                warn(item("radius"),
                     "this spotlight emits no light (its `radius`, `falloff` and `tightness` leave no direction "
                     "lit): photon leaves it out",
                     "approximated light", "spotlight");
                return;
            }
            cone.emplace(Vec3<S>(axis), S(half));
        }
        const S solid_angle = cone ? cone->solid_angle() : S(4) * pi<S>;
        const Rgb<S> power = Rgb<S>(intensity) * solid_angle;
        double radius = 0;
        if (l.area && l.area->size1 * l.area->size2 > 1) {
            const AreaLight& a = *l.area;
            const double l1 = glm::length(t.vector(a.axis1)), l2 = glm::length(t.vector(a.axis2));
            if (a.circular && a.orient && std::abs(l1 - l2) <= 1e-9 * std::max(l1, l2)) {
                radius = 0.5 * l1;
            } else {
                radius = a.circular ? 0.5 * std::sqrt(l1 * l2) : std::sqrt(l1 * l2 / pi_d);
                warn(a.at,
                     "photon's area lights are spheres: this `area_light` (without `circular orient` and "
                     "equal axes) becomes a sphere light of radius " +
                         format_number(radius) + " (same area)");
            }
        }
        if (radius > 0)
            scene.add_light(SphereLight<S>{Vec3<S>(position), S(radius), power, cone});
        else
            scene.add_light(PointLight<S>{Vec3<S>(position), power, cone});
    } catch (const std::invalid_argument& e) {
        throw Error(at, e.what());
    }
    if (l.shadowless) warn(item("shadowless"), "`shadowless` is ignored: photon's lights always cast shadows");
    if (l.looks_like)
        warn(item("looks_like"),
             "`looks_like` is ignored: photon's lights are invisible, as POV-Ray's without it");
    if (!l.photon_reflection || !l.photon_refraction)
        warn(item("photons"),
             "light photons `reflection off` / `refraction off` are ignored: photon traces every "
             "photon path");
}

}  // namespace photon::dsl
