// SPDX-License-Identifier: MIT
#pragma once
// The light-path plan: before any photon is traced, which of Heckbert's path classes (the
// paper's section 2) the scene can produce and the camera can see, and from that which photon
// maps are built with how many photons, which passes run, and, for everything dropped, why.
// render() obeys it and embedders can call plan_effects() to see the same decisions.
//
// Conservative: an inference drops work only when it proves that the work cannot change the
// image (no mirror or glass: no caustics; one flat or convex diffuse surface and nothing
// specular: light never bounces twice; a light walled off from the camera, inside a closed
// opaque solid the camera is outside of or behind an opaque plane, or whose cone meets nothing,
// or without power: none of its light reaches the image, so it gets neither photons nor shadow
// rays; a mirror or glass object walled off the same way: its caustics cannot be seen, so no
// caustic photon is aimed at it). Anything it cannot prove is kept. RenderSettings::effects
// forces an effect either way. docs/effects-plan.md lists the rules.

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <optional>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include "../settings/render_settings.hpp"
#include "../scene/camera.hpp"
#include "../tracing/caustic_targets.hpp"
#include "../tracing/light_allocation.hpp"
#include "../tracing/photon_tracer.hpp"
#include "shape_facts.hpp"
#include "visible_caustics.hpp"
#include "visible_power.hpp"

namespace photon {

/// One of Heckbert's path classes: whether the image can show it, and why (one line).
struct PathClassPlan {
    bool present = false;
    std::string reason;
};

/// What the plan decided for one light.
struct LightPlan {
    bool emits = true;        ///< photons are shot from it
    std::string name;         ///< "light 1 (point light at <-2, 2, 0>)"
    std::string reason;       ///< why it emits nothing (empty when it emits)
    std::size_t global_photons = 0, caustic_photons = 0;  ///< its share of each pass
    /// Fraction of its power the pilot saw reach what the camera sees (visible_power.hpp; above 1
    /// for a light whose falloff is not 1/d^2 whose photons bring more than its nominal power); -1:
    /// not measured (no camera, one light, no global pass, or `lights=on`).
    double visible_fraction = -1.0;
};

/// One thing the settings asked for that the plan does not do.
struct DroppedEffect {
    std::string what;  ///< "caustic photons at object 7 (sphere)", naming the object or light
    std::string why;   ///< "behind object 1 (plane)"; empty when `what` says it all
    /// "WHAT: WHY", as `photon check` prints an item.
    [[nodiscard]] std::string line() const { return why.empty() ? what : what + ": " + why; }
    bool operator==(const DroppedEffect&) const = default;
};

struct EffectsPlan {
    /// False for modes with passes of their own (rt, reference, sppm): the path classes are
    /// still worked out, but nothing is dropped (sppm is the judge and must see every path).
    bool planned = false;
    PathClassPlan direct;         ///< L D E
    PathClassPlan indirect;       ///< L D D+ E (and L D (S|D)* D E)
    PathClassPlan caustics;       ///< L S+ D E
    PathClassPlan specular_view;  ///< L (S|D)* S+ E: seen in mirrors and through glass
    std::vector<std::uint32_t> caustic_objects;  ///< the mirror and glass objects that carry caustics
    std::vector<std::string> caustic_object_names;  ///< "object 5 (sphere)", one per caustic_objects entry
    /// Per object: a mirror or glass object at which the caustic pass does not aim (caustic_aim's
    /// `skip`): its caustics cannot be seen (walled off), or the caustic pilot saw them land out of
    /// view (then the global pass carries them).
    std::vector<bool> hidden_caustic_objects;
    /// What the caustic pilot measured per aimed target (visible_caustics.hpp); empty: not run.
    std::vector<TargetCausticsSeen> caustic_pilot;

    std::vector<LightPlan> lights;
    bool global_pass = false, caustic_pass = false;
    bool precomputed_irradiance = false, irradiance_cache = false, final_gather = false;
    /// The global pass hands the caustic map the L S+ D photons the caustic pass does not cover
    /// (an infinite mirror plane's, or all of them when there is no caustic pass).
    bool global_collects_caustics = false;
    /// The global pass runs only for those: it stores nothing else.
    bool global_for_unaimed_caustics_only = false;
    PathKinds global_store{};  ///< what the global map holds, if built
    std::size_t global_photons = 0, caustic_photons = 0;  ///< emitted by the passes that run
    std::size_t environment_photons = 0;  ///< of the global photons, the sky's (shared with the lights by power)

    /// What the settings asked for and the plan does not do, one item each naming the object or
    /// light and the reason ({"caustic photons", "no mirror or glass surface"}).
    std::vector<DroppedEffect> dropped;
    std::vector<std::string> passes_skipped;  ///< the passes the settings would run and the plan does not
    std::uint64_t photons_not_shot = 0;       ///< photons the settings asked for and the plan does not emit
    /// Global photons given to other lights than power alone would give them to: those of hidden
    /// lights, and those moved by visible power.
    std::uint64_t photons_moved = 0;
    /// Per light, its share of the global photons by the power it sends to what the camera sees
    /// (PhotonTracingSettings::light_shares); empty: shared by power.
    std::vector<double> global_light_shares;
    VisiblePowerPilot pilot{};  ///< how the shares were measured, if they were

    /// Per light, whether it emits (PhotonTracingSettings::light_emits).
    [[nodiscard]] std::vector<bool> light_emits() const {
        std::vector<bool> e;
        for (const auto& l : lights) e.push_back(l.emits);
        return e;
    }
};

namespace plan_detail {

/// ", LABEL" for a labelled object or light (Scene::set_object_label), else nothing.
[[nodiscard]] inline std::string label_suffix(std::string_view label) {
    return label.empty() ? std::string() : ", " + std::string(label);
}

/// "object 2 (box)", or "object 2 (box, room.pov:14:1)" when the scene labels it.
template <class SceneT> [[nodiscard]] std::string object_name(const SceneT& scene, std::uint32_t i) {
    return "object " + std::to_string(i) + " (" +
           std::visit([](const auto& shape) { return plan::shape_name(shape); }, scene.objects()[i].shape) +
           label_suffix(scene.object_label(i)) + ")";
}

/// "light 0 (point light at <0, 2, 0>)", with the scene's label for it after a comma.
template <class SceneT> [[nodiscard]] std::string light_name(const SceneT& scene, std::size_t i) {
    using S = typename SceneT::scalar_type;
    const Light<S>& light = scene.lights()[i];
    const Vec3<S> c = light_center(light);
    char at[96];
    std::snprintf(at, sizeof at, "<%g, %g, %g>", double(c.x), double(c.y), double(c.z));
    return "light " + std::to_string(i) + " (" + (std::holds_alternative<AreaLight<S>>(light) ? "area" : is_parallel(light) ? "parallel" : light_radius(light) > S(0) ? "sphere" : "point") + " light at " + at + label_suffix(scene.light_label(i)) + ")";
}

/// Whether some ray leaving `light` can hit object `i`: false only when the light has a cone
/// and the cone misses the cone of directions to the object's bounding sphere (widened by the
/// light's radius), or, for a plane, points wholly away from it.
template <class SceneT>
[[nodiscard]] bool cone_can_reach(const SceneT& scene, const Light<typename SceneT::scalar_type>& light, std::uint32_t i) {
    using S = typename SceneT::scalar_type;
    const auto& cone = light_cone(light);
    if (!cone) return true;
    constexpr double margin = 1e-3;  // radians, for rounding
    const double half = double(cone->half_angle_degrees()) * pi<double> / 180.0;
    const Vec3<double> axis(cone->axis()), origin(light_center(light));
    const double light_r = double(light_radius(light));
    const auto angle_to = [&](const Vec3<double>& d) { return std::acos(std::clamp(glm::dot(axis, d), -1.0, 1.0)); };
    const Ball<S> ball = scene.object_bounding_ball(i);
    if (std::isfinite(ball.radius)) {
        const Vec3<double> to = Vec3<double>(ball.center) - origin;
        const double d = glm::length(to);
        const double reach = double(ball.radius) + light_r;
        if (!(d > reach)) return true;
        return angle_to(to / d) <= half + std::asin(reach / d) + margin;
    }
    if (const auto* plane = std::get_if<Plane<S>>(&scene.objects()[i].shape)) {
        const Vec3<double> n(plane->normal());
        const double side = glm::dot(n, origin) - double(plane->offset());
        if (!(std::abs(side) > light_r)) return true;
        const Vec3<double> towards = side > 0 ? -n : n;
        return angle_to(towards) < pi<double> / 2 + half + margin;
    }
    return true;  // unbounded and not a plane: assume it can be reached
}

/// Why nothing the camera at `eye` sees can receive light from the ball (centre, radius), or
/// nothing when that is not proved: the ball is inside a closed opaque convex solid the camera is
/// outside of, or an opaque infinite plane has the ball strictly on one side and the camera on the
/// other. Opaque: no transmission, and casting shadows (so that shadow rays stop there too).
/// Object `self` (the ball's own object, if any) is not a wall.
template <class SceneT>
[[nodiscard]] std::optional<std::string> walled_off(const SceneT& scene, const Vec3<typename SceneT::scalar_type>& eye,
                                                    const Vec3<typename SceneT::scalar_type>& center,
                                                    typename SceneT::scalar_type radius, std::int64_t self = -1) {
    using S = typename SceneT::scalar_type;
    const auto objects = scene.objects();
    // A wall is a plane (unbounded) or a solid whose bounds hold the ball: the scene's BVH finds
    // them (the ones that cast shadows), so a scene of 40,000 objects asks a few, not all, per ball.
    std::vector<std::uint32_t> walls;
    scene.occluders_in(BBox<S>{center - Vec3<S>(radius), center + Vec3<S>(radius)}, walls);
    std::sort(walls.begin(), walls.end());  // the first wall in the scene's order names the reason
    for (std::uint32_t i : walls) {
        const auto& o = objects[i];
        if (std::int64_t(i) == self || scene.any_material_of(i, is_transmissive_material)) continue;
        const bool closed = std::visit([](const auto& s) { return plan::is_convex_solid(s); }, o.shape);
        if (closed && !scene.object_bounds(i).contains(eye) &&
            std::visit([&](const auto& s) { return plan::contains_ball(s, center, radius); }, o.shape))
            return "inside " + object_name(scene, i) + ", a closed opaque solid the camera is outside of";
        if (const auto* plane = std::get_if<Plane<S>>(&o.shape)) {
            const S margin = S(1e-4) * std::max({max_component(glm::abs(eye)), max_component(glm::abs(center)), radius,
                                                 std::abs(plane->offset())});
            const S eye_side = glm::dot(plane->normal(), eye) - plane->offset();
            const S ball_side = glm::dot(plane->normal(), center) - plane->offset();
            if (std::abs(eye_side) > margin && std::abs(ball_side) > radius + margin && (eye_side > 0) != (ball_side > 0))
                return "behind " + object_name(scene, i) + ", an opaque plane the camera is on the other side of";
        }
    }
    return std::nullopt;
}

}  // namespace plan_detail

/// The plan for `scene` seen by a camera at `eye` (nothing: unknown, the inferences that need
/// the camera are not made) under `settings`. The caustic targets in `unseen_caustics` (the
/// caustic pilot's verdict, visible_caustics.hpp) are not aimed at; the global pass carries
/// their caustics.
template <class SceneT>
[[nodiscard]] EffectsPlan plan_effects(const SceneT& scene, const std::optional<Vec3<typename SceneT::scalar_type>>& eye,
                                       const RenderSettings& settings,
                                       const std::vector<std::uint32_t>& unseen_caustics = {}) {
    using S = typename SceneT::scalar_type;
    using plan_detail::object_name;
    EffectsPlan plan;
    const auto objects = scene.objects();
    const auto lights = scene.lights();
    const EffectSwitches& force = settings.effects;

    // Lights: which can send light to anything the camera may see.
    for (std::size_t l = 0; l < lights.size(); ++l) {
        LightPlan lp;
        const Light<S>& light = lights[l];
        lp.name = plan_detail::light_name(scene, l);
        if (!light_is_lit(light)) {
            lp.emits = false;
            lp.reason = "no power";
        } else if (force.lights != EffectSwitch::on) {
            // A parallel light comes from a whole plane, not from near its position: never walled off here.
            if (eye && !is_parallel(light))
                if (const auto why = plan_detail::walled_off(scene, *eye, light_center(light), light_radius(light))) {
                    lp.emits = false;
                    lp.reason = *why;
                }
            if (lp.emits && light_cone(light)) {
                bool reaches = false;
                for (std::uint32_t i = 0; i < objects.size() && !reaches; ++i)
                    reaches = plan_detail::cone_can_reach(scene, light, i);
                if (!reaches) {
                    lp.emits = false;
                    lp.reason = "its cone meets no object";
                }
            }
        }
        plan.lights.push_back(std::move(lp));
    }
    bool lit = false;
    for (const auto& lp : plan.lights) lit = lit || lp.emits;
    // The sky lights whatever it can reach from outside, and is never walled off from all of
    // it: it counts as a light that emits (its photons go with the global pass).
    const bool sky = scene.has_environment_light();
    lit = lit || sky;

    // Surfaces.
    std::vector<std::uint32_t> diffuse, specular;
    for (std::uint32_t i = 0; i < objects.size(); ++i) {
        if (scene.any_material_of(i, has_diffuse_material)) diffuse.push_back(i);
        if (scene.any_material_of(i, is_specular_material)) specular.push_back(i);
    }
    const std::string no_light = lights.empty() ? "no light" : "no light sends any light to the scene";

    plan.direct.present = lit && !diffuse.empty();
    plan.direct.reason = !lit ? no_light : diffuse.empty() ? "no diffuse surface" : "";

    plan.specular_view.present = lit && !specular.empty() && settings.max_ray_depth > 1;
    plan.specular_view.reason = !lit             ? no_light
                                : specular.empty() ? "no mirror or glass surface"
                                : settings.max_ray_depth > 1 ? ""
                                                             : "max ray depth 1: camera rays end at the first hit";

    // Caustics of a mirror or glass object walled off from the camera land where it cannot see.
    plan.hidden_caustic_objects.assign(objects.size(), false);
    std::vector<std::uint32_t> seen_specular;
    std::vector<DroppedEffect> walled;  // "caustic photons at" each, and the wall
    for (std::uint32_t i : specular) {
        const Ball<S> ball = scene.object_bounding_ball(i);
        std::optional<std::string> why;
        if (eye && std::isfinite(ball.radius) && force.caustics != EffectSwitch::on)
            why = plan_detail::walled_off(scene, *eye, ball.center, ball.radius, i);
        if (!why) {
            seen_specular.push_back(i);
            continue;
        }
        plan.hidden_caustic_objects[i] = true;
        walled.push_back({"caustic photons at " + object_name(scene, i), *why});
    }
    for (std::uint32_t i : unseen_caustics) plan.hidden_caustic_objects.at(i) = true;
    plan.caustics.present = lit && !seen_specular.empty() && !diffuse.empty();
    plan.caustics.reason = !lit                   ? no_light
                           : specular.empty()      ? "no mirror or glass surface"
                           : diffuse.empty()       ? "no diffuse surface for caustics to land on"
                           : seen_specular.empty() ? "every mirror and glass object is walled off from the camera"
                                                   : "";
    if (plan.caustics.present) plan.caustic_objects = seen_specular;
    for (std::uint32_t i : plan.caustic_objects) plan.caustic_object_names.push_back(object_name(scene, i));

    // Indirect light needs light to bounce off a diffuse surface onto a diffuse surface. With
    // nothing specular to redirect it, one flat surface cannot light itself, nor can one convex
    // solid whose lights are all outside it (light leaving its outside moves away from it).
    bool indirect = lit && !diffuse.empty();
    std::string indirect_reason = !lit ? no_light : diffuse.empty() ? "no diffuse surface" : "";
    if (indirect && specular.empty() && diffuse.size() == 1) {
        const std::uint32_t only = diffuse[0];
        const auto& shape = objects[only].shape;
        const bool flat = std::visit([](const auto& s) { return plan::is_flat(s); }, shape);
        bool convex_lit_outside = std::visit([](const auto& s) { return plan::is_convex_solid(s); }, shape);
        const BBox<S> b = scene.object_bounds(only);
        for (std::size_t l = 0; l < lights.size() && convex_lit_outside; ++l) {
            if (!plan.lights[l].emits) continue;
            if (const auto* parallel = std::get_if<ParallelLight<S>>(&lights[l])) {
                // Its light starts on its plane: outside when the whole box is in front of it.
                const Vec3<S> e = b.extent() * S(0.5);
                const S reach = std::abs(e.x * parallel->direction.x) + std::abs(e.y * parallel->direction.y) +
                                std::abs(e.z * parallel->direction.z);
                convex_lit_outside = parallel->plane_distance(b.center()) > reach;
                continue;
            }
            const Vec3<S> c = light_center(lights[l]);
            const S r = light_radius(lights[l]);
            convex_lit_outside = !b.overlaps(BBox<S>{c - r, c + r});
        }
        if (flat || convex_lit_outside) {
            indirect = false;
            indirect_reason = "one diffuse surface, " + object_name(scene, only) + (flat ? ", flat" : ", convex and lit from outside") +
                              ", and no mirror or glass: light cannot reach it twice";
        }
    }
    plan.indirect.present = indirect;
    plan.indirect.reason = indirect_reason;

    // Passes: only the photon-mapping modes build maps the plan can drop.
    plan.planned = settings.mode == RenderMode::pm || settings.mode == RenderMode::pm_direct;
    if (!plan.planned) return plan;
    const auto forced = [](EffectSwitch s, bool inferred) {
        return s == EffectSwitch::on ? true : s == EffectSwitch::off ? false : inferred;
    };
    const bool want_caustics = forced(force.caustics, plan.caustics.present);
    const bool want_indirect = forced(force.indirect, plan.indirect.present);
    const auto drop = [&](const std::string& what, const std::string& why, bool by_user) {
        plan.dropped.push_back({what, by_user ? "forced off (effects)" : why});
    };

    // Caustic pass, as render() runs it: aimed at the caustic targets, from the lights that emit.
    const std::vector<bool> emits = plan.light_emits();
    const auto aim = caustic_aim(scene, plan.hidden_caustic_objects);
    const bool lights_emit = [&] {
        for (std::size_t l = 0; l < lights.size(); ++l)
            if (emits[l] && max_component(light_power(lights[l])) > S(0)) return true;
        return false;
    }();
    const bool any_emits = lights_emit || sky;
    // Only lights aim caustic photons: the sky's caustics come with the global pass.
    plan.caustic_pass = want_caustics && settings.caustic_photons > 0 && !aim.empty() && lights_emit && !diffuse.empty();
    if (settings.caustic_photons > 0 && !plan.caustic_pass) {
        const std::string why = !plan.caustics.present ? plan.caustics.reason
                                : aim.empty() && !unseen_caustics.empty()
                                    ? "the pilot saw no target's caustics land in view; the global photons carry them"
                                : aim.empty() ? "no caustic target to aim at (each is unbounded and not a plane, or has no `target`)"
                                              : no_light;
        drop("caustic photons", force.caustics == EffectSwitch::on ? "forced on, but " + why : why,
             force.caustics == EffectSwitch::off);
        plan.passes_skipped.push_back("caustic photons");
    }
    // The global pass also carries the caustics the caustic pass does not: those of mirrors and
    // glass it cannot aim at, or all of them when it does not run.
    const bool collect = want_caustics && plan.caustics.present;
    bool unaimed = collect && !plan.caustic_pass;
    for (std::uint32_t i : seen_specular) unaimed = unaimed || (collect && !is_aimable_target(scene, i));
    unaimed = unaimed || (collect && !unseen_caustics.empty()) || (collect && sky);
    if (settings.caustic_photons > 0) {
        plan.dropped.insert(plan.dropped.end(), walled.begin(), walled.end());
        for (std::uint32_t i : unseen_caustics)
            plan.dropped.push_back({"caustic photons at " + object_name(scene, i),
                                    "the pilot saw under 1% of the caustic light land in view come from it; "
                                    "the global photons carry its caustics"});
    }
    // Spotlights: the targets outside a light's cone get none of its caustic photons, and a
    // target outside every emitting light's cone gets none at all (its caustics need light that
    // reaches it first by way of a diffuse bounce: the global pass carries them).
    if (plan.caustic_pass) {
        std::vector<std::uint32_t> targets;
        for (std::uint32_t i = 0; i < objects.size(); ++i)
            if (is_aimable_target(scene, i) && !plan.hidden_caustic_objects[i]) targets.push_back(i);
        for (std::size_t l = 0; l < lights.size(); ++l)
            if (emits[l] && light_cone(lights[l]) && aim.cones[l].empty())
                plan.dropped.push_back({"caustic photons from " + plan.lights[l].name,
                                        "its cone reaches no mirror or glass target"});
        for (std::uint32_t i : targets) {
            bool reached = false;
            for (std::size_t l = 0; l < lights.size() && !reached; ++l)
                reached = emits[l] && plan_detail::cone_can_reach(scene, lights[l], i);
            if (!reached)
                plan.dropped.push_back({"caustic photons at " + object_name(scene, i),
                                        "no light's cone reaches it directly"});
        }
    }

    const bool gathering = settings.mode == RenderMode::pm && settings.final_gather_rays > 0;
    const bool all_light = settings.mode == RenderMode::pm_direct;  // direct light from the map too
    const bool global_needed = want_indirect || (all_light && plan.direct.present) || unaimed;
    plan.global_pass = settings.global_photons > 0 && global_needed && any_emits;
    plan.global_collects_caustics = plan.global_pass && collect;
    plan.global_for_unaimed_caustics_only = plan.global_pass && !want_indirect && !all_light;
    plan.final_gather = gathering && want_indirect && plan.global_pass;
    plan.precomputed_irradiance = plan.final_gather && settings.irradiance_stride > 0;
    plan.irradiance_cache = plan.final_gather && settings.irradiance_cache_error > 0.0f;
    plan.global_store = {.direct = plan.final_gather || all_light,
                         .caustic = plan.final_gather,
                         .indirect = want_indirect};
    if (plan.global_for_unaimed_caustics_only) plan.global_store = {.direct = false, .caustic = false, .indirect = false};
    const std::string indirect_why = force.indirect == EffectSwitch::off ? "" : plan.indirect.reason;
    if (settings.global_photons > 0 && !plan.global_pass) {
        drop("global photons", any_emits ? indirect_why : no_light, force.indirect == EffectSwitch::off);
        plan.passes_skipped.push_back("global photons");
    }
    if (gathering && !plan.final_gather) {
        std::string what = "final gather";
        if (settings.irradiance_stride > 0) what += ", precomputed irradiance";
        if (settings.irradiance_cache_error > 0.0f) what += ", irradiance cache";
        drop(what, indirect_why, force.indirect == EffectSwitch::off);
        plan.passes_skipped.push_back("final gather");
        if (settings.irradiance_stride > 0) plan.passes_skipped.push_back("precomputed irradiance");
        if (settings.irradiance_cache_error > 0.0f) plan.passes_skipped.push_back("irradiance cache");
    }

    plan.global_photons = plan.global_pass ? settings.global_photons : 0;
    plan.caustic_photons = plan.caustic_pass ? settings.caustic_photons : 0;
    plan.photons_not_shot = (settings.global_photons - plan.global_photons) + (settings.caustic_photons - plan.caustic_photons);
    // The sky's share of the global photons, by its power into the ball its photons enter through
    // (trace_global_photons shares them so).
    const Ball<S> sky_ball = scene.environment_ball();
    const double sky_power = sky && sky_ball.radius > S(0) ? double(scene.environment()->power_into(sky_ball)) : 0.0;
    const auto global_share = photons_per_light<S>(lights, plan.global_photons, emits, {}, sky_power);
    plan.environment_photons = sky_power > 0 ? global_share.back() : 0;
    // A light whose cone reaches no caustic target shoots no caustic photon (caustic_aim).
    const auto caustic_share = photons_per_light<S>(lights, plan.caustic_photons, aim.aiming_lights(lights.size(), emits));
    const auto unplanned_share = photons_per_light<S>(lights, plan.global_photons, {}, {}, sky_power);
    for (std::size_t l = 0; l < lights.size(); ++l) {
        plan.lights[l].global_photons = global_share[l];
        plan.lights[l].caustic_photons = caustic_share[l];
        if (!plan.lights[l].emits) {
            plan.photons_moved += unplanned_share[l];
            plan.dropped.push_back({"photons from " + plan.lights[l].name, plan.lights[l].reason});
        }
    }
    return plan;
}

/// The plan for `scene` seen by `camera` under `settings`: the walls are proved from the camera's
/// eye, so a camera whose rays start at many points (orthographic, cylinders 3 and 4, focal
/// blur) gets none of those proofs. With several lights, the global
/// photons are shared by the power each sends to what the camera sees, as a pilot pass measures
/// it, with a floor (visible_power.hpp), unless `lights=on` asks for photon's old sharing by power.
template <class SceneT>
[[nodiscard]] EffectsPlan plan_effects(const SceneT& scene, const Camera<typename SceneT::scalar_type>& camera,
                                       const RenderSettings& settings) {
    using S = typename SceneT::scalar_type;
    EffectsPlan plan = plan_effects(scene, camera.eye(), settings);
    // The caustic pilot: targets whose caustics land out of view are not aimed at. Only when the
    // global pass runs and hands over the caustics the caustic pass does not aim at, since it
    // then carries those targets' caustics.
    if (plan.planned && plan.caustic_pass && plan.global_collects_caustics && settings.effects.caustics == EffectSwitch::automatic) {
        std::vector<std::uint32_t> aimed;
        for (std::uint32_t i = 0; i < scene.objects().size(); ++i)
            if (is_aimable_target(scene, i) && !plan.hidden_caustic_objects[i]) aimed.push_back(i);
        VisibleCausticsPilot pilot;
        pilot.seed = settings.seed;
        std::vector<TargetCausticsSeen> measured = visible_caustics(scene, camera, aimed, plan.light_emits(), pilot);
        const std::vector<std::uint32_t> unseen = unseen_caustic_targets(measured, pilot.min_share);
        if (!unseen.empty()) plan = plan_effects(scene, camera.eye(), settings, unseen);
        plan.caustic_pilot = std::move(measured);
    }
    const auto lights = scene.lights();
    const std::vector<bool> emits = plan.light_emits();
    if (!plan.planned || !plan.global_pass || std::count(emits.begin(), emits.end(), true) < 2 ||
        settings.effects.lights == EffectSwitch::on)
        return plan;
    plan.pilot.seed = settings.seed;
    const std::vector<double> fraction = visible_power_fractions(scene, camera, emits, settings.emission, plan.pilot);
    plan.global_light_shares = visible_power_shares<S>(lights, fraction, emits, plan.pilot.floor);
    const Ball<S> sky_ball = scene.environment_ball();
    const double sky_power = scene.has_environment_light() && sky_ball.radius > S(0)
                                 ? double(scene.environment()->power_into(sky_ball)) : 0.0;
    const auto shared = photons_per_light<S>(lights, plan.global_photons, emits, plan.global_light_shares, sky_power);
    const auto unplanned = photons_per_light<S>(lights, plan.global_photons, {}, {}, sky_power);
    plan.environment_photons = sky_power > 0 ? shared.back() : 0;
    plan.photons_moved = 0;
    for (std::size_t l = 0; l < lights.size(); ++l) {
        if (emits[l]) plan.lights[l].visible_fraction = fraction[l];
        plan.lights[l].global_photons = shared[l];
        // Moved: hidden lights' photons, and those the visible shares give elsewhere.
        plan.photons_moved += unplanned[l] > shared[l] ? unplanned[l] - shared[l] : 0;
    }
    return plan;
}

}  // namespace photon
