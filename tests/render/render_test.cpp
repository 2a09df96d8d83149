// SPDX-License-Identifier: MIT
// Whole renders of the Cornell box at toy sizes: finite output in every mode, the same image on
// any thread count, modes that agree, and settings that are checked.

#include <catch2/catch.hpp>

#include "../../examples/cornell_box.hpp"
#include "film_compare.hpp"

#include <cstring>

using namespace photon;

namespace {

RenderSettings small(RenderMode mode) {
    RenderSettings s;
    s.mode = mode;
    s.width = 64;
    s.height = 48;
    s.samples_per_pixel = 1;
    s.shadow_samples = 4;
    s.global_photons = 50'000;
    s.caustic_photons = 50'000;
    s.final_gather_rays = 16;
    return s;
}

}  // namespace

TEMPLATE_TEST_CASE("Cornell box renders without NaN, Inf or negative pixels in every mode", "[render]", float, double) {
    const auto box = cornell::make_cornell_box<TestType>();
    for (const RenderMode mode : {RenderMode::rt, RenderMode::pm, RenderMode::pm_direct}) {
        INFO("mode " << to_string(mode));
        const RenderResult r = render(box.scene, box.camera, small(mode));
        CHECK(r.film.all_finite_nonnegative());
        CHECK(r.film.mean().x > 0.05);
        CHECK_FALSE(r.stats.partial);
    }
}

TEMPLATE_TEST_CASE("cylinder, cone, disc and torus render in DefaultScene without NaN, the same on any thread count",
                   "[render]", float, double) {
    using S = TestType;
    DefaultScene<S> scene;
    const auto white = scene.add_material(Material<S>::lambertian(Rgb<S>(S(0.7))));
    const auto glass = scene.add_material(Material<S>::glass(S(1.5)));
    scene.add(Plane<S>({0, 1, 0}, S(0)), white);
    scene.add(Cylinder<S>({-1.5, 0, 0}, {-1.5, 1, 0}, S(0.4)), white);
    scene.add(TruncatedCone<S>({-0.5, 0, 0}, S(0.4), {-0.5, 1, 0}, S(0)), glass);
    scene.add(Disc<S>({0.5, 0.01, -1}, {0, 1, 0}, S(0.4), S(0.1)), white);
    scene.add(Transformed<Torus<S>>(Torus<S>(S(0.35), S(0.12)), Affine<S>::translate({1.4, 0.12, 0})), white);
    scene.add(Transformed<TruncatedCone<S>>(TruncatedCone<S>({0, 0, 0}, S(0.3), {0, 0.5, 0}, S(0.3), true),
                                            Affine<S>::scale({1, 1, 0.5}).then(Affine<S>::translate({0.5, 0, 1}))),
              white);
    scene.add(Transformed<Disc<S>>(Disc<S>({0, 0, 0}, {0, 0, -1}, S(0.3)), Affine<S>::scale({2, 1, 1}).then(
                                                                            Affine<S>::translate({0, 1.6, 1}))),
              white);
    scene.add_light(PointLight<S>{.position = {0, 3, -2}, .power = Rgb<S>(S(60))});
    scene.commit();
    const auto camera = PinholeCamera<S>::look_at({0, 1.5, -4}, {0, 0.4, 0}, {0, 1, 0}, S(60), S(4) / S(3));
    for (const RenderMode mode : {RenderMode::rt, RenderMode::pm}) {
        INFO("mode " << to_string(mode));
        RenderSettings s = small(mode);
        s.threads = 1;
        const RenderResult one = render(scene, camera, s);
        CHECK(one.film.all_finite_nonnegative());
        CHECK(one.film.mean().x > 0.01);
        s.threads = 2;
        CHECK(identical(one.film, render(scene, camera, s).film));
    }
}

TEST_CASE("the same seed gives the same image on 1 and 2 threads", "[render]") {
    const auto box = cornell::make_cornell_box<float>();
    for (const RenderMode mode : {RenderMode::rt, RenderMode::pm, RenderMode::pm_direct}) {
        RenderSettings s = small(mode);
        s.samples_per_pixel = 4;
        s.threads = 1;
        const RenderResult one = render(box.scene, box.camera, s);
        s.threads = 2;
        const RenderResult two = render(box.scene, box.camera, s);
        INFO("mode " << to_string(mode));
        CHECK(identical(one.film, two.film));
        CHECK(one.stats.global.stored == two.stats.global.stored);
        CHECK(one.stats.rays.total() == two.stats.rays.total());
        s.seed = 2;
        const RenderResult other = render(box.scene, box.camera, s);
        if (mode != RenderMode::rt || s.shadow_samples > 1) CHECK_FALSE(identical(one.film, other.film));
    }
}

TEST_CASE("photon mapping adds indirect light to ray tracing, and its modes agree", "[render][heavy]") {
    const auto box = cornell::make_cornell_box<float>();
    RenderSettings s = small(RenderMode::rt);
    s.global_photons = 200'000;
    const double rt = render(box.scene, box.camera, s).film.mean().y;
    s.mode = RenderMode::pm;
    const double pm = render(box.scene, box.camera, s).film.mean().y;
    s.final_gather_rays = 0;
    const double pm_no_gather = render(box.scene, box.camera, s).film.mean().y;
    s.mode = RenderMode::pm_direct;
    const double pm_direct = render(box.scene, box.camera, s).film.mean().y;
    CHECK(pm > 1.2 * rt);  // indirect light is a large part of a closed box
    CHECK(pm_no_gather == Approx(pm).epsilon(0.05));
    CHECK(pm_direct == Approx(pm).epsilon(0.05));
}

TEST_CASE("rt needs no photons: pm skips the caustic pass where nothing can make a caustic", "[render]") {
    auto box = cornell::make_cornell_box<float>();
    const RenderResult rt = render(box.scene, box.camera, small(RenderMode::rt));
    CHECK(rt.stats.global.emitted == 0);
    CHECK(rt.stats.caustic.emitted == 0);
    const RenderResult pm = render(box.scene, box.camera, small(RenderMode::pm));
    CHECK(pm.stats.caustic.stored > 0);

    DefaultScene<float> diffuse_only;
    diffuse_only.add(Box<float>({-1, -1, -1}, {1, 0, 1}), diffuse_only.add_material(Material<float>::lambertian(Rgb<float>(0.5f))));
    diffuse_only.add_light(PointLight<float>{{0, 1, 0}, Rgb<float>(10)});
    diffuse_only.commit();
    const RenderResult d = render(diffuse_only, box.camera, small(RenderMode::pm));
    CHECK(d.stats.caustic.emitted == 0);
    // One box lit from outside cannot light itself: the light-path plan drops the global pass
    // too (tests/render/effects_plan_test.cpp).
    CHECK(d.stats.global.emitted == 0);
}

TEST_CASE("cancelling a render returns a partial image", "[render]") {
    const auto box = cornell::make_cornell_box<float>();
    std::atomic<bool> cancel{true};
    RenderSettings s = small(RenderMode::rt);
    s.cancel = &cancel;
    const RenderResult r = render(box.scene, box.camera, s);
    CHECK(r.stats.partial);
    CHECK(r.film.all_finite_nonnegative());
}

TEST_CASE("settings and materials out of range are errors", "[render]") {
    const auto box = cornell::make_cornell_box<float>();
    RenderSettings s = small(RenderMode::pm);
    s.width = 0;
    CHECK_THROWS_AS(render(box.scene, box.camera, s), std::invalid_argument);
    s = small(RenderMode::pm);
    s.global_estimate.max_radius = -1;
    CHECK_THROWS_AS(render(box.scene, box.camera, s), std::invalid_argument);
    CHECK_THROWS_WITH(Material<float>({.diffuse = Rgb<float>(0.7f), .specular = Rgb<float>(0.4f)}),
                      Catch::Contains("> 1 in the red channel"));
    CHECK_THROWS_AS(Material<float>::glass(0.0f), std::invalid_argument);
    CHECK_THROWS_AS(Material<float>::lambertian({-0.1f, 0.5f, 0.5f}), std::invalid_argument);
}
