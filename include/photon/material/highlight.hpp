// SPDX-License-Identifier: MIT
#pragma once
// POV-Ray's finish terms for light from light sources (POV-Ray 3.7, trace.cpp: ComputeDiffuseColour,
// ComputePhongColour, ComputeSpecularColour): the Phong and Blinn highlights, their metallic tint,
// and brilliance. Each is a term of the light reflected towards the camera from shadow rays, not a
// BRDF: none of them conserves energy, and no path, photon or gather carries them on. POV-Ray
// leaves highlights out of its radiosity rays too; photon adds all of them only where the camera
// sees a surface (directly or through mirrors and glass), in every mode alike.
//
// Units: POV-Ray's pixel is colour * brightness * term; photon's irradiance E from that light is
// pi * colour * brightness, so each term below is POV-Ray's divided by pi.

#include <algorithm>
#include <cmath>

#include "../math/vec.hpp"
#include "fresnel.hpp"
#include "material.hpp"

namespace photon {

/// POV-Ray's phong term for light arriving from unit `wi`, seen from `wo`: strength *
/// cos(alpha)^size, alpha between the mirrored light direction and the viewer, over pi.
template <Scalar S>
[[nodiscard]] S phong_highlight(const Material<S>& material, const Vec3<S>& n, const Vec3<S>& wo, const Vec3<S>& wi) noexcept {
    const S phong = material.params().phong;
    if (!(phong > S(0))) return S(0);
    const S c = glm::dot(reflect(-wi, n), wo);
    return c > S(0) ? phong * std::pow(c, material.params().phong_exponent) * inv_pi<S> : S(0);
}

/// POV-Ray's specular (Blinn) term: strength * cos(beta)^(1 / roughness), beta between the
/// normal and the half-way vector of `wi` and `wo`, over pi.
template <Scalar S>
[[nodiscard]] S blinn_highlight(const Material<S>& material, const Vec3<S>& n, const Vec3<S>& wo, const Vec3<S>& wi) noexcept {
    const S blinn = material.params().blinn;
    if (!(blinn > S(0))) return S(0);
    const Vec3<S> h = wo + wi;
    const S length = glm::length(h);
    if (!(length > S(0))) return S(0);
    const S c = glm::dot(h, n) / length;
    return c > S(0) ? blinn * std::pow(c, material.params().blinn_exponent) * inv_pi<S> : S(0);
}

/// POV-Ray's empirical Fresnel curve for metallic highlights (Daniel Burrows, 1994) at light
/// incidence cos_i: 0 at normal incidence, rising to 1 at grazing light.
template <Scalar S> [[nodiscard]] S metallic_fresnel(S cos_i) noexcept {
    const S x = std::acos(std::clamp(cos_i, S(-1), S(1))) / (pi<S> / S(2));
    const S f = S(0.014567225) / ((x - S(1.12)) * (x - S(1.12))) - S(0.011612903);
    return std::clamp(f, S(0), S(1));
}

/// The highlights (phong + blinn) for light from unit `wi` seen from `wo`, per unit irradiance,
/// in the light's colour, or with metallic m blended towards `surface_color` (the material's
/// highlight_color_at the point) by m (1 - F): POV-Ray's 1 + m (1 - F) (colour - 1).
template <Scalar S>
[[nodiscard]] Rgb<S> highlight(const Material<S>& material, const Rgb<S>& surface_color, const Vec3<S>& n,
                               const Vec3<S>& wo, const Vec3<S>& wi) noexcept {
    const S strength = phong_highlight(material, n, wo, wi) + blinn_highlight(material, n, wo, wi);
    const S m = material.params().metallic;
    if (!(strength > S(0)) || !(m > S(0))) return Rgb<S>(strength);
    const S blend = m * (S(1) - metallic_fresnel(glm::dot(n, wi)));
    return strength * (Rgb<S>(S(1)) + blend * (surface_color - Rgb<S>(S(1))));
}

/// POV-Ray's diffuse intensity for direct light at cos_theta > 0: cos^brilliance (cos when
/// brilliance is 1, Lambert's law).
template <Scalar S> [[nodiscard]] S diffuse_cosine(const Material<S>& material, S cos_theta) noexcept {
    return material.has_brilliance() ? std::pow(cos_theta, material.params().brilliance) : cos_theta;
}

}  // namespace photon
