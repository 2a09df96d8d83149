// SPDX-License-Identifier: MIT
#pragma once
// POV-Ray's shadow rays through transparent surfaces (trace.cpp, TracePointLightShadowRay and
// ComputeShadowColour), for rt: a shadow ray that meets a surface which transmits light goes on
// in a straight line (no refraction), its light multiplied by the surface's transmission
// (POV-Ray's filter times the colour plus transmit), and dimmed by an absorbing interior over the
// length it runs inside; an opaque surface stops it. Glass then casts the light, tinted, soft
// shadow POV-Ray draws without photons. pm does not use it: there, light through glass arrives
// by the caustic photons, and a filtered shadow ray would count it twice.

#include "../geometry/offset.hpp"
#include "../material/scatter.hpp"
#include "../math/vec.hpp"

namespace photon {

/// Crossings a filtered shadow ray follows before it is taken as blocked (a stack of panes).
inline constexpr unsigned filtered_shadow_crossings = 64;

/// The fraction of light, per channel, that reaches the end of shadow ray `ray` (from a shading
/// point to a light, t_max the light's distance) through the transparent surfaces on its way;
/// 0 where an opaque surface lies on it. Objects that cast no shadows are passed.
template <class SceneT, Scalar S>
[[nodiscard]] Rgb<S> filtered_shadow(const SceneT& scene, Ray<S> ray) {
    Rgb<S> pass(S(1));
    for (unsigned crossing = 0; crossing < filtered_shadow_crossings; ++crossing) {
        const auto surface = scene.intersect_shadow_casters(ray);
        if (!surface) return pass;
        const Material<S>& m = *surface->material;
        const Rgb<S>& transmission = m.params().transmission;
        if (is_black(transmission)) return Rgb<S>(S(0));
        const Vec3<S>& x = surface->hit.point;
        const Facing<S> f = facing(surface->hit.normal, ray.direction);
        // Dimmed inside, on the way out; but as POV-Ray's shadow rays (ComputeShadowTexture, which
        // fades only where fade_power > 0), not by the fade its camera rays take at power 0.
        const auto& absorption = m.params().absorption;
        const bool unfaded = absorption.law() == Absorption<S>::Law::pov_fade && absorption.fade_power() == S(0);
        pass *= transmission * (unfaded ? Rgb<S>(S(1)) : segment_transmittance(m, f, surface->hit.t));
        if (max_component(pass) <= S(0)) return pass;
        // On, past the surface, along the same line.
        const Vec3<S> next = offset_origin(x, -f.normal, intersection_error(x, ray.origin));
        ray.t_max -= glm::length(next - ray.origin);
        ray.origin = next;
        if (!(ray.t_max > S(0))) return pass;
    }
    return Rgb<S>(S(0));
}

}  // namespace photon
