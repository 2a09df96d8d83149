// SPDX-License-Identifier: MIT
#pragma once
// POV-Ray's highlights: terms a surface adds to the light it reflects from light sources only
// (shadow rays), never to light that paths or photons carry. They are not a BRDF that
// conserves energy; photon adds them, as POV-Ray does, so that POV-Ray's shiny surfaces look
// as their authors meant.

#include <cmath>

#include "../math/vec.hpp"
#include "fresnel.hpp"
#include "material.hpp"

namespace photon {

/// POV-Ray's phong term for light arriving from unit `wi`, seen from `wo`: strength *
/// cos(alpha)^size, alpha between the mirrored light direction and the viewer; E / pi converts
/// it to radiance units. Direct light only: it is not a BRDF that paths could sample.
template <Scalar S>
[[nodiscard]] S phong_highlight(const Material<S>& material, const Vec3<S>& n, const Vec3<S>& wo, const Vec3<S>& wi) noexcept {
    const S phong = material.params().phong;
    if (!(phong > S(0))) return S(0);
    const S c = glm::dot(reflect(-wi, n), wo);
    return c > S(0) ? phong * std::pow(c, material.params().phong_exponent) * inv_pi<S> : S(0);
}

}  // namespace photon
