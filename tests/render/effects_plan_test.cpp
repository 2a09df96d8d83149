// SPDX-License-Identifier: MIT
// The light-path plan (plan/effects_plan.hpp): what it infers from small scenes, that render()
// obeys it (maps not built, passes not run, hidden lights silent), that what it drops changes
// nothing in the image, and that an effect forced on or off reaches the renderer.

#include <catch2/catch.hpp>

#include <photon/photon.hpp>

#include "film_compare.hpp"

#include <algorithm>
#include <cstring>

using namespace photon;

namespace {

RenderSettings small(RenderMode mode = RenderMode::pm) {
    RenderSettings s;
    s.mode = mode;
    s.width = 48;
    s.height = 36;
    s.samples_per_pixel = 4;
    s.shadow_samples = 4;
    s.global_photons = 20'000;
    s.caustic_photons = 20'000;
    s.final_gather_rays = 16;
    return s;
}

PinholeCamera<float> camera_at(Vec3<float> eye, Vec3<float> target) {
    return PinholeCamera<float>::look_at(eye, target, {0, 1, 0}, 60.0f, 4.0f / 3.0f);
}

/// A floor plane and whatever `more` adds, lit by a point light above; committed.
template <class More> DefaultScene<float> floor_scene(More&& more) {
    DefaultScene<float> scene;
    const auto white = scene.add_material(Material<float>::lambertian(Rgb<float>(0.7f)));
    scene.add(Plane<float>({0, 1, 0}, 0.0f), white);
    scene.add_light(PointLight<float>{.position = {0, 3, 0}, .power = Rgb<float>(100.0f)});
    more(scene, white);
    scene.commit();
    return scene;
}

/// A diffuse room of five boxes (open at the front) with a diffuse ball and a sphere light.
DefaultScene<float> diffuse_room(bool glass_ball) {
    DefaultScene<float> scene;
    const auto white = scene.add_material(Material<float>::lambertian(Rgb<float>(0.75f)));
    const auto red = scene.add_material(Material<float>::lambertian({0.75f, 0.25f, 0.25f}));
    const auto ball = scene.add_material(glass_ball ? Material<float>::glass(1.5f) : Material<float>::lambertian(Rgb<float>(0.5f)));
    scene.add(Box<float>({-1.22f, -0.02f, -1.2f}, {1.22f, 0.0f, 1.22f}), white);
    scene.add(Box<float>({-1.22f, 1.8f, -1.2f}, {1.22f, 1.82f, 1.22f}), white);
    scene.add(Box<float>({-1.22f, -0.02f, 1.2f}, {1.22f, 1.82f, 1.22f}), white);
    scene.add(Box<float>({-1.22f, -0.02f, -1.2f}, {-1.2f, 1.82f, 1.22f}), red);
    scene.add(Box<float>({1.2f, -0.02f, -1.2f}, {1.22f, 1.82f, 1.22f}), white);
    scene.add(Sphere<float>({0.3f, 0.4f, 0.0f}, 0.4f), ball);
    scene.add_light(SphereLight<float>{.center = {0, 1.5f, 0}, .radius = 0.1f, .power = Rgb<float>(30.0f)});
    scene.commit();
    return scene;
}
const PinholeCamera<float> room_camera = camera_at({0, 0.9f, -3.5f}, {0, 0.9f, 0});

bool mentions(const std::vector<std::string>& lines, const std::string& text) {
    return std::any_of(lines.begin(), lines.end(), [&](const std::string& l) { return l.find(text) != l.npos; });
}
bool mentions(const std::vector<DroppedEffect>& dropped, const std::string& text) {
    return std::any_of(dropped.begin(), dropped.end(), [&](const DroppedEffect& d) { return d.line().find(text) != std::string::npos; });
}

}  // namespace

TEST_CASE("effects are forced by text: EFFECT=on|off|auto, read back as written", "[plan]") {
    const EffectSwitches s = parse_effect_switches("caustics=off,indirect=on");
    CHECK(s.caustics == EffectSwitch::off);
    CHECK(s.indirect == EffectSwitch::on);
    CHECK(s.lights == EffectSwitch::automatic);
    CHECK(to_string(s) == "caustics=off,indirect=on");
    CHECK(parse_effect_switches(to_string(s)) == s);
    CHECK(parse_effect_switches("") == EffectSwitches{});
    CHECK(parse_effect_switches("lights=on,lights=auto").lights == EffectSwitch::automatic);
    CHECK_THROWS_WITH(parse_effect_switches("caustic=off"), Catch::Contains("caustics, indirect, lights"));
    CHECK_THROWS_WITH(parse_effect_switches("indirect=maybe"), Catch::Contains("on, off or auto"));
    CHECK_THROWS_WITH(parse_effect_switches("lights=off"), Catch::Contains("on or auto"));
    CHECK(effect_switches_problem("caustics=on,"));  // an empty item names nothing
    CHECK(effect_switches_problem("caustics=on,,indirect=off"));
}

TEST_CASE("the plan's inferences on small scenes", "[plan]") {
    const RenderSettings s = small();
    SECTION("a pure-diffuse room has direct and indirect light but no caustics") {
        const EffectsPlan p = plan_effects(diffuse_room(false), room_camera, s);
        CHECK(p.direct.present);
        CHECK(p.indirect.present);
        CHECK_FALSE(p.caustics.present);
        CHECK_FALSE(p.caustic_pass);
        CHECK(p.global_pass);
        CHECK(p.final_gather);
        CHECK(mentions(p.dropped, "caustic photons: no mirror or glass surface"));
        CHECK(p.photons_not_shot == s.caustic_photons);
    }
    SECTION("a glass ball makes caustics, carried by the ball") {
        const EffectsPlan p = plan_effects(diffuse_room(true), room_camera, s);
        CHECK(p.caustics.present);
        CHECK(p.caustic_pass);
        CHECK(p.caustic_objects == std::vector<std::uint32_t>{5});
        CHECK(p.dropped.empty());
        CHECK(p.photons_not_shot == 0);
    }
    SECTION("one plane: no indirect light, no global pass, nothing to gather") {
        const auto scene = floor_scene([](auto&, auto) {});
        const EffectsPlan p = plan_effects(scene, camera_at({0, 2, -4}, {0, 0, 0}), s);
        CHECK(p.direct.present);
        CHECK_FALSE(p.indirect.present);
        CHECK_THAT(p.indirect.reason, Catch::Contains("object 0 (plane), flat"));
        CHECK_FALSE(p.global_pass);
        CHECK_FALSE(p.final_gather);
        CHECK_FALSE(p.irradiance_cache);
        CHECK_FALSE(p.precomputed_irradiance);
        CHECK(p.photons_not_shot == s.global_photons + s.caustic_photons);
        CHECK(p.passes_skipped.size() == 5);
    }
    SECTION("one ball lit from outside cannot light itself; lit from inside it can") {
        DefaultScene<float> outside, inside;
        for (auto* scene : {&outside, &inside}) {
            const auto white = scene->add_material(Material<float>::lambertian(Rgb<float>(0.7f)));
            scene->add(Sphere<float>({0, 0, 0}, 1.0f), white);
        }
        outside.add_light(PointLight<float>{.position = {0, 3, 0}, .power = Rgb<float>(10.0f)});
        inside.add_light(PointLight<float>{.position = {0, 0.5f, 0}, .power = Rgb<float>(10.0f)});
        outside.commit();
        inside.commit();
        CHECK_FALSE(plan_effects(outside, camera_at({0, 0, -4}, {0, 0, 0}), s).indirect.present);
        // Seen from inside (from outside, the light inside it is hidden and nothing is lit).
        CHECK(plan_effects(inside, camera_at({0, 0, -0.5f}, {0, 0, 0}), s).indirect.present);
        CHECK_FALSE(plan_effects(inside, camera_at({0, 0, -4}, {0, 0, 0}), s).direct.present);
    }
    SECTION("the quadrics of DefaultScene: flat and closed convex ones cannot light themselves, a torus can") {
        auto alone = [&](auto shape) {
            DefaultScene<float> scene;
            scene.add(shape, scene.add_material(Material<float>::lambertian(Rgb<float>(0.7f))));
            scene.add_light(PointLight<float>{.position = {0, 3, -3}, .power = Rgb<float>(10.0f)});
            scene.commit();
            return plan_effects(scene, camera_at({0, 1, -4}, {0, 0, 0}), s);
        };
        const EffectsPlan cylinder = alone(Cylinder<float>({0, -1, 0}, {0, 1, 0}, 1.0f));
        CHECK_FALSE(cylinder.indirect.present);
        CHECK_THAT(cylinder.indirect.reason, Catch::Contains("object 0 (cylinder)"));
        CHECK_FALSE(alone(TruncatedCone<float>({0, -1, 0}, 1.0f, {0, 1, 0}, 0.0f)).indirect.present);
        CHECK_FALSE(alone(Disc<float>({0, 0, 0}, {0, 1, 0}, 1.0f)).indirect.present);
        const EffectsPlan squashed = alone(Transformed<TruncatedCone<float>>(
            TruncatedCone<float>({0, -1, 0}, 1.0f, {0, 1, 0}, 1.0f), Affine<float>::scale({1, 1, 0.5f})));
        CHECK_FALSE(squashed.indirect.present);
        CHECK_THAT(squashed.indirect.reason, Catch::Contains("transformed cylinder"));
        // An open tube and a torus see themselves: light bounces inside them.
        CHECK(alone(Cylinder<float>({0, -1, 0}, {0, 1, 0}, 1.0f, true)).indirect.present);
        CHECK(alone(Transformed<Torus<float>>(Torus<float>(1.0f, 0.3f), Affine<float>::rotate_xyz({-30, 0, 0})))
                  .indirect.present);
    }
    SECTION("a plane and a ball on it: light bounces between them") {
        const auto scene = floor_scene([](auto& sc, auto white) { sc.add(Sphere<float>({0, 1, 0}, 1.0f), white); });
        CHECK(plan_effects(scene, camera_at({0, 2, -4}, {0, 0, 0}), s).indirect.present);
    }
    SECTION("a light of zero power, and a cone light aimed away from everything, emit nothing") {
        auto scene = floor_scene([](auto& sc, auto) {
            sc.add_light(PointLight<float>{.position = {1, 3, 0}, .power = Rgb<float>(0.0f)});
            sc.add_light(PointLight<float>{.position = {2, 3, 0}, .power = Rgb<float>(50.0f),
                                           .cone = Cone<float>({0, 1, 0}, 30.0f)});  // up, away from the floor
            sc.add_light(PointLight<float>{.position = {3, 3, 0}, .power = Rgb<float>(50.0f),
                                           .cone = Cone<float>({1, 1, 0}, 46.0f)});  // grazes the floor's side
        });
        const EffectsPlan p = plan_effects(scene, camera_at({0, 2, -4}, {0, 0, 0}), s);
        REQUIRE(p.lights.size() == 4);
        CHECK(p.lights[0].emits);
        CHECK_FALSE(p.lights[1].emits);
        CHECK_THAT(p.lights[1].reason, Catch::Contains("no power"));
        CHECK_FALSE(p.lights[2].emits);
        CHECK_THAT(p.lights[2].reason, Catch::Contains("cone meets no object"));
        CHECK(p.lights[3].emits);
    }
    SECTION("a light inside a closed box: silent when the camera is outside, not when inside") {
        const auto scene = floor_scene([](auto& sc, auto white) {
            sc.add(Box<float>({4, 0, 4}, {6, 2, 6}), white);
            sc.add_light(PointLight<float>{.position = {5, 1, 5}, .power = Rgb<float>(500.0f)});
        });
        const EffectsPlan outside = plan_effects(scene, camera_at({0, 2, -4}, {0, 0, 0}), s);
        CHECK(outside.lights[0].emits);
        CHECK_FALSE(outside.lights[1].emits);
        CHECK_THAT(outside.lights[1].reason, Catch::Contains("inside object 1 (box)"));
        CHECK(outside.lights[0].global_photons == s.global_photons);
        CHECK(outside.photons_moved > 0);
        const EffectsPlan within = plan_effects(scene, camera_at({5, 1, 4.5f}, {5, 1, 6}), s);
        CHECK(within.lights[1].emits);
        RenderSettings forced = s;
        forced.effects.lights = EffectSwitch::on;
        CHECK(plan_effects(scene, camera_at({0, 2, -4}, {0, 0, 0}), forced).lights[1].emits);
    }
    SECTION("a glass box around the light lets its light out") {
        const auto scene = floor_scene([](auto& sc, auto) {
            const auto glass = sc.add_material(Material<float>::glass(1.5f));
            sc.add(Box<float>({4, 0, 4}, {6, 2, 6}), glass);
            sc.add_light(PointLight<float>{.position = {5, 1, 5}, .power = Rgb<float>(500.0f)});
        });
        CHECK(plan_effects(scene, camera_at({0, 2, -4}, {0, 0, 0}), s).lights[1].emits);
    }
    SECTION("rt, reference and sppm: path classes only, nothing dropped") {
        for (const RenderMode m : {RenderMode::rt, RenderMode::reference, RenderMode::sppm}) {
            const EffectsPlan p = plan_effects(diffuse_room(false), room_camera, small(m));
            CHECK_FALSE(p.planned);
            CHECK(p.dropped.empty());
            CHECK(mentions(plan_lines(p, to_string(m)), "drops nothing"));
        }
    }
}

TEST_CASE("a pure-diffuse scene shoots no caustic photon and equals its render with caustics forced off", "[plan]") {
    const auto scene = diffuse_room(false);
    const RenderSettings s = small();
    const RenderResult planned = render(scene, room_camera, s);
    CHECK(planned.stats.caustic.emitted == 0);
    CHECK(planned.stats.caustic.stored == 0);
    CHECK(planned.stats.global.emitted == s.global_photons);
    CHECK(planned.stats.plan.photons_not_shot == s.caustic_photons);
    RenderSettings off = s;
    off.effects = parse_effect_switches("caustics=off");
    const RenderResult forced_off = render(scene, room_camera, off);
    CHECK(identical(planned.film, forced_off.film));
    CHECK(planned.film.all_finite_nonnegative());
    CHECK(planned.film.mean().y > 0.01);
}

TEST_CASE("a one-plane scene runs no global pass and equals rt", "[plan]") {
    const auto scene = floor_scene([](auto&, auto) {});
    const auto cam = camera_at({0, 2, -4}, {0, 0, 0});
    const RenderSettings s = small();
    const RenderResult pm = render(scene, cam, s);
    CHECK(pm.stats.global.emitted == 0);
    CHECK(pm.stats.caustic.emitted == 0);
    CHECK(pm.stats.rays.gather == 0);
    CHECK(pm.stats.cache_records == 0);
    CHECK(pm.stats.precompute_seconds == 0);
    CHECK(pm.stats.plan.passes_skipped.size() == 5);
    const RenderResult rt = render(scene, cam, small(RenderMode::rt));
    CHECK(identical(pm.film, rt.film));
    CHECK(rt.film.mean().y > 0.01);

    SECTION("forced on, indirect light runs every pass and finds nothing to add") {
        RenderSettings on = s;
        on.effects.indirect = EffectSwitch::on;
        const RenderResult forced = render(scene, cam, on);
        CHECK(forced.stats.global.emitted == s.global_photons);
        CHECK(forced.stats.rays.gather > 0);
        CHECK(forced.stats.cache_records > 0);
        CHECK(forced.film.mean().y == Approx(rt.film.mean().y).epsilon(0.01));
    }
}

TEST_CASE("a light in a closed box elsewhere emits nothing and changes nothing", "[plan]") {
    const auto box_only = [](auto& sc, auto white) { sc.add(Box<float>({4, 0, 4}, {6, 2, 6}), white); };
    const auto with_light = floor_scene([&](auto& sc, auto white) {
        box_only(sc, white);
        sc.add_light(PointLight<float>{.position = {5, 1, 5}, .power = Rgb<float>(500.0f)});
    });
    const auto without = floor_scene(box_only);
    const auto cam = camera_at({0, 2, -4}, {2, 0, 2});
    const RenderSettings s = small();
    const RenderResult planned = render(with_light, cam, s);
    const RenderResult no_light = render(without, cam, s);
    CHECK(planned.stats.plan.photons_moved > 0);
    CHECK(planned.stats.global.stored == no_light.stats.global.stored);
    CHECK(identical(planned.film, no_light.film));  // the boxed light's photons all went to the other
    CHECK(planned.stats.rays.shadow == no_light.stats.rays.shadow);  // and it gets no shadow rays

    SECTION("forced on, its photons land inside the box, which the camera cannot see") {
        RenderSettings on = s;
        on.effects.lights = EffectSwitch::on;
        const RenderResult forced = render(with_light, cam, on);
        CHECK(forced.stats.plan.photons_moved == 0);
        CHECK(forced.stats.global.emitted == s.global_photons);
        CHECK(forced.stats.rays.shadow > planned.stats.rays.shadow);
        // Far more photons are stored (the box's bright inside), yet the image is the same
        // within the noise of the fewer photons left to the visible light.
        CHECK(forced.stats.global.stored > planned.stats.global.stored);
        CHECK(forced.film.mean().y == Approx(planned.film.mean().y).epsilon(0.05));
    }
}

TEST_CASE("a glass ball behind a wall behind the camera gets no caustic photons and changes nothing", "[plan]") {
    // A floor, and a wall at z = -1 behind the camera, which looks along +z; the light is in front.
    const auto walled = [](Vec3<float> ball) {
        return floor_scene([ball](auto& sc, auto white) {
            sc.add(Plane<float>({0, 0, 1}, -1.0f), white);
            if (ball.z != 0) sc.add(Sphere<float>(ball, 0.5f), sc.add_material(Material<float>::glass(1.5f)));
        });
    };
    const auto cam = camera_at({0, 1, 0}, {0, 0.5f, 3});
    const RenderSettings s = small();
    const auto behind = walled({0, 0.6f, -2});
    const EffectsPlan p = plan_effects(behind, cam, s);
    CHECK_FALSE(p.caustics.present);
    CHECK_FALSE(p.caustic_pass);
    CHECK(mentions(p.dropped, "caustic photons at object 2 (sphere): behind object 1 (plane)"));
    // The object and the reason apart, for an embedder that groups or filters them.
    CHECK(std::any_of(p.dropped.begin(), p.dropped.end(), [](const DroppedEffect& d) {
        return d.what == "caustic photons at object 2 (sphere)" && d.why.starts_with("behind object 1 (plane)");
    }));
    CHECK(plan_effects(walled({0, 0.6f, 2}), cam, s).caustic_pass);  // in front of the wall: kept
    const RenderResult planned = render(behind, cam, s);
    CHECK(planned.stats.caustic.emitted == 0);
    const RenderResult no_ball = render(walled({0, 0, 0}), cam, s);
    CHECK(planned.stats.global.stored == no_ball.stats.global.stored);  // no photon reaches the ball
    // Not bit-identical: the ball enlarges the scene's bounds, which scale the ray offsets.
    CHECK(planned.film.mean().y == Approx(no_ball.film.mean().y).epsilon(0.005));
    RenderSettings on = s;
    on.effects.caustics = EffectSwitch::on;
    const RenderResult forced = render(behind, cam, on);
    CHECK(forced.stats.caustic.emitted == s.caustic_photons);
    CHECK(forced.stats.caustic.stored == 0);  // every one of them ends on the wall's back
    CHECK(identical(forced.film, planned.film));

    SECTION("a light behind the wall emits nothing") {
        const auto lamp = floor_scene([](auto& sc, auto white) {
            sc.add(Plane<float>({0, 0, 1}, -1.0f), white);
            sc.add_light(PointLight<float>{.position = {0, 2, -3}, .power = Rgb<float>(100.0f)});
        });
        const EffectsPlan lp = plan_effects(lamp, cam, s);
        CHECK(lp.lights[0].emits);
        CHECK_FALSE(lp.lights[1].emits);
        CHECK_THAT(lp.lights[1].reason, Catch::Contains("behind object 1 (plane)"));
    }
}

TEST_CASE("the plan names objects and lights by their labels where the scene gives them", "[plan]") {
    auto scene = floor_scene([](auto& sc, auto white) {
        sc.add(Plane<float>({0, 0, 1}, -1.0f), white);  // a wall between the camera and the lamp behind it
        sc.add_light(PointLight<float>{.position = {0, 2, -3}, .power = Rgb<float>(100.0f)});
    });
    scene.set_object_label(1, "room.pov:7:1");
    scene.set_light_label(1, "the hall lamp");
    CHECK(scene.object_label(1) == "room.pov:7:1");
    CHECK(scene.object_label(0).empty());
    CHECK(scene.light_label(0).empty());
    CHECK_THROWS_AS(scene.set_object_label(2, "no such object"), std::out_of_range);
    CHECK_THROWS_AS(scene.set_light_label(2, "no such light"), std::out_of_range);
    const EffectsPlan p = plan_effects(scene, camera_at({0, 1, 0}, {0, 0.5f, 3}), small());
    CHECK(p.lights[0].name == "light 0 (point light at <0, 3, 0>)");
    CHECK(p.lights[1].name == "light 1 (point light at <0, 2, -3>, the hall lamp)");
    CHECK_FALSE(p.lights[1].emits);
    CHECK(p.lights[1].reason.starts_with("behind object 1 (plane, room.pov:7:1)"));
}

TEST_CASE("a caustic seen only in a mirror is aimed at, one seen nowhere is not", "[plan]") {
    // The camera looks along +z at a mirror wall at z = 3; the glass ball and the light are behind
    // the camera, whose caustic on the floor near z = -2 the camera sees only in the mirror.
    const auto room = [](bool mirror) {
        return floor_scene([mirror](auto& sc, auto white) {
            const auto glass = sc.add_material(Material<float>::glass(1.5f));
            sc.add(Box<float>({-3, 0, 3}, {3, 2.5f, 3.1f}), mirror ? sc.add_material(Material<float>::mirror(Rgb<float>(0.9f))) : white);
            sc.add(Sphere<float>({0, 0.6f, -2}, 0.5f), glass);
            sc.add_light(PointLight<float>{.position = {0, 3, -2.5f}, .power = Rgb<float>(100.0f)});
        });
    };
    const auto cam = camera_at({0, 1, 0}, {0, 0.8f, 3});
    const RenderSettings s = small();
    const EffectsPlan seen = plan_effects(room(true), cam, s);
    const auto ball = [](const EffectsPlan& p) {
        const auto m = std::find_if(p.caustic_pilot.begin(), p.caustic_pilot.end(), [](const auto& t) { return t.object == 2; });
        REQUIRE(m != p.caustic_pilot.end());
        return *m;
    };
    INFO("ball: landed " << ball(seen).landed << " W, seen " << ball(seen).seen << " W, in mirrors " << ball(seen).seen_in_mirrors);
    CHECK(ball(seen).seen_in_mirrors > 0.0);
    CHECK(ball(seen).seen == Approx(ball(seen).seen_in_mirrors));  // none of it directly
    CHECK_FALSE(seen.hidden_caustic_objects[2]);
    // The same room with a white wall instead of the mirror: the caustic is out of view, but for
    // the little the ball's surface reflects forward onto the wall and floor in view.
    const EffectsPlan unseen = plan_effects(room(false), cam, s);
    CHECK(ball(unseen).seen_in_mirrors == 0.0);
    CHECK(ball(unseen).seen < 0.05 * ball(seen).seen);
}

TEST_CASE("a glass ball behind the camera, with no wall, gets no caustic photons: the global photons carry its caustics",
          "[plan]") {
    // The camera looks along +z from the origin; ball 1 is in view, ball 2 behind the camera, and
    // the light behind ball 2: its caustics land near it, out of view. No wall proves that: the
    // caustic pilot measures it, and the global pass still carries ball 3's caustics.
    const auto scene = floor_scene([](auto& sc, auto) {
        const auto glass = sc.add_material(Material<float>::glass(1.5f));
        sc.add(Sphere<float>({0, 0.6f, 3}, 0.5f), glass);
        sc.add(Sphere<float>({0, 0.6f, -3}, 0.5f), glass);
        sc.add_light(PointLight<float>{.position = {0, 3, -5}, .power = Rgb<float>(100.0f)});
    });
    const auto cam = camera_at({0, 1, 0}, {0, 0.5f, 3});
    const RenderSettings s = small();
    const EffectsPlan p = plan_effects(scene, cam, s);
    REQUIRE(p.caustic_pilot.size() == 2);
    INFO("seen: ball 1 " << p.caustic_pilot[0].seen << " W, ball 2 " << p.caustic_pilot[1].seen << " W (landed "
                         << p.caustic_pilot[1].landed << " W)");
    CHECK(p.caustic_pilot[0].seen > 0.0);
    CHECK(p.caustic_pilot[1].landed > 0.0);
    CHECK(p.caustic_pilot[1].seen < 0.01 * p.caustic_pilot[0].seen);
    CHECK(p.caustic_pass);
    CHECK_FALSE(p.hidden_caustic_objects[1]);
    CHECK(p.hidden_caustic_objects[2]);
    CHECK(mentions(p.dropped, "caustic photons at object 2 (sphere): the pilot saw under 1%"));
    CHECK(p.caustic_objects == std::vector<std::uint32_t>{1, 2});  // both still make caustics
    // Every caustic photon goes to ball 1: its cone is the only one.
    const auto aim = caustic_aim(scene, p.hidden_caustic_objects);
    REQUIRE(aim.cones.size() == 2);
    CHECK(aim.cones[0].size() + aim.cones[1].size() == 2);
    CHECK(caustic_aim(scene).cones[0].size() + caustic_aim(scene).cones[1].size() == 4);
    CHECK(p.global_collects_caustics);

    const RenderResult planned = render(scene, cam, s);
    RenderSettings on = s;
    on.effects.caustics = EffectSwitch::on;  // no pilot: both balls aimed at
    const RenderResult forced = render(scene, cam, on);
    const EffectsPlan forced_plan = plan_effects(scene, cam, on);
    CHECK(forced_plan.caustic_pilot.empty());
    CHECK_FALSE(forced_plan.hidden_caustic_objects[2]);
    CHECK(planned.stats.caustic.emitted == s.caustic_photons);
    CHECK(planned.stats.caustic.from_global > 0);  // ball 2's caustics, from the global pass
    CHECK(forced.stats.caustic.from_global == 0);
    // The same image within noise: the mean over the image moves by well under 1% between seeds.
    CHECK(planned.film.mean().y == Approx(forced.film.mean().y).epsilon(0.02));
}

TEST_CASE("a forced-on effect equals the unplanned render: forced off, it is gone", "[plan]") {
    const auto scene = diffuse_room(true);
    const RenderSettings s = small();
    const RenderResult planned = render(scene, room_camera, s);
    CHECK(planned.stats.caustic.emitted == s.caustic_photons);
    RenderSettings all_on = s;
    all_on.effects = parse_effect_switches("caustics=on,indirect=on,lights=on");
    const RenderResult unplanned = render(scene, room_camera, all_on);
    // Nothing in this scene is dropped, so forcing everything on renders the same image.
    CHECK(identical(planned.film, unplanned.film));

    RenderSettings no_caustics = s;
    no_caustics.effects.caustics = EffectSwitch::off;
    const RenderResult off = render(scene, room_camera, no_caustics);
    CHECK(off.stats.caustic.emitted == 0);
    CHECK(off.stats.caustic.stored == 0);
    CHECK(off.film.mean().y < planned.film.mean().y);  // the ball's caustic on the floor is gone
    RenderSettings no_indirect = s;
    no_indirect.effects.indirect = EffectSwitch::off;
    const RenderResult dark = render(scene, room_camera, no_indirect);
    CHECK(dark.stats.global.emitted == 0);
    CHECK(dark.film.mean().y < 0.9 * planned.film.mean().y);  // a closed room's bounce light is gone
}

TEST_CASE("the memory check budgets for the maps the plan builds, not those the settings ask for", "[plan][limits]") {
    // One floor: the plan drops both photon passes, so 10^11 photons asked for allocate nothing.
    const auto scene = floor_scene([](auto&, auto) {});
    const auto cam = camera_at({0, 2, -4}, {0, 0, 0});
    RenderSettings s = small();
    s.global_photons = 100'000'000'000;
    s.caustic_photons = 100'000'000'000;
    s.memory_limit = std::uint64_t(1) << 30;
    CHECK(estimate_memory(s, max_albedo(scene)).total() > double(s.memory_limit));
    const RenderResult planned = render(scene, cam, s);
    CHECK(planned.stats.global.emitted == 0);
    CHECK(planned.film.mean().y > 0.01);
    RenderSettings on = s;
    on.effects.indirect = EffectSwitch::on;  // the global pass forced on: its photons count again
    CHECK_THROWS_AS(render(scene, cam, on), MemoryLimitError);
}

TEST_CASE("global photons are shared by the power that reaches what the camera sees, with a floor", "[plan]") {
    // A floor, a thick wall across it (a box: the plan cannot prove anything behind it hidden),
    // light 0 in front of the wall, light 1 behind it; the camera looks at the front.
    const auto scene = floor_scene([](auto& sc, auto white) {
        sc.add(Box<float>({-20, 0, 2}, {20, 6, 2.3f}), white);
        sc.add_light(PointLight<float>{.position = {0, 3, 5}, .power = Rgb<float>(100.0f)});
    });
    const auto cam = camera_at({0, 2, -4}, {0, 0, 0});
    const RenderSettings s = small();
    const EffectsPlan p = plan_effects(scene, cam, s);
    REQUIRE(p.global_light_shares.size() == 2);
    CHECK(p.lights[0].visible_fraction > 0.1);  // the part of the infinite floor in view
    CHECK(p.lights[1].visible_fraction < 0.05);
    CHECK(p.lights[1].emits);  // not silenced on a pilot's word
    // Light 1 keeps at least the floor of its share by power (half the photons).
    CHECK(p.lights[1].global_photons >= std::size_t(p.pilot.floor * 0.5 * double(s.global_photons)));
    CHECK(p.lights[0].global_photons > 4 * p.lights[1].global_photons);
    CHECK(p.lights[0].global_photons + p.lights[1].global_photons == s.global_photons);
    CHECK(p.photons_moved > 0);
    CHECK(mentions(plan_lines(p, "pm"), "global photons by the power reaching what the camera sees"));

    // The render obeys it and, each photon carrying its own light's power, sees the same light as
    // photon's old sharing by power (lights=on) within noise.
    const RenderResult shared = render(scene, cam, s);
    RenderSettings by_power = s;
    by_power.effects.lights = EffectSwitch::on;
    const EffectsPlan q = plan_effects(scene, cam, by_power);
    CHECK(q.global_light_shares.empty());
    CHECK(q.lights[0].global_photons == s.global_photons / 2);
    const RenderResult old = render(scene, cam, by_power);
    CHECK(shared.stats.global.emitted == old.stats.global.emitted);
    CHECK(shared.stats.global.stored != old.stats.global.stored);
    CHECK(shared.film.mean().y == Approx(old.film.mean().y).epsilon(0.02));
}

TEST_CASE("aimed caustic photons give the caustic of unaimed ones within noise, with far fewer shot", "[plan]") {
    // A glass ball over a floor under a point light: its caustic is the bright spot below it.
    const auto scene = floor_scene([](auto& sc, auto) {
        sc.add(Sphere<float>({0, 1, 0}, 0.4f), sc.add_material(Material<float>::glass(1.5f)));
    });
    // Caustic power landing within 0.5 of the spot's centre, and the photons that carry it.
    struct Spot {
        double power = 0;
        std::size_t photons = 0;
    };
    const auto spot = [](std::span<const Photon> photons) {
        Spot s;
        for (const Photon& p : photons) {
            const Vec3<float> x = p.position;
            if (p.packed.kind() != PathKind::caustic || x.x * x.x + x.z * x.z > 0.25f) continue;
            s.power += double(p.packed.power().x);
            ++s.photons;
        }
        return s;
    };
    const std::size_t aimed_count = 10'000, unaimed_count = 1'000'000;
    const Spot aimed = spot(trace_caustic_photons(scene, {.photons = aimed_count, .max_depth = 100, .seed = 5}).photons);
    const Spot unaimed = spot(trace_global_photons(scene, {.photons = unaimed_count, .max_depth = 100, .seed = 6}).photons);
    INFO("aimed: " << aimed.photons << " photons, " << aimed.power << " W; unaimed: " << unaimed.photons << " photons, "
                   << unaimed.power << " W");
    REQUIRE(unaimed.photons > 1000);
    // A hundred times fewer shot, and over twenty times as many land in the caustic per photon
    // shot: the ball subtends about 1.5% of the light's sphere of directions.
    CHECK(double(aimed.photons) / double(aimed_count) > 20.0 * double(unaimed.photons) / double(unaimed_count));
    // Equal within 4 standard deviations of the two sums (photon counts' Poisson noise; the
    // aimed photons' powers vary a little, by the cone mixture's overlap).
    const double sigma = std::sqrt(1.0 / double(aimed.photons) + 1.0 / double(unaimed.photons));
    CHECK(std::abs(aimed.power / unaimed.power - 1.0) < 4.0 * sigma);
}

TEST_CASE("a spotlight aims caustic photons only at the mirrors and glass its cone reaches", "[plan]") {
    // A glass ball at x = 2 over the floor; light 0 above the origin (no cone), light 1 a
    // spotlight at x = -2 pointing away from the ball, light 2 a spotlight pointing at it.
    const auto scene = floor_scene([](auto& sc, auto) {
        sc.add(Sphere<float>({2, 0.5f, 0}, 0.5f), sc.add_material(Material<float>::glass(1.5f)));
        sc.add_light(PointLight<float>{.position = {-2, 2, 0}, .power = Rgb<float>(100.0f),
                                       .cone = Cone<float>({-1, -1, 0}, 20.0f)});
        sc.add_light(PointLight<float>{.position = {2, 3, 0}, .power = Rgb<float>(100.0f),
                                       .cone = Cone<float>({0, -1, 0}, 20.0f)});
    });
    const auto cam = camera_at({0, 2, -4}, {0, 0, 0});
    const RenderSettings s = small();
    const auto aim = caustic_aim(scene);
    CHECK(aim.cones[0].size() == 1);
    CHECK(aim.cones[1].empty());
    CHECK(aim.cones[2].size() == 1);
    const EffectsPlan p = plan_effects(scene, cam, s);
    CHECK(p.caustic_pass);
    CHECK(p.lights[1].emits);  // it lights the floor
    CHECK(p.lights[1].caustic_photons == 0);
    CHECK(p.lights[0].caustic_photons + p.lights[2].caustic_photons == s.caustic_photons);
    CHECK(mentions(p.dropped, "caustic photons from light 1 (point light at <-2, 2, 0>): its cone reaches no mirror or glass target"));
    // Its photons went to the others: the caustic map is what it was, with less noise.
    const RenderResult r = render(scene, cam, s);
    CHECK(r.stats.caustic.emitted == s.caustic_photons);
    CHECK(r.stats.caustic.stored > 0);
    CHECK(r.film.all_finite_nonnegative());
}

TEST_CASE("the automatic estimate radius follows the photons' spacing and the scene's scale", "[plan][estimate]") {
    // Photons on a jittered grid over a square of side L: density N / L^2, so k photons lie within
    // sqrt(k L^2 / (pi N)) and the radius is about twice that.
    const auto square = [](float side) {
        std::vector<Photon> photons;
        Pcg32 rng(7, 0);
        const int n = 200;
        for (int i = 0; i < n; ++i)
            for (int j = 0; j < n; ++j) {
                const Vec2<float> u = rng.uniform2<float>();
                photons.push_back({Vec3<float>((float(i) + u.x) / n * side, 0.0f, (float(j) + u.y) / n * side),
                                   PackedPhoton(Rgb<float>(1.0f), {0, -1, 0}, PathKind::indirect)});
            }
        return PhotonMap(photons);
    };
    const float expected = 2.0f * std::sqrt(100.0f / (pi<float> * 40'000.0f));  // k = 100, side 1
    const float metre = estimate_radius_from_density(square(1.0f), 100, -1.0f);
    CHECK(metre == Approx(expected).epsilon(0.1));
    CHECK(estimate_radius_from_density(square(1000.0f), 100, -1.0f) == Approx(1000.0f * metre).epsilon(1e-3));
    CHECK(estimate_radius_from_density(square(0.001f), 100, -1.0f) == Approx(0.001f * metre).epsilon(1e-3));
    // Four times the photons: half the radius.
    CHECK(estimate_radius_from_density(square(1.0f), 25, -1.0f) == Approx(0.5f * metre).epsilon(0.1));
    // Fewer photons than k: the caller's fallback.
    CHECK(estimate_radius_from_density(PhotonMap(std::vector<Photon>(10, Photon{})), 100, 3.0f) == 3.0f);

    // render() uses it where the settings say 0, and prints what it used.
    const auto scene = diffuse_room(false);
    RenderSettings s = small();
    const RenderResult automatic = render(scene, room_camera, s);
    CHECK(automatic.stats.global.radius_derived);
    CHECK(automatic.stats.global.radius > 0.01f);
    CHECK(automatic.stats.global.radius < 1.0f);
    s.global_estimate.max_radius = 0.3f;
    const RenderResult set = render(scene, room_camera, s);
    CHECK_FALSE(set.stats.global.radius_derived);
    CHECK(set.stats.global.radius == 0.3f);
    CHECK_THAT(format_stats(automatic.stats), Catch::Contains("(from the photon density)"));
}

TEST_CASE("the plan's dropped items: one line per reason shared by many, at most a screenful", "[plan]") {
    const auto lines_of = [](const std::vector<DroppedEffect>& items) {
        std::vector<std::string> lines;
        for (const DroppedEffect& d : items) lines.push_back(d.line());
        return lines;
    };
    // A few items print as they are, one line each.
    const std::vector<DroppedEffect> few{{"caustic photons", "no mirror or glass surface"},
                                         {"global photons", "one diffuse surface"},
                                         {"final gather", "one diffuse surface"}};
    CHECK(dropped_lines(few) == std::vector<std::string>{"caustic photons: no mirror or glass surface",
                                                         "global photons: one diffuse surface",
                                                         "final gather: one diffuse surface"});
    // Thousands of objects dropped for one reason (a caustic pilot's verdict): one line.
    std::vector<DroppedEffect> many;
    for (int i = 0; i < 4313; ++i)
        many.push_back({"caustic photons at object " + std::to_string(i) + " (sphere)", "the pilot saw under 1%"});
    many.push_back({"photons from light 2 (point light)", "inside object 9 (box)"});
    const auto grouped = dropped_lines(many);
    REQUIRE(grouped.size() == 2);
    CHECK(grouped[0] == "caustic photons at object 0 (sphere), object 1 (sphere), object 2 (sphere) and 4310 more: "
                        "the pilot saw under 1%");
    CHECK(grouped[1] == "photons from light 2 (point light): inside object 9 (box)");
    // An item whose `what` says it all prints without a colon, and a reason with a colon in it
    // stays whole.
    CHECK(dropped_lines({{"caustic photons at object 3", ""}, {"photons from light 0", "behind: object 1"}}) ==
          std::vector<std::string>{"caustic photons at object 3", "photons from light 0: behind: object 1"});
    // As many reasons as items: the first lines, then how many more.
    std::vector<DroppedEffect> distinct;
    for (int i = 0; i < 100; ++i)
        distinct.push_back({"caustic photons at object " + std::to_string(i), "inside object " + std::to_string(i + 100)});
    const auto capped = dropped_lines(distinct, 24);
    REQUIRE(capped.size() == 24);
    CHECK(capped[22] == lines_of(distinct)[22]);
    CHECK(capped[23] == "and 77 more lines (100 items dropped in all; EffectsPlan::dropped lists each)");
    // Cut short, the lines naming the most items come first.
    distinct.insert(distinct.end(), many.begin(), many.begin() + 50);
    const auto largest_first = dropped_lines(distinct, 24);
    REQUIRE(largest_first.size() == 24);
    CHECK(largest_first[0] == "caustic photons at object 0 (sphere), object 1 (sphere), object 2 (sphere) and 47 more: "
                              "the pilot saw under 1%");
    CHECK(largest_first[1] == lines_of(distinct)[0]);
}
