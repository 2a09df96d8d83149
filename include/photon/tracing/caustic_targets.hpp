// SPDX-License-Identifier: MIT
#pragma once
// Aiming caustic photons: instead of Jensen's projection maps, each light shoots into the cones
// that bound the caustic targets (mirror and glass objects) as seen from the whole light. A photon
// drawn from the mixture of cones is weighted by the mixture's density, so overlapping cones are
// counted once (a one-sample balance heuristic) and the caustic map stays unbiased.

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include "../geometry/bbox.hpp"
#include "../light/light.hpp"
#include "../math/frame.hpp"
#include "../math/sampling.hpp"

namespace photon {

/// Directions from a light that can reach one target.
template <Scalar S> struct TargetCone {
    Vec3<S> axis;
    S one_minus_cos;  ///< 1 - cos of the half-angle; 2: the whole sphere of directions
    S solid_angle;
    Frame<S> frame;

    [[nodiscard]] bool contains(const Vec3<S>& d) const noexcept { return one_minus_cos_between(d, axis) <= one_minus_cos; }
};

/// Cones from `light` to targets bounded by spheres (centre, radius). The cone is widened by the
/// light's own radius so that it covers rays leaving any point of a sphere light.
template <Scalar S>
[[nodiscard]] std::vector<TargetCone<S>> target_cones(const Light<S>& light,
                                                      const std::vector<std::pair<Vec3<S>, S>>& targets) {
    std::vector<TargetCone<S>> cones;
    const Vec3<S> origin = light_center(light);
    const S light_r = light_radius(light);
    for (const auto& [center, radius] : targets) {
        const Vec3<S> to = center - origin;
        const S d = glm::length(to);
        const S reach = radius + light_r;
        TargetCone<S> cone;
        if (!(d > reach)) {
            cone.axis = {S(0), S(0), S(1)};
            cone.one_minus_cos = S(2);
        } else {
            // 1 - cos = sin^2 / (1 + cos): a small target far away keeps its solid angle.
            cone.axis = to / d;
            const S sin2 = squared(reach / d);
            cone.one_minus_cos = sin2 / (S(1) + std::sqrt(std::max(S(0), S(1) - sin2)));
        }
        cone.solid_angle = cone_solid_angle_1mc(cone.one_minus_cos);
        cone.frame = Frame<S>::from_normal(cone.axis);
        cones.push_back(cone);
    }
    return cones;
}

/// A direction from the mixture of cones (each chosen in proportion to its solid angle) and its
/// density per steradian: (number of cones containing it) / (sum of solid angles).
template <Scalar S> struct ConeMixtureSample {
    Vec3<S> direction;
    S pdf;
};

template <Scalar S>
[[nodiscard]] ConeMixtureSample<S> sample_cone_mixture(const std::vector<TargetCone<S>>& cones, S total_solid_angle,
                                                       Pcg32& rng) noexcept {
    S pick = rng.uniform<S>() * total_solid_angle;
    std::size_t chosen = cones.size() - 1;
    for (std::size_t i = 0; i < cones.size(); ++i) {
        if (pick < cones[i].solid_angle) {
            chosen = i;
            break;
        }
        pick -= cones[i].solid_angle;
    }
    const TargetCone<S>& c = cones[chosen];
    const Vec3<S> d = c.frame.to_world(uniform_cone_1mc(rng.uniform2<S>(), c.one_minus_cos));
    unsigned covering = 0;
    for (const auto& cone : cones) covering += cone.contains(d) ? 1u : 0u;
    covering = std::max(covering, 1u);  // the chosen cone contains d up to rounding
    return {d, S(covering) / total_solid_angle};
}

/// Where each light's caustic photons are aimed: the cones around the bounding spheres of the
/// scene's caustic targets, per light. The caustic pass samples them; the global pass asks
/// covers() which of its L S+ D photons the caustic pass could also have produced, and hands
/// the others to the caustic map itself, so that no caustic path is lost (an infinite mirror
/// plane cannot be aimed at, a mirror with `photons { }` but no `target` is not).
template <Scalar S> struct CausticAim {
    std::vector<std::vector<TargetCone<S>>> cones;  ///< per light; empty: no caustic pass
    std::vector<S> total_solid_angle;               ///< per light

    [[nodiscard]] bool empty() const noexcept {
        for (const auto& c : cones)
            if (!c.empty()) return false;
        return true;
    }
    /// Per light, whether it shoots caustic photons: it may emit (`emits`, empty: all) and has a
    /// target its cone can reach.
    [[nodiscard]] std::vector<bool> aiming_lights(std::size_t lights, const std::vector<bool>& emits = {}) const {
        std::vector<bool> aiming(lights, false);
        for (std::size_t l = 0; l < lights && l < cones.size(); ++l)
            aiming[l] = (l >= emits.size() || emits[l]) && !cones[l].empty();
        return aiming;
    }
    [[nodiscard]] bool covers(std::size_t light, const Vec3<S>& direction) const noexcept {
        if (light >= cones.size()) return false;
        for (const auto& c : cones[light])
            if (c.contains(direction)) return true;
        return false;
    }
};

/// Whether caustic photons can be aimed at object `i`: a caustic target with finite bounds.
template <class SceneT> [[nodiscard]] bool is_aimable_target(const SceneT& scene, std::uint32_t i) {
    return scene.is_caustic_target(i) && scene.object_bounds(i).is_finite();
}

/// Whether a light's cone (axis, half-angle) and a target's cone of directions can share a
/// direction: the angle between their axes is at most the sum of their half-angles (plus 1e-3
/// radians for rounding). A target cone of the whole sphere always can.
template <Scalar S> [[nodiscard]] bool cones_meet(const Cone<S>& light, const TargetCone<S>& target) noexcept {
    if (!(target.one_minus_cos < S(2))) return true;
    const double target_half = std::acos(std::clamp(1.0 - double(target.one_minus_cos), -1.0, 1.0));
    const double light_half = double(light.half_angle_degrees()) * pi<double> / 180.0;
    const double between = std::acos(std::clamp(double(glm::dot(light.axis(), target.axis)), -1.0, 1.0));
    return between <= light_half + target_half + 1e-3;
}

/// The cones of every light towards every aimable caustic target, but those with `skip[i]` (the
/// light-path plan's targets whose caustics the camera cannot see) and, for a light with a cone
/// (a spotlight), the targets its cone cannot reach: their photons would all be thrown away.
template <class SceneT>
[[nodiscard]] CausticAim<typename SceneT::scalar_type> caustic_aim(const SceneT& scene, const std::vector<bool>& skip = {}) {
    using S = typename SceneT::scalar_type;
    std::vector<std::pair<Vec3<S>, S>> targets;
    for (std::uint32_t i = 0; i < scene.objects().size(); ++i) {
        if (!is_aimable_target(scene, i) || (i < skip.size() && skip[i])) continue;
        const BBox<S> b = scene.object_bounds(i);
        targets.push_back({b.center(), glm::length(b.extent()) * S(0.5)});
    }
    CausticAim<S> aim;
    if (targets.empty()) return aim;
    for (const auto& light : scene.lights()) {
        aim.cones.push_back(target_cones(light, targets));
        if (const auto& cone = light_cone(light))
            std::erase_if(aim.cones.back(), [&](const TargetCone<S>& t) { return !cones_meet(*cone, t); });
        S sum = 0;
        for (const auto& c : aim.cones.back()) sum += c.solid_angle;
        aim.total_solid_angle.push_back(sum);
    }
    return aim;
}

/// What to tell the user about each object unaimed_specular_objects() lists.
inline constexpr const char* unaimed_caustics_warning =
    "mirror or glass object that caustic photons are not aimed at (an infinite plane, or no `target`): "
    "its caustics come from the global photons alone, rendered but noisier";

/// Mirror and glass objects the caustic pass cannot aim at: their caustics reach the caustic map
/// only through the global photons, which are far fewer there (noisier, not lost).
template <class SceneT> [[nodiscard]] std::vector<std::uint32_t> unaimed_specular_objects(const SceneT& scene) {
    std::vector<std::uint32_t> ids;
    for (std::uint32_t i = 0; i < scene.objects().size(); ++i)
        if (scene.any_material_of(i, is_specular_material) && !is_aimable_target(scene, i)) ids.push_back(i);
    return ids;
}

}  // namespace photon
