// SPDX-License-Identifier: MIT
#pragma once
// POV-Ray's area light (`area_light A1, A2, N1, N2 [jitter] [circular]`): an N1 x N2
// grid of isotropic point emitters sharing the light's power, spanning the parallelogram of the
// two axes centred on the light. Grid position (u, v), u in 0..N1-1, sits at
// centre + A1 (u / (N1 - 1) - 0.5) + A2 (v / (N2 - 1) - 0.5), on the parallelogram's corners
// and edges (POV-Ray 3.7, Trace::TraceAreaLightSubsetShadowRay); an axis with one light adds 0.
// `jitter` moves each emitter uniformly within +-half a cell around its grid position on every
// sample, so over many samples the emitters fill a parallelogram half a cell wider on each side:
// photon draws that continuous emitter. `circular` maps the square of grid coordinates onto a
// disc (POV-Ray's shells: each coordinate pair is scaled by its max-norm over its length after
// POV-Ray's +0.001 offset). The emitters are points: no ray meets them, and each lights a point
// by I cos(theta) g(d) of its own direction and distance d (g the falloff, 1/d^2 when physical),
// as POV-Ray's `area_illumination` computes (without it POV-Ray takes the cosine and distance of
// the centre for every emitter).
// POV-Ray's `orient` (the grid turned to face each lit point) is no emitter photons can leave:
// a photon's receiver is not known when it leaves. Its picture, a disc facing every point it
// lights, is a Lambertian sphere's silhouette: SphereLight.

#include <cmath>
#include <optional>
#include <stdexcept>

#include <glm/geometric.hpp>

#include "cone.hpp"
#include "falloff.hpp"

namespace photon {

template <Scalar S> struct AreaLight {
    Vec3<S> center{};
    Vec3<S> axis1{}, axis2{};
    unsigned size1 = 1, size2 = 1;  ///< emitters along axis1 and axis2
    bool jitter = false, circular = false;
    /// POV-Ray's `adaptive N`: where photon renders as POV-Ray does (rt and pm's direct light),
    /// the grid is shadow-tested from its corners and refined where their shadows differ, at least
    /// N levels deep (integrator/area_light_adaptive.hpp). None: every emitter, as POV-Ray without it.
    std::optional<unsigned> adaptive{};
    Rgb<S> power{S(0)};
    std::optional<Cone<S>> cone{};
    Falloff<S> falloff{};        ///< physical 1/d^2 unless set (POV-Ray's fades)
    bool casts_shadows = true;   ///< false: direct light without shadow rays or highlights (POV-Ray's `shadowless`)
    bool media_interaction = true;   ///< false: participating media scatter none of it (POV-Ray's `media_interaction off`)
    bool media_attenuation = false;  ///< true: atmospheric media dim its shadow rays (POV-Ray's `media_attenuation on`)

    /// Throws std::invalid_argument on a non-finite centre or axis, a size of 0, a circular light
    /// with a size of 1 (POV-Ray's error too: its mapping divides by 0 there), or a negative or
    /// non-finite power. Zero or parallel axes are allowed: the grid then lies on a line or a
    /// point (POV-Ray renders those too).
    void validate() const {
        if (!is_finite(center)) throw std::invalid_argument("light: position must be finite");
        if (!is_finite(axis1) || !is_finite(axis2)) throw std::invalid_argument("light: area light axes must be finite");
        if (size1 == 0 || size2 == 0) throw std::invalid_argument("light: an area light needs at least 1 x 1 emitters");
        if (circular && (size1 < 2 || size2 < 2))
            throw std::invalid_argument("light: a circular area light needs more than 1 emitter along each axis");
        if (!is_finite(power) || min_component(power) < S(0))
            throw std::invalid_argument("light: power must be finite and >= 0 in every channel");
        falloff.validate();
    }

    /// The number of distinct emitters: N1 N2, or 0 for a jittered light (a continuum).
    [[nodiscard]] unsigned emitters() const noexcept { return jitter ? 0u : size1 * size2; }

    /// Offset from the centre of the emitter that u, uniform in [0,1)^2, picks: grid cell
    /// floor(u N) (its jittered point for `jitter`), so that u stratified N1 x N2 takes every
    /// emitter once.
    [[nodiscard]] Vec3<S> emitter_offset(Vec2<S> u) const noexcept {
        S s = grid_coordinate(u.x, size1), t = grid_coordinate(u.y, size2);
        if (circular) {
            s += S(0.001), t += S(0.001);  // POV-Ray's offset, which keeps the centre off 0 / 0
            const S scale = std::max(std::abs(s), std::abs(t)) / std::sqrt(s * s + t * t);
            s *= scale, t *= scale;
        }
        return s * axis1 + t * axis2;
    }

    /// Radius of a ball around `center` holding every emitter.
    [[nodiscard]] S bounding_radius() const noexcept {
        const S l1 = glm::length(axis1), l2 = glm::length(axis2);
        const S h1 = half_extent(size1), h2 = half_extent(size2);
        // Circular maps a coordinate pair to one no longer than its max-norm.
        if (circular) return (std::max(h1, h2) + S(0.001)) * (l1 + l2);
        return h1 * l1 + h2 * l2;
    }

private:
    /// Coordinate along an axis of n emitters, in units of the axis, from u in [0,1).
    [[nodiscard]] S grid_coordinate(S u, unsigned n) const noexcept {
        if (n == 1) return S(0);
        const S cell = jitter ? u * S(n) - S(0.5) : std::min(std::floor(u * S(n)), S(n - 1));
        return cell / S(n - 1) - S(0.5);
    }
    [[nodiscard]] S half_extent(unsigned n) const noexcept {
        if (n == 1) return S(0);
        return jitter ? S(0.5) * S(n) / S(n - 1) : S(0.5);
    }
};

}  // namespace photon
