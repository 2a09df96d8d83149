// SPDX-License-Identifier: MIT
#pragma once
// Aiming caustic photons: instead of Jensen's projection maps, each light shoots into the cones
// that bound the caustic targets (mirror and glass objects) as seen from the whole light. A photon
// drawn from the mixture of cones is weighted by the mixture's density, so overlapping cones are
// counted once (a one-sample balance heuristic) and the caustic map stays unbiased.

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <optional>
#include <variant>
#include <vector>

#include "../geometry/bbox.hpp"
#include "../geometry/bounding_ball.hpp"
#include "../geometry/plane.hpp"
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
    /// Around an infinite mirror plane's image of the scene: its photons spread over whole floors
    /// and walls like the global map's, and are read like them (TracedPhotons::unaimed_caustics).
    bool broad = false;

    [[nodiscard]] bool contains(const Vec3<S>& d) const noexcept { return one_minus_cos_between(d, axis) <= one_minus_cos; }
};

/// What caustic photons are aimed at: a ball holding a mirror or glass object, or, for an infinite
/// mirror plane (`mirror`), the ball of the scene's bounded objects seen in that mirror. Light a
/// plane reflects into a ball leaves the light in the mirror image of the directions from the
/// light's own mirror image to the ball: one cone again, with no bound on the plane needed. What
/// the plane reflects past the ball (onto another infinite plane far away) is left to the global
/// pass, which hands the caustic map every L S+ D photon the cones do not cover.
template <Scalar S> struct AimTarget {
    Ball<S> ball;
    BBox<S> box;  ///< also holds the target (the corners' cone is narrower for a flat one)
    std::optional<Plane<S>> mirror;
};

namespace detail {
/// 1 - cos of the half-angle of the cone about `axis` from `origin` (widened by `widen`, a sphere
/// around it) that holds the box, or 2 (every direction) when no such cone of at most
/// 90 degrees does: a wider cone is not convex, so holding the corners would not prove holding
/// the box.
template <Scalar S>
[[nodiscard]] S box_cone_1mc(const Vec3<S>& origin, S widen, const Vec3<S>& axis, const BBox<S>& box) noexcept {
    if (!box.is_finite()) return S(2);
    const Vec3<S> nearest = glm::clamp(origin, box.min, box.max);
    const S distance = glm::length(nearest - origin);
    if (!(distance > widen)) return S(2);
    double widest = 0.0;
    for (int corner = 0; corner < 8; ++corner) {
        const Vec3<double> c((corner & 1) ? box.max.x : box.min.x, (corner & 2) ? box.max.y : box.min.y,
                             (corner & 4) ? box.max.z : box.min.z);
        const Vec3<double> v = c - Vec3<double>(origin);
        const double length = glm::length(v);
        if (!(length > 0.0)) return S(2);
        widest = std::max(widest, std::acos(std::clamp(glm::dot(Vec3<double>(axis), v) / length, -1.0, 1.0)));
    }
    widest += std::asin(std::min(1.0, double(widen) / double(distance))) + 1e-6;  // 1e-6 rad for rounding
    if (!(widest < pi<double> / 2)) return S(2);
    return S(2.0 * squared(std::sin(0.5 * widest)));
}
}  // namespace detail

/// Cones from `light` to each target: around the target's ball or its box's corners, whichever
/// is narrower, widened by the light's own radius so that they cover rays leaving any point of a
/// sphere light.
template <Scalar S>
[[nodiscard]] std::vector<TargetCone<S>> target_cones(const Light<S>& light, const std::vector<AimTarget<S>>& targets) {
    std::vector<TargetCone<S>> cones;
    const S light_r = light_radius(light);
    for (const auto& target : targets) {
        Vec3<S> origin = light_center(light);
        if (target.mirror) origin -= S(2) * (glm::dot(origin, target.mirror->normal()) - target.mirror->offset()) * target.mirror->normal();
        TargetCone<S> cone{.axis = {S(0), S(0), S(1)}, .one_minus_cos = S(2), .solid_angle = S(0), .frame = {}, .broad = false};
        const Vec3<S> to = target.ball.center - origin;
        const S d = glm::length(to);
        const S reach = target.ball.radius + light_r;
        if (d > reach) {
            // 1 - cos = sin^2 / (1 + cos): a small target far away keeps its solid angle.
            cone.axis = to / d;
            const S sin2 = squared(reach / d);
            cone.one_minus_cos = sin2 / (S(1) + std::sqrt(std::max(S(0), S(1) - sin2)));
        }
        const Vec3<S> to_box = target.box.center() - origin;
        if (target.box.is_finite() && glm::length(to_box) > S(0)) {
            const Vec3<S> box_axis = glm::normalize(to_box);
            const S box_1mc = detail::box_cone_1mc(origin, light_r, box_axis, target.box);
            if (box_1mc < cone.one_minus_cos) {
                cone.axis = box_axis;
                cone.one_minus_cos = box_1mc;
            }
        }
        // Directions from the light's mirror image, mirrored back: those from the light itself.
        if (target.mirror && cone.one_minus_cos < S(2))
            cone.axis -= S(2) * glm::dot(cone.axis, target.mirror->normal()) * target.mirror->normal();
        cone.solid_angle = cone_solid_angle_1mc(cone.one_minus_cos);
        cone.frame = Frame<S>::from_normal(cone.axis);
        cone.broad = target.mirror.has_value();
        cones.push_back(cone);
    }
    return cones;
}

/// A direction from the mixture of cones (each chosen in proportion to its solid angle) and its
/// density per steradian: (number of cones containing it) / (sum of solid angles).
template <Scalar S> struct ConeMixtureSample {
    Vec3<S> direction;
    S pdf;
    bool broad = false;  ///< drawn from a mirror plane's cone (TargetCone::broad)
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
    return {d, S(covering) / total_solid_angle, c.broad};
}

/// Where each light's caustic photons are aimed: the cones around the bounding spheres of the
/// scene's caustic targets, per light. The caustic pass samples them; the global pass asks
/// covers() which of its L S+ D photons the caustic pass could also have produced, and hands
/// the others to the caustic map itself, so that no caustic path is lost (an infinite mirror
/// unbounded shape other than a plane cannot be aimed at, a mirror with `photons { }` but no
/// `target` is not).
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

/// The box an infinite mirror plane's caustics are aimed into: that of the scene's bounded
/// objects (none: the plane cannot be aimed at).
template <class SceneT> [[nodiscard]] std::optional<BBox<typename SceneT::scalar_type>> mirror_aim_box(const SceneT& scene) {
    const auto bounds = scene.bounds();
    if (!bounds.is_finite()) return std::nullopt;
    return bounds;
}

/// What caustic photons aim at for object `i`: its bounding ball, or, for an infinite plane, the
/// scene's bounded objects seen in it (AimTarget); nothing for another unbounded shape.
template <class SceneT>
[[nodiscard]] std::optional<AimTarget<typename SceneT::scalar_type>> aim_target(const SceneT& scene, std::uint32_t i) {
    using S = typename SceneT::scalar_type;
    const Ball<S> ball = scene.object_bounding_ball(i);
    if (std::isfinite(ball.radius)) return AimTarget<S>{ball, scene.object_bounds(i), std::nullopt};
    if (const auto* plane = std::get_if<Plane<S>>(&scene.objects()[i].shape))
        if (const auto seen = mirror_aim_box(scene)) return AimTarget<S>{ball_around(*seen), *seen, *plane};
    return std::nullopt;
}

/// Whether caustic photons can be aimed at object `i`: a caustic target with finite bounds, or an
/// infinite plane in a scene with bounded objects for its caustics to land on.
template <class SceneT> [[nodiscard]] bool is_aimable_target(const SceneT& scene, std::uint32_t i) {
    return scene.is_caustic_target(i) && aim_target(scene, i).has_value();
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

/// The cones of every light towards every aimable caustic target (a ball around each, the
/// mirrored scene for an infinite mirror plane), but those with `skip[i]` (the
/// light-path plan's targets whose caustics the camera cannot see) and, for a light with a cone
/// (a spotlight), the targets its cone cannot reach: their photons would all be thrown away.
template <class SceneT>
[[nodiscard]] CausticAim<typename SceneT::scalar_type> caustic_aim(const SceneT& scene, const std::vector<bool>& skip = {}) {
    using S = typename SceneT::scalar_type;
    std::vector<AimTarget<S>> targets;
    for (std::uint32_t i = 0; i < scene.objects().size(); ++i) {
        if (!scene.is_caustic_target(i) || (i < skip.size() && skip[i])) continue;
        if (const auto target = aim_target(scene, i)) targets.push_back(*target);
    }
    CausticAim<S> aim;
    if (targets.empty()) return aim;
    for (const auto& light : scene.lights()) {
        // A parallel light's photons all travel one way: no cone of directions to aim into (its
        // caustics come with the global pass, as unaimed ones).
        aim.cones.push_back(is_parallel(light) ? std::vector<TargetCone<S>>{} : target_cones(light, targets));
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
    "mirror or glass object that caustic photons are not aimed at (unbounded and not a plane, a plane in a scene "
    "with no bounded object, or no `target`): "
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
