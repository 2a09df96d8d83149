// SPDX-License-Identifier: MIT
#pragma once
// Which side of a surface a ray is on, and the photon's Russian roulette (paper, section 3.1).

#include <cmath>

#include "../math/frame.hpp"
#include "../math/rng.hpp"
#include "../math/sampling.hpp"
#include "material.hpp"

namespace photon {

/// The geometric normal turned towards an incoming unit direction.
template <Scalar S> struct Facing {
    Vec3<S> normal;  ///< unit, on the side the ray comes from
    S cos_i;         ///< cosine between the reversed ray and `normal`, in [0, 1]
    bool entering;   ///< the ray arrives on the side the geometric normal points to (outside)
};

template <Scalar S> [[nodiscard]] Facing<S> facing(const Vec3<S>& geometric_normal, const Vec3<S>& dir) noexcept {
    const S c = -glm::dot(dir, geometric_normal);
    return c >= S(0) ? Facing<S>{geometric_normal, c, true} : Facing<S>{-geometric_normal, -c, false};
}

/// Ratio of the indices of refraction across the surface for a ray on side `entering`.
template <Scalar S> [[nodiscard]] S relative_eta(const Material<S>& m, bool entering) noexcept {
    return entering ? S(1) / m.ior() : m.ior();
}

enum class ScatterEvent { diffuse, specular, transmission, absorbed };

/// Outcome of one Russian roulette step: the event, the new direction, and the factor that
/// scales the photon's power per channel (rho / rho_avg of the chosen event).
template <Scalar S> struct PhotonScatter {
    ScatterEvent event = ScatterEvent::absorbed;
    Vec3<S> direction{};
    Rgb<S> weight{S(0)};
};

/// Russian roulette on channel-averaged reflectances: with psi uniform in [0,1), psi below
/// rho_d,avg reflects diffusely, below rho_d,avg + rho_s,avg specularly, below that + rho_t,avg
/// transmits, else the photon is absorbed. The survivor's power is scaled per channel by
/// rho / rho_avg so that the expected power per channel is exact (paper, section 3.1).
/// `s` is material.scattering() at the hit (its diffuse part the texture's value there).
template <Scalar S>
[[nodiscard]] PhotonScatter<S> russian_roulette(const Material<S>& material, const Scattering<S>& s, const Facing<S>& f,
                                                const Vec3<S>& dir, Pcg32& rng) noexcept {
    const S pd = average(s.diffuse), ps = average(s.specular), pt = average(s.transmission);
    const S psi = rng.uniform<S>();
    const Vec2<S> u = rng.uniform2<S>();
    if (psi < pd) {
        return {ScatterEvent::diffuse, Frame<S>::from_normal(f.normal).to_world(cosine_hemisphere(u)), s.diffuse / pd};
    }
    if (psi < pd + ps) return {ScatterEvent::specular, reflect(dir, f.normal), s.specular / ps};
    if (psi < pd + ps + pt) {
        if (const auto refracted = refract(dir, f.normal, relative_eta(material, f.entering)))
            return {ScatterEvent::transmission, *refracted, s.transmission / pt};
        // Total internal reflection of a non-Fresnel transmitter: the light stays inside.
        return {ScatterEvent::specular, reflect(dir, f.normal), s.transmission / pt};
    }
    return {};
}

/// Russian roulette at hit point `x`, where a textured material's reflectance is read.
template <Scalar S>
[[nodiscard]] PhotonScatter<S> russian_roulette(const Material<S>& material, const Vec3<S>& x, const Facing<S>& f,
                                                const Vec3<S>& dir, Pcg32& rng) {
    return russian_roulette(material, material.scattering(x, f.cos_i, f.entering), f, dir, rng);
}

}  // namespace photon
