// SPDX-License-Identifier: MIT
#pragma once
// POV-Ray's light_source as photon's lights, computing what POV-Ray 3.7 computes: its colour and
// fade give the radiant intensity and the falloff (none, or POV-Ray's fade), its spotlight the
// cone's profile, `shadowless` a light without shadow rays, `area_light` photon's AreaLight,
// `parallel` photon's ParallelLight.

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

/// POV-Ray's light_source as photon sees it: radiant intensity I and falloff g with
/// I g(d) = pi colour * POV-Ray's brightness at distance d (a Lambertian surface of albedo a under
/// irradiance E has radiance a E / pi, POV-Ray's a * colour * brightness). POV-Ray 3.7
/// (Attenuate_Light) fades by 2 / (1 + (d / D)^p) when fade_power p > 0 and fade_distance D >
/// 1e-10, which is I = 2 pi D^2 colour with Falloff::fade(D, p): for p = 2 the physical I / d^2
/// far from the light. Otherwise its light does not fall off at all: I = pi colour with
/// Falloff::constant(1).
struct PovLightIntensity {
    Vector3 intensity;
    bool fades;
    double distance, power;
};
[[nodiscard]] inline PovLightIntensity pov_light_intensity(const LightSource& l) {
    constexpr double pi_d = 3.14159265358979323846;
    const double d = l.fade_distance;
    if (l.fade_power > 0 && std::abs(d) > 1e-10) return {2 * pi_d * d * d * l.color.rgb, true, std::abs(d), l.fade_power};
    return {pi_d * l.color.rgb, false, 1.0, 2.0};
}
/// Radiant intensity (W/sr per channel) of a POV-Ray light along its axis (pov_light_intensity).
[[nodiscard]] inline Vector3 radiant_intensity(const LightSource& l) { return pov_light_intensity(l).intensity; }

/// Adds POV-Ray's parallel light `l` (its intensity clamped to `intensity`): irradiance
/// pi colour on a surface facing it, what POV-Ray's colour times its brightness of 1 gives
/// (pov_light_intensity); with a fade, POV-Ray's 2 / (1 + (d / D)^p) of the distance d from the
/// light's plane (Trace::ComputeOneWhiteLightRay), 2 pi colour with ParallelLight's fade factor.
/// Its spotlight cone, if any, has no effect, as in POV-Ray 3.7. An area light's emitters each
/// shine towards point_at in POV-Ray (soft shadows): here one light along the centre's direction.
template <Scalar S>
void add_pov_parallel_light(DefaultScene<S>& scene, const LightSource& l, const Transform& t, const SourceLocation& at,
                            Warnings& warn, const Vector3& intensity, const PovLightIntensity& pov) {
    const Vector3 position = t.point(l.position);
    const Vector3 axis = t.point(l.point_at) - position;
    const auto where = l.written.find("point_at");
    if (!(glm::length(axis) > 0.0))
        throw Error(where != l.written.end() ? where->second : l.at, "parallel light: point_at equals the light's position");
    if (l.area && l.area->size1 * l.area->size2 > 1)
        warn(l.area->at,
             "a parallel `area_light` is approximated by one parallel light along its centre's direction (no soft "
             "shadows): photon has no parallel area lights yet",
             "approximated light", "area_light");
    ParallelLight<S> light;
    light.position = Vec3<S>(position);
    light.direction = Vec3<S>(glm::normalize(axis));
    light.irradiance = Rgb<S>(pov.fades ? intensity / (pov.distance * pov.distance) : intensity);
    if (pov.fades) light.falloff = Falloff<S>::fade(S(pov.distance), S(pov.power));
    light.casts_shadows = !l.shadowless;
    light.media_interaction = l.media_interaction;
    light.media_attenuation = l.media_attenuation;
    try {
        scene.add_light(light);
    } catch (const std::invalid_argument& e) {
        throw Error(at, e.what());
    }
}

/// Adds POV-Ray's `light_source` `l`, placed by `t`, to `scene`: a point light, POV-Ray's grid
/// for an area light of more than one emitter (a sphere light for `orient`), with POV-Ray's
/// falloff and spotlight profile. Says what it approximates or
/// ignores; a value the library rejects is a dsl::Error at `at`.
template <Scalar S>
void add_pov_light(DefaultScene<S>& scene, const LightSource& l, const Transform& t, const SourceLocation& at,
                   Warnings& warn) {
    const auto item = [&](const char* k) {
        const auto it = l.written.find(k);
        return it != l.written.end() ? it->second : l.at;
    };
    const Vector3 position = t.point(l.position);
    const PovLightIntensity pov = pov_light_intensity(l);
    const Clamped<Vector3> physical = physical_light(pov.intensity, l.color.rgb);
    if (!physical.message.empty()) {
        warn(l.at, physical.message, "approximated light", "light_source");
        if (physical.value == Vector3(0.0)) return;
    }
    const Vector3 intensity = physical.value;
    const Falloff<S> falloff = pov.fades ? Falloff<S>::fade(S(pov.distance), S(pov.power)) : Falloff<S>::constant(S(1));
    if (l.parallel && !l.written.count("cylinder")) {
        add_pov_parallel_light(scene, l, t, at, warn, physical.value, pov);
    } else try {
        std::optional<Cone<S>> cone;
        if (l.spotlight) {
            const Spotlight& sp = *l.spotlight;
            const Vector3 axis = t.point(sp.point_at) - position;
            if (glm::length(axis) == 0.0)
                throw Error(item("point_at"), "spotlight point_at equals the light's position");
            try {
                cone = Cone<S>::pov_spotlight(Vec3<S>(axis), sp.radius, sp.falloff, sp.tightness);
            } catch (const std::invalid_argument&) {  // POV-Ray renders it, dark: photon leaves it out
                warn(item("radius"),
                     "this spotlight emits no light (its `radius`, `falloff` and `tightness` leave no direction "
                     "lit): photon leaves it out",
                     "approximated light", "spotlight");
                return;
            }
        }
        const S solid_angle = cone ? cone->effective_solid_angle() : S(4) * pi<S>;
        const Rgb<S> power = Rgb<S>(intensity) * solid_angle;
        const bool shadows = !l.shadowless;
        const AreaLight* a = l.area && l.area->size1 * l.area->size2 > 1 ? &*l.area : nullptr;
        // POV-Ray stops at a circular light with a single emitter along an axis.
        if (a && a->circular && (a->size1 < 2 || a->size2 < 2))
            throw Error(a->at, "a circular area light needs more than 1 light along each axis (POV-Ray stops here too)");
        if (a && a->orient) {
            // POV-Ray turns the grid to face each lit point, a disc of diameter |A1| (it makes an
            // oriented light circular and uses A1's length for both axes): what a Lambertian
            // sphere of that diameter shows every point. Its unoccluded light is POV-Ray's (the
            // centre's I cos / d^2); only the penumbra's profile can differ, by POV-Ray's denser
            // diagonals and, without jitter, its separate shadows per emitter.
            const double radius = 0.5 * glm::length(t.vector(a->axis1));
            if (!a->jitter)
                warn(a->at, "this oriented `area_light` without `jitter` (" + std::to_string(a->size1) + " x " +
                                std::to_string(a->size2) + " separate shadows in POV-Ray) becomes one soft shadow: a sphere light of radius " +
                                format_number(radius),
                     "approximated light", "orient");
            scene.add_light(SphereLight<S>{Vec3<S>(position), S(radius), power, cone, falloff, shadows,
                                           l.media_interaction, l.media_attenuation});
        } else if (a) {
            scene.add_light(photon::AreaLight<S>{.center = Vec3<S>(position), .axis1 = Vec3<S>(t.vector(a->axis1)),
                                                 .axis2 = Vec3<S>(t.vector(a->axis2)), .size1 = unsigned(a->size1),
                                                 .size2 = unsigned(a->size2), .jitter = a->jitter, .circular = a->circular,
                                                 .adaptive = a->adaptive ? std::optional<unsigned>(unsigned(*a->adaptive))
                                                                         : std::nullopt,
                                                 .power = power, .cone = cone, .falloff = falloff, .casts_shadows = shadows,
                                                 .media_interaction = l.media_interaction,
                                                 .media_attenuation = l.media_attenuation});
        } else {
            scene.add_light(PointLight<S>{Vec3<S>(position), power, cone, falloff, shadows, l.media_interaction,
                                          l.media_attenuation});
        }
    } catch (const std::invalid_argument& e) {
        throw Error(at, e.what());
    }
    if (!l.photon_reflection || !l.photon_refraction)
        warn(item("photons"),
             "light photons `reflection off` / `refraction off` are ignored: photon traces every "
             "photon path");
}

}  // namespace photon::dsl
