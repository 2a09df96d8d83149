// SPDX-License-Identifier: MIT
// Lights in awkward places: inside a closed sphere (nothing may leak out), exactly on a surface,
// of zero power, of zero radius, and no light at all.

#include "hard_case_util.hpp"

using namespace photon;

namespace {

template <class S> PinholeCamera<S> lit_room_camera() {
    return PinholeCamera<S>::look_at({0, 1.2, -3}, {0, 0.5, 0}, {0, 1, 0}, S(55), S(32.0 / 24.0));
}

/// Floor and back wall; `extra` adds objects and lights.
template <class S, class Extra> DefaultScene<S> lit_room(Extra&& extra) {
    DefaultScene<S> scene;
    const auto white = scene.add_material(Material<S>::lambertian(Rgb<S>(S(0.7))));
    scene.add(Box<S>({-3, -0.1, -3}, {3, 0, 3}), white);
    scene.add(Box<S>({-3, 0, 1.2}, {3, 3, 1.3}), white);
    extra(scene);
    scene.commit();
    return scene;
}

const std::vector<RenderMode> all_modes{RenderMode::rt, RenderMode::pm, RenderMode::pm_direct};

double max_pixel(const Film& film) {
    double m = 0;
    for (const auto& p : film.pixels()) m = std::max(m, double(max_component(p)));
    return m;
}

}  // namespace

TEMPLATE_TEST_CASE("a light inside a closed sphere lights nothing outside it", "[hard][light]", float, double) {
    using S = TestType;
    for (const bool area : {false, true}) {
        const auto scene = lit_room<S>([&](DefaultScene<S>& sc) {
            sc.add(Sphere<S>({0, 0.6, 0}, S(0.5)), sc.add_material(Material<S>::lambertian(Rgb<S>(S(0.8)))));
            if (area)
                sc.add_light(SphereLight<S>{.center = {0.1, 0.6, 0}, .radius = S(0.2), .power = Rgb<S>(S(100))});
            else
                sc.add_light(PointLight<S>{{0.1, 0.6, 0}, Rgb<S>(S(100))});
        });
        for (const RenderMode mode : all_modes) {
            INFO((area ? "sphere" : "point") << " light, mode " << to_string(mode));
            const RenderResult r = render(scene, lit_room_camera<S>(), hard::tiny(mode));
            HARD_REQUIRE_VALID(r.film);
            hard::dump(r.film, std::string("light-inside-") + (area ? "sphere-" : "point-") + to_string(mode) + "-" + (sizeof(S) == 4 ? "f" : "d"));
            CHECK(max_pixel(r.film) == 0.0);  // not one photon or shadow ray gets out
            // The light-path plan silences a light in a closed solid the camera is outside of;
            // forced to emit, its photons all stay inside.
            CHECK(r.stats.global.stored == 0);
            if (mode == RenderMode::rt) continue;
            RenderSettings forced = hard::tiny(mode);
            forced.effects.lights = EffectSwitch::on;
            const RenderResult f = render(scene, lit_room_camera<S>(), forced);
            HARD_REQUIRE_VALID(f.film);
            CHECK(max_pixel(f.film) == 0.0);
            CHECK(f.stats.global.stored > 0);
        }
    }
}

TEMPLATE_TEST_CASE("a light exactly on a surface", "[hard][light]", float, double) {
    using S = TestType;
    // A point light on the floor lights the floor at grazing incidence (cos = 0: nothing) and the
    // wall normally; a sphere light centred on the floor is half buried in it.
    const auto point = lit_room<S>([](DefaultScene<S>& sc) { sc.add_light(PointLight<S>{{0, 0, 0}, Rgb<S>(S(50))}); });
    const auto half_buried = lit_room<S>([](DefaultScene<S>& sc) {
        sc.add_light(SphereLight<S>{.center = {0, 0, 0}, .radius = S(0.2), .power = Rgb<S>(S(50))});
    });
    for (const DefaultScene<S>* scene : {&point, &half_buried}) {
        for (const RenderMode mode : all_modes) {
            INFO((scene == &point ? "point" : "sphere") << " light on the floor, mode " << to_string(mode));
            const RenderResult r = render(*scene, lit_room_camera<S>(), hard::tiny(mode));
            HARD_REQUIRE_VALID(r.film);
            CHECK(r.film.mean().x > 0.01);  // the wall is lit
        }
    }
    // rt, point light: the floor sees it at cos = 0, so every pixel that sees the floor (the
    // bottom row) is black but for rounding in the hit point's height (cos ~ 1e-8).
    const RenderResult r = render(point, lit_room_camera<S>(), hard::tiny(RenderMode::rt));
    const double wall = max_pixel(r.film);
    for (unsigned x = 0; x < r.film.width(); ++x) CHECK(r.film.at(x, r.film.height() - 1).x <= 1e-6 * wall);
}

TEMPLATE_TEST_CASE("a zero-radius sphere light is an error: a zero-power light is valid and black", "[hard][light]",
                   float, double) {
    using S = TestType;
    DefaultScene<S> empty;
    CHECK_THROWS_WITH(empty.add_light(SphereLight<S>{.center = {0, 1, 0}, .radius = S(0), .power = Rgb<S>(S(1))}),
                      Catch::Contains("radius must be positive"));
    CHECK_THROWS_AS(empty.add_light(SphereLight<S>{.center = {0, 1, 0}, .radius = -S(1), .power = Rgb<S>(S(1))}),
                    std::invalid_argument);
    CHECK_THROWS_WITH(empty.add_light(PointLight<S>{{0, 1, 0}, Rgb<S>(S(-1))}), Catch::Contains("power"));
    CHECK(empty.lights().empty());

    const auto dark = lit_room<S>([](DefaultScene<S>& sc) {
        sc.add(Sphere<S>({0, 0.4, 0}, S(0.4)), sc.add_material(Material<S>::glass(S(1.5))));
        sc.add_light(PointLight<S>{{0, 2, 0}, Rgb<S>(S(0))});
        sc.add_light(SphereLight<S>{.center = {1, 2, 0}, .radius = S(0.1), .power = Rgb<S>(S(0))});
    });
    const auto unlit = lit_room<S>([](DefaultScene<S>& sc) {
        sc.add(Sphere<S>({0, 0.4, 0}, S(0.4)), sc.add_material(Material<S>::glass(S(1.5))));
    });
    for (const DefaultScene<S>* scene : {&dark, &unlit}) {
        for (const RenderMode mode : all_modes) {
            INFO((scene == &dark ? "zero-power lights" : "no light") << ", mode " << to_string(mode));
            const RenderResult r = render(*scene, lit_room_camera<S>(), hard::tiny(mode));
            HARD_REQUIRE_VALID(r.film);
            CHECK(max_pixel(r.film) == 0.0);
            // Nothing to emit: no photon is traced or stored.
            CHECK(r.stats.global.stored == 0);
            CHECK(r.stats.caustic.stored == 0);
        }
    }
}

TEMPLATE_TEST_CASE("a very narrow cone keeps its solid angle, its samples and a finite intensity", "[hard][light]",
                   float, double) {
    // 2 pi (1 - cos) in float was 4% off at 0.1 degrees and 0 below 0.03 degrees (intensity =
    // power / 0 = inf); the cone now holds 1 - cos = 2 sin^2(theta / 2), computed in double.
    using S = TestType;
    for (const double degrees : {30.0, 1.0, 0.1, 0.01, 0.001}) {
        INFO("half-angle " << degrees << " degrees");
        const Cone<S> cone({0, -1, 0}, S(degrees));
        const double theta = degrees * pi<double> / 180.0;
        const double exact = 4.0 * pi<double> * std::sin(theta / 2) * std::sin(theta / 2);
        CHECK(double(cone.solid_angle()) == Approx(exact).epsilon(1e-5));
        const PointLight<S> light{{0, 2, 0}, Rgb<S>(S(1)), cone};
        const Rgb<S> intensity = radiant_intensity(Light<S>(light));
        CHECK(is_finite(intensity));
        CHECK(double(intensity.x) == Approx(1.0 / exact).epsilon(1e-5));
        // Its own samples are inside it, and a direction twice as far off the axis is not.
        Pcg32 rng(1, 2);
        for (int i = 0; i < 1000; ++i) REQUIRE(cone.contains(cone.sample(rng.uniform2<S>())));
        const S off = S(std::tan(2 * theta));
        CHECK_FALSE(cone.contains(glm::normalize(Vec3<S>{off, -1, 0})));
        CHECK(cone.contains(glm::normalize(Vec3<S>{off / 4, -1, 0})));
    }
}

TEMPLATE_TEST_CASE("a spotlight of 0.01 degrees lights its spot, finitely, in every mode", "[hard][light]", float, double) {
    using S = TestType;
    // A 0.01-degree cone 2 m above the floor lights a spot 0.35 mm wide: far below a pixel, so the
    // image shows only its reflections; what matters is a finite image and the light's power
    // conserved in the photons that reach the floor.
    const auto scene = lit_room<S>([](DefaultScene<S>& sc) {
        sc.add_light(PointLight<S>{{0, 2, 0}, Rgb<S>(S(1)), Cone<S>({0, -1, 0}, S(0.01))});
    });
    for (const RenderMode mode : all_modes) {
        INFO("mode " << to_string(mode));
        const RenderResult r = render(scene, lit_room_camera<S>(), hard::tiny(mode));
        HARD_REQUIRE_VALID(r.film);
    }
    const TracedPhotons traced =
        trace_global_photons(scene, {.photons = 10'000, .max_depth = 1, .seed = 5, .threads = 2});
    Rgb<double> direct(0.0);
    for (const Photon& p : traced.photons) {
        CHECK(std::abs(p.position.x) < 1e-3f);  // all inside the spot
        direct += Rgb<double>(p.packed.power());
    }
    CHECK(direct.x == Approx(1.0).epsilon(1e-3));  // powers are stored packed, to about 1e-4
}
