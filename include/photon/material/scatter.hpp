// SPDX-License-Identifier: MIT
#pragma once
// Which side of a surface a ray is on, with its geometric and shading normals, and the Russian
// roulette that continues photons and paths (paper, section 3.1).

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <optional>

#include "../math/frame.hpp"
#include "../math/rng.hpp"
#include "../math/sampling.hpp"
#include "material.hpp"

namespace photon {

/// The surface at a hit as a ray arriving along a unit direction meets it. Two normals: the
/// geometric one, which decides the side (offsets of new rays, entering or leaving) and which
/// directions leave the surface, and the shading one, which a material's normal field tilts and
/// which every pass uses for cosines, the diffuse lobe, mirror and refraction (camera shading,
/// shadow rays, final gathering, photons, the path tracer and sppm alike).
template <Scalar S> struct Facing {
    Vec3<S> normal;  ///< unit geometric normal, on the side the ray comes from
    S cos_i;         ///< cosine between the reversed ray and `normal`, in [0, 1]
    bool entering;   ///< the ray arrives on the side the geometric normal points to (outside)
    Vec3<S> shading{normal};  ///< unit shading normal on the same side; `normal` unless perturbed
    S shading_cos{cos_i};     ///< cosine between the reversed ray and `shading`
    bool perturbed = false;   ///< a normal field tilted `shading`
};

template <Scalar S> [[nodiscard]] Facing<S> facing(const Vec3<S>& geometric_normal, const Vec3<S>& dir) noexcept {
    const S c = -glm::dot(dir, geometric_normal);
    const Vec3<S> n = c >= S(0) ? geometric_normal : -geometric_normal;
    return {n, std::abs(c), c >= S(0), n, std::abs(c), false};
}

/// The smallest cosine a guarded shading normal keeps with the viewer (about 89.4 degrees).
template <Scalar S> inline constexpr S min_shading_cos = S(0.01);

/// A tilted unit normal `tilted`, already on the side of the unit geometric normal `n` the
/// viewer `wo` (unit, cos_wo = dot(n, wo) >= 0) is on, made safe to shade with, as robust
/// renderers do. First a tilt past the geometric tangent plane is mirrored back across it
/// (flip: bumps never face into the surface). Then, if the viewer would see the back of the
/// tilted tangent plane (a bump's far slope at a grazing view), the normal is bent towards `n`
/// until it faces the viewer at min_shading_cos (clamp: the bump's back is shaded as seen
/// edge-on, not black, and no ray leaves on the wrong side). At a view within 1e-6 of grazing
/// the geometric normal is used.
template <Scalar S>
[[nodiscard]] Vec3<S> guard_shading_normal(Vec3<S> tilted, const Vec3<S>& n, const Vec3<S>& wo, S cos_wo) noexcept {
    const S below = glm::dot(tilted, n);
    if (below < S(0)) tilted -= S(2) * below * n;
    const S seen = glm::dot(tilted, wo);
    if (seen >= min_shading_cos<S>) return tilted;
    if (!(cos_wo > S(1e-6))) return n;
    const Vec3<S> bent = tilted + ((min_shading_cos<S> - seen) / cos_wo) * n;
    const S length = glm::length(bent);
    return length > S(0) && std::isfinite(length) ? bent / length : n;
}

/// facing() for a hit at `point` of a surface of `material` with unit outward geometric normal
/// `geometric_normal`: with the material's normal field, the shading normal is its tilt of that
/// normal, turned to the ray's side and guarded (guard_shading_normal).
template <Scalar S>
[[nodiscard]] Facing<S> facing(const Material<S>& material, const Vec3<S>& point, const Vec3<S>& geometric_normal,
                               const Vec3<S>& dir) {
    Facing<S> f = facing(geometric_normal, dir);
    if (!material.has_normal_field()) [[likely]]
        return f;
    const Vec3<S> tilted = material.shading_normal(point, geometric_normal);
    f.shading = guard_shading_normal(f.entering ? tilted : -tilted, f.normal, -dir, f.cos_i);
    f.shading_cos = glm::dot(f.shading, -dir);
    f.perturbed = true;
    return f;
}

/// `v` (unit) kept at least a little on the side `side` (unit) points to: a mirror or refracted
/// direction about a tilted shading normal may point into the surface it leaves, and is then
/// pushed back along `side` to leave nearly tangentially.
template <Scalar S> [[nodiscard]] Vec3<S> keep_on_side(const Vec3<S>& v, const Vec3<S>& side) noexcept {
    constexpr S least = S(1e-3);
    const S c = glm::dot(v, side);
    if (c >= least) return v;
    return glm::normalize(v + (least - c) * side);
}

/// The mirror direction of `dir` at the surface `f`: about the shading normal, kept above the
/// geometric surface.
template <Scalar S> [[nodiscard]] Vec3<S> mirror_direction(const Vec3<S>& dir, const Facing<S>& f) noexcept {
    const Vec3<S> r = reflect(dir, f.shading);
    return f.perturbed ? keep_on_side(r, f.normal) : r;
}

/// The refracted direction of `dir` at the surface `f` with relative index `eta` (none: total
/// internal reflection): about the shading normal, kept below the geometric surface.
template <Scalar S>
[[nodiscard]] std::optional<Vec3<S>> refraction_direction(const Vec3<S>& dir, const Facing<S>& f, S eta) noexcept {
    auto t = refract(dir, f.shading, eta);
    if (t && f.perturbed) *t = keep_on_side(*t, -f.normal);
    return t;
}

/// The largest factor shading_ratio() gives: it grows without bound as a photon arrives
/// grazing the geometric surface onto a bump that faces it, and its variance with it.
template <Scalar S> inline constexpr S max_shading_ratio = S(10);

/// cos(shading) / cos(geometric) for light arriving at `f`: the factor by which a photon's power,
/// a flux through the geometric surface, becomes its share of the irradiance the shading normal
/// sees (Veach 1997, section 5.3, the adjoint BSDF with shading normals). Exactly 1 without a
/// normal field; capped at max_shading_ratio (a small bias for photons within a few degrees of
/// grazing, said in docs/design.md).
template <Scalar S> [[nodiscard]] S shading_ratio(const Facing<S>& f) noexcept {
    if (!f.perturbed || !(f.cos_i > S(0))) return S(1);
    return std::min(std::max(f.shading_cos, S(0)) / f.cos_i, max_shading_ratio<S>);
}

/// The fraction of light per channel that survives the segment of length `t` a ray or photon
/// travelled to reach the hit `f` on a surface of `material`: the material's absorption over t
/// when the segment ends on the inside (it ran inside the object), else 1. Every pass calls it
/// at every hit, so camera rays, photons, sppm paths and the path tracer absorb alike. Nested
/// objects: a segment inside one absorbing object that ends on another object's outside is not
/// absorbed (photon keeps no stack of the media a path is in).
template <Scalar S>
[[nodiscard]] Rgb<S> segment_transmittance(const Material<S>& material, const Facing<S>& f, S t) {
    if (f.entering || !material.absorbs()) [[likely]]
        return Rgb<S>(S(1));
    return material.params().absorption.transmittance(t);
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

/// Which way light flows along the path being continued: photons carry light from the lights,
/// camera paths (the path tracer) gather it towards the camera. Only a tilted shading normal
/// makes the two differ (scattering with shading normals is not symmetric).
enum class PathFlow : std::uint8_t { from_light, from_camera };

/// Russian roulette on channel-averaged reflectances: with psi uniform in [0,1), psi below
/// rho_d,avg reflects diffusely, below rho_d,avg + rho_s,avg specularly, below that + rho_t,avg
/// transmits, else the photon is absorbed. The survivor's power is scaled per channel by
/// rho / rho_avg so that the expected power per channel is exact (paper, section 3.1).
/// `s` is material.scattering() at the hit (its diffuse part the texture's value there).
/// Under a tilted shading normal the diffuse lobe differs by `flow`: a camera path samples
/// cos(shading) and ends where that sends it into the surface (the Lambertian integral over the
/// directions that leave it); a photon leaves by cos(geometric) with its power scaled by
/// shading_ratio() (the adjoint of the same BRDF), so both compute the same radiance.
template <Scalar S>
[[nodiscard]] PhotonScatter<S> russian_roulette(const Material<S>& material, const Scattering<S>& s, const Facing<S>& f,
                                                const Vec3<S>& dir, Pcg32& rng,
                                                PathFlow flow = PathFlow::from_light) noexcept {
    const S pd = average(s.diffuse), ps = average(s.specular), pt = average(s.transmission);
    const S psi = rng.uniform<S>();
    const Vec2<S> u = rng.uniform2<S>();
    if (psi < pd) {
        if (flow == PathFlow::from_light)
            return {ScatterEvent::diffuse, Frame<S>::from_normal(f.normal).to_world(cosine_hemisphere(u)),
                    s.diffuse / pd * shading_ratio(f)};
        const Vec3<S> out = Frame<S>::from_normal(f.shading).to_world(cosine_hemisphere(u));
        if (f.perturbed && !(glm::dot(out, f.normal) > S(0))) return {};
        return {ScatterEvent::diffuse, out, s.diffuse / pd};
    }
    if (psi < pd + ps) return {ScatterEvent::specular, mirror_direction(dir, f), s.specular / ps};
    if (psi < pd + ps + pt) {
        if (const auto refracted = refraction_direction(dir, f, relative_eta(material, f.entering)))
            return {ScatterEvent::transmission, *refracted, s.transmission / pt};
        // Total internal reflection of a non-Fresnel transmitter: the light stays inside.
        return {ScatterEvent::specular, mirror_direction(dir, f), s.transmission / pt};
    }
    return {};
}

/// Russian roulette at hit point `x`, where a textured material's reflectance is read.
template <Scalar S>
[[nodiscard]] PhotonScatter<S> russian_roulette(const Material<S>& material, const Vec3<S>& x, const Facing<S>& f,
                                                const Vec3<S>& dir, Pcg32& rng,
                                                PathFlow flow = PathFlow::from_light) {
    return russian_roulette(material, material.scattering(x, f.shading_cos, f.entering), f, dir, rng, flow);
}

}  // namespace photon
