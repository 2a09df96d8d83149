// SPDX-License-Identifier: MIT
// The light-path plan with POV-Ray's other cameras: what camera_sees reports for an orthographic
// camera, and that the plan stays conservative (keeps what the image may need) for cameras that
// see more than a perspective frustum or whose rays do not start at one point.

#include <catch2/catch.hpp>

#include <photon/photon.hpp>

using namespace photon;

namespace {

RenderSettings camera_plan_settings() {
    RenderSettings s;
    s.width = 48;
    s.height = 36;
    s.global_photons = 20'000;
    s.caustic_photons = 20'000;
    return s;
}

/// A floor, glass ball 1 in front of (0, 1, 0) along +z, glass ball 2 behind it, a light above
/// the origin and one behind ball 2 (the scene of effects_plan_test's pilot test).
DefaultScene<float> two_balls_scene() {
    DefaultScene<float> scene;
    const auto white = scene.add_material(Material<float>::lambertian(Rgb<float>(0.7f)));
    const auto glass = scene.add_material(Material<float>::glass(1.5f));
    scene.add(Plane<float>({0, 1, 0}, 0.0f), white);
    scene.add(Sphere<float>({0, 0.6f, 3}, 0.5f), glass);
    scene.add(Sphere<float>({0, 0.6f, -3}, 0.5f), glass);
    scene.add_light(PointLight<float>{.position = {0, 3, 0}, .power = Rgb<float>(100.0f)});
    scene.add_light(PointLight<float>{.position = {0, 3, -5}, .power = Rgb<float>(100.0f)});
    scene.commit();
    return scene;
}

}  // namespace

TEST_CASE("cameras that see behind a perspective frustum keep the caustics it would drop", "[plan][camera]") {
    const DefaultScene<float> scene = two_balls_scene();
    const RenderSettings s = camera_plan_settings();
    const CameraFrame<float> along_z{{0, 1, 0}, {0, 0, 1}, {4.0f / 3.0f, 0, 0}, {0, 1, 0}};
    const EffectsPlan perspective = plan_effects(scene, Camera<float>(Projection::perspective, along_z), s);
    REQUIRE(perspective.caustic_pilot.size() == 2);
    CHECK(perspective.hidden_caustic_objects[2]);  // ball 2's caustics are behind the camera
    // A panoramic camera looking along +x: its 180 degrees reach from -z (u = 1) to +z (u = 0).
    const CameraFrame<float> along_x{{0, 1, 0}, {1, 0, 0}, {0, 0, -1}, {0, 1, 0}};
    const Camera<float> panoramic(Projection::panoramic, along_x);
    CHECK(panoramic.ray(1.0f, 0.6f)->direction.z < -0.9f);  // the image's right edge looks at ball 2
    // A spherical camera looking along +z sees all around.
    const Camera<float> spherical(Projection::spherical, along_z);
    for (const Camera<float>* camera : {&panoramic, &spherical}) {
        INFO(to_string(camera->projection()));
        const EffectsPlan p = plan_effects(scene, *camera, s);
        REQUIRE(p.caustic_pilot.size() == 2);
        CHECK(p.caustic_pilot[1].seen > 0.1 * p.caustic_pilot[1].landed);
        CHECK_FALSE(p.hidden_caustic_objects[1]);
        CHECK_FALSE(p.hidden_caustic_objects[2]);
    }
}

TEST_CASE("cameras whose rays start at many points prove nothing from their location", "[plan][camera]") {
    // A solid box around light 1; the camera's location is outside it, but an orthographic
    // camera's rays start across its image, part of which is inside the box.
    DefaultScene<float> scene;
    const auto white = scene.add_material(Material<float>::lambertian(Rgb<float>(0.7f)));
    scene.add(Plane<float>({0, 1, 0}, 0.0f), white);
    scene.add(Box<float>({-1, 0, -1}, {1, 2, 1}), white);
    scene.add_light(PointLight<float>{.position = {0, 5, 4}, .power = Rgb<float>(100.0f)});
    scene.add_light(PointLight<float>{.position = {0, 1, 0}, .power = Rgb<float>(100.0f)});
    scene.commit();
    const RenderSettings s = camera_plan_settings();
    const CameraFrame<float> frame{{3, 1, -0.5f}, {0, 0, 1}, {8, 0, 0}, {0, 1, 0}};
    const EffectsPlan perspective = plan_effects(scene, Camera<float>(Projection::perspective, frame), s);
    CHECK_FALSE(perspective.lights[1].emits);  // walled off from a pinhole at (3, 1, -0.5)
    const Camera<float> orthographic(Projection::orthographic, frame);
    CHECK_FALSE(orthographic.eye());
    CHECK(plan_effects(scene, orthographic, s).lights[1].emits);
    const Camera<float> cylinder(Projection::cylinder_4, frame);  // rays from a line along right
    CHECK(plan_effects(scene, cylinder, s).lights[1].emits);
    const Camera<float> blurred(Projection::perspective, frame, FocalBlur<float>{0.5f, 3.0f});
    CHECK(plan_effects(scene, blurred, s).lights[1].emits);
}

TEMPLATE_TEST_CASE("camera_sees: an orthographic camera sees the box its image sweeps, unblocked", "[plan][camera]", float,
                   double) {
    using S = TestType;
    DefaultScene<S> scene;
    const auto white = scene.add_material(Material<S>::lambertian(Rgb<S>(S(0.7))));
    scene.add(Sphere<S>({2, 0, 5}, S(0.5)), white);
    scene.commit();
    // Looking along +z from the origin; the image is 4 wide (x) and 2 high (y).
    const Camera<S> ortho(Projection::orthographic, CameraFrame<S>{{0, 0, 0}, {0, 0, 1}, {4, 0, 0}, {0, 2, 0}});
    CHECK(camera_sees(scene, ortho, Vec3<S>(1.9, 0.9, 20)));     // far, still inside the image's sweep
    CHECK_FALSE(camera_sees(scene, ortho, Vec3<S>(2.1, 0, 3)));  // beside it
    CHECK_FALSE(camera_sees(scene, ortho, Vec3<S>(0, 1.1, 3)));  // above it
    CHECK_FALSE(camera_sees(scene, ortho, Vec3<S>(0, 0, -1)));   // behind the image plane
    CHECK_FALSE(camera_sees(scene, ortho, Vec3<S>(1.8, 0, 9)));  // behind the ball, along the parallel rays
    CHECK(camera_sees(scene, ortho, Vec3<S>(1.8, 0, 4)));        // in front of it
    // A perspective camera at the same place sees (1.8, 0, 9) past the ball's side and not (1.9, 0.9, 2).
    const Camera<S> persp({0, 0, 0}, {0, 0, 1}, {4, 0, 0}, {0, 1, 0});
    CHECK(camera_sees(scene, persp, Vec3<S>(1.8, 0, 9)) == true);
    CHECK_FALSE(camera_sees(scene, persp, Vec3<S>(1.9, 0.9, 1)));
}
