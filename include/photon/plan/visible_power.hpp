// SPDX-License-Identifier: MIT
#pragma once
// Sharing the global photons by the power that reaches what the camera sees, not by total power.
// A pilot pass of a few photons per light measures, for each light, the fraction of its power
// that lands on a diffuse point the camera sees, directly or after one bounce. Lights whose light
// mostly ends where the camera cannot look (a lamp in another room) then shoot fewer photons and
// the visible ones more. The pilot is an estimate, not a proof: every emitting light keeps a
// floor share of what power alone would give it, so no light goes silent on a pilot's word
// (silencing is the plan's walls' job, which prove it), and each photon still carries its own
// light's power over its own light's count, so the map stays unbiased whatever the shares.

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <span>
#include <vector>

#include <glm/mat3x3.hpp>
#include <glm/matrix.hpp>

#include "../geometry/offset.hpp"
#include "../light/light.hpp"
#include "../material/scatter.hpp"
#include "../math/rng.hpp"
#include "../scene/camera.hpp"
#include "../tracing/photon_hit.hpp"

namespace photon {

/// How the pilot measures and how its measurement becomes shares (visible_power_shares).
struct VisiblePowerPilot {
    unsigned photons_per_light = 128;
    /// Each light's share is (1 - floor) of its visible-power share plus `floor` of its power
    /// share: a light the pilot saw nothing of keeps a tenth of its usual photons.
    double floor = 0.1;
    std::uint64_t seed = 1;
};

/// Whether the camera may see point `p` directly: some primary ray reaches it unblocked. Exact
/// for a perspective or orthographic camera without focal blur (inside the frustum or the
/// prism, nothing in between); conservative for the others: any point in front of nothing
/// that blocks it from the eye, or any point at all when the rays share no eye. The pilots
/// may then keep work the image does not need, never drop light it shows.
template <class SceneT>
[[nodiscard]] bool camera_sees(const SceneT& scene, const Camera<typename SceneT::scalar_type>& camera,
                               const Vec3<typename SceneT::scalar_type>& p) {
    using S = typename SceneT::scalar_type;
    const Projection projection = camera.projection();
    const bool framed = !camera.has_focal_blur() &&
                        (projection == Projection::perspective || projection == Projection::orthographic);
    Vec3<S> from = camera.location();
    if (framed) {
        // p - location = a direction + b right + c up, for any (not only orthogonal) camera axes.
        const glm::mat<3, 3, S> axes(camera.direction(), camera.right(), camera.up());
        if (!(std::abs(glm::determinant(axes)) > S(0))) return true;  // degenerate: cannot tell
        const Vec3<S> abc = glm::inverse(axes) * (p - camera.location());
        const S a = abc.x, b = abc.y, c = abc.z;
        if (!(a > S(0))) return false;
        if (projection == Projection::perspective) {
            if (std::abs(b) > S(0.5) * a || std::abs(c) > S(0.5) * a) return false;
        } else {
            if (std::abs(b) > S(0.5) || std::abs(c) > S(0.5)) return false;
            from = camera.location() + b * camera.right() + c * camera.up();  // the ray's origin
        }
    } else {
        const auto eye = camera.eye();
        if (!eye) return true;
        from = *eye;
    }
    const Vec3<S> d = p - from;
    const S error = intersection_error(p, from);
    const S length = glm::length(d);
    if (!(length > S(4) * error)) return true;
    return !scene.occluded(Ray<S>{from, d / length, length - S(4) * error});
}

/// Whether light arriving at `at` along `incident` (pointing into the surface) arrives on the
/// side the camera may look at it from. Conservative where the rays share no eye.
template <Scalar S>
[[nodiscard]] bool on_camera_side(const Camera<S>& camera, const Vec3<S>& at, const Vec3<S>& incident) noexcept {
    if (camera.projection() == Projection::orthographic && !camera.has_focal_blur())
        return glm::dot(incident, camera.direction()) > S(0);
    const auto eye = camera.eye();
    return !eye || glm::dot(incident, *eye - at) < S(0);
}

/// Per light, the fraction of its emitted power that the pilot saw land on a diffuse point the
/// camera sees, at the first hit or the second (weighted by the bounce's reflectance). For a
/// light whose falloff is not 1/d^2 the photons' first-hit rescaling counts too, so the
/// "fraction" is the visible power over the nominal power and may exceed 1. Lights
/// with `emits[l] == false` are not measured (0). Deterministic: photon i of light l draws from
/// its own random stream.
template <class SceneT>
[[nodiscard]] std::vector<double> visible_power_fractions(const SceneT& scene,
                                                          const Camera<typename SceneT::scalar_type>& camera,
                                                          const std::vector<bool>& emits, EmissionSampler sampler,
                                                          const VisiblePowerPilot& pilot = {}) {
    using S = typename SceneT::scalar_type;
    const auto lights = scene.lights();
    std::vector<double> fraction(lights.size(), 0.0);
    for (std::size_t l = 0; l < lights.size(); ++l) {
        if (l < emits.size() && !emits[l]) continue;
        double seen = 0.0;
        for (unsigned i = 0; i < pilot.photons_per_light; ++i) {
            Pcg32 rng(pilot.seed ^ 0x70696c6f74ULL, std::uint64_t(l) * pilot.photons_per_light + i);
            const Vec3<S> dir = sample_emission_direction(lights[l], sampler, rng);
            Ray<S> ray{leaving_light(sample_emission_origin(lights[l], dir, rng.uniform2<S>()), dir), dir};
            // The power the photon would carry: its direction's share of the profile, and the
            // light's falloff at its first hit, so a light that does not fall off (POV-Ray's
            // default) counts the power its photons really bring, not its nominal power.
            double weight = double(emission_weight(lights[l], dir));
            for (unsigned hit = 0; hit < 2; ++hit) {
                unsigned passed = 0;
                const auto surface = photon_intersect(scene, ray, passed);
                if (!surface) break;
                if (hit == 0) weight *= double(first_hit_scale(lights[l], surface->hit.point, ray.origin));
                const Material<S>& material = *surface->material;
                if (material.has_diffuse() && camera_sees(scene, camera, surface->hit.point)) {
                    seen += weight;
                    break;
                }
                const Facing<S> f = facing(material, surface->hit.point, surface->hit.normal, ray.direction);
                weight *= double(average(segment_transmittance(material, f, surface->hit.t)));
                const PhotonScatter<S> s = russian_roulette(material, surface->hit.point, f, ray.direction, rng);
                if (s.event == ScatterEvent::absorbed) break;
                weight *= double(average(s.weight));
                const Vec3<S> side = s.event == ScatterEvent::transmission ? -f.normal : f.normal;
                ray = Ray<S>{offset_origin(surface->hit.point, side, intersection_error(surface->hit.point, ray.origin)),
                             s.direction};
            }
        }
        fraction[l] = pilot.photons_per_light ? seen / double(pilot.photons_per_light) : 0.0;
    }
    return fraction;
}

/// Relative photon shares from each light's power P and visible fraction f: P sqrt(f) (a light
/// whose visible power is a quarter of another's gets half its photons, not a quarter: the
/// pilot is coarse, and a light's photons also light what the camera sees through mirrors),
/// mixed with the power share by `floor`. Lights with `emits[l] == false` get 0.
template <Scalar S>
[[nodiscard]] std::vector<double> visible_power_shares(std::span<const Light<S>> lights, const std::vector<double>& fraction,
                                                       const std::vector<bool>& emits, double floor) {
    std::vector<double> power(lights.size(), 0.0), visible(lights.size(), 0.0);
    double power_sum = 0.0, visible_sum = 0.0;
    for (std::size_t l = 0; l < lights.size(); ++l) {
        if (l < emits.size() && !emits[l]) continue;
        power[l] = std::max(0.0, double(average(light_power(lights[l]))));
        // Not clamped to 1: a non-physical light's photons may bring more than its nominal power.
        const double f = l < fraction.size() && std::isfinite(fraction[l]) ? std::max(0.0, fraction[l]) : 0.0;
        visible[l] = power[l] * std::sqrt(f);
        power_sum += power[l];
        visible_sum += visible[l];
    }
    std::vector<double> share(lights.size(), 0.0);
    if (!(power_sum > 0.0)) return share;
    const double f = visible_sum > 0.0 ? std::clamp(floor, 0.0, 1.0) : 1.0;  // the pilot saw nothing: by power
    for (std::size_t l = 0; l < lights.size(); ++l)
        share[l] = f * power[l] / power_sum + (visible_sum > 0.0 ? (1.0 - f) * visible[l] / visible_sum : 0.0);
    return share;
}

}  // namespace photon
