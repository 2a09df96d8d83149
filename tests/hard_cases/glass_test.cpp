// SPDX-License-Identifier: MIT
// Glass at its limits: ior 1 (must be invisible), ior 2.5 (total internal reflection), a ray
// leaving at the critical angle, glass nested in glass, and glass spheres that touch. Glass
// absorbs nothing, so photon tracing must deliver all the light that enters it back out.

#include "hard_case_util.hpp"

#include <photon/math/frame.hpp>

using namespace photon;

namespace {

/// A floor and a back wall under a sphere light, plus whatever `add_glass` puts in front.
template <class S, class AddGlass> DefaultScene<S> glass_room(AddGlass&& add_glass, ObjectOptions glass_options = {}) {
    DefaultScene<S> scene;
    const auto white = scene.add_material(Material<S>::lambertian(Rgb<S>(S(0.7))));
    const auto green = scene.add_material(Material<S>::lambertian({S(0.2), S(0.7), S(0.3)}));
    scene.add(Box<S>({-3, -0.1, -3}, {3, 0, 3}), white);
    scene.add(Box<S>({-3, 0, 1.2}, {3, 3, 1.3}), green);
    scene.add_light(SphereLight<S>{.center = {0.3, 2.2, -0.8}, .radius = S(0.15), .power = Rgb<S>(S(80))});
    add_glass(scene, glass_options);
    scene.commit();
    return scene;
}

template <class S> PinholeCamera<S> glass_room_camera() {
    return PinholeCamera<S>::look_at({0, 1.0, -3}, {0, 0.5, 0}, {0, 1, 0}, S(50), S(32.0 / 24.0));
}

/// Power (channel mean) stored at first diffuse hits on a nearly black enclosure (albedo 1e-6:
/// photons are stored once and then absorbed), with a cone light aimed at the glass. All of
/// the light power must arrive there: glass only redirects it.
template <class S, class AddGlass> double power_through_glass(AddGlass&& add_glass) {
    DefaultScene<S> scene;
    scene.add(Sphere<S>({0, 0, 0}, S(10)), scene.add_material(Material<S>::lambertian(Rgb<S>(S(1e-6)))));
    add_glass(scene, ObjectOptions{});
    scene.add_light(PointLight<S>{{0, 4, 0}, Rgb<S>(S(1)), Cone<S>({0, -1, 0}, S(15))});
    scene.commit();
    const TracedPhotons traced =
        trace_global_photons(scene, {.photons = 40'000, .max_depth = 200, .seed = 17, .threads = 2});
    double sum = 0;
    for (const Photon& p : traced.photons) sum += average(Rgb<double>(p.packed.power()));
    return sum;
}

template <class S> auto glass_sphere(Vec3<S> c, S r, S ior) {
    return [=](DefaultScene<S>& scene, ObjectOptions o) { scene.add(Sphere<S>(c, r), scene.add_material(Material<S>::glass(ior)), o); };
}

}  // namespace

TEMPLATE_TEST_CASE("a glass sphere of ior 1 is invisible", "[hard][glass]", float, double) {
    using S = TestType;
    const auto nothing = [](DefaultScene<S>&, ObjectOptions) {};
    const auto sphere = glass_sphere<S>({0, 0.5, -0.5}, S(0.5), S(1));
    const PinholeCamera<S> camera = glass_room_camera<S>();
    SECTION("rt, sphere casting no shadow: the same image to rounding") {
        const RenderSettings s = hard::tiny(RenderMode::rt);
        const RenderResult without = render(glass_room<S>(nothing), camera, s);
        const RenderResult with = render(glass_room<S>(sphere, {.casts_shadow = false}), camera, s);
        HARD_REQUIRE_VALID(with.film);
        // Stratified shadow samples draw the same numbers whether or not a ray crossed the
        // sphere: only rounding along the twice-offset rays differs.
        CHECK(hard::max_relative_difference(with.film, without.film, 1e-3) < 1e-3);
    }
    SECTION("pm: its shadow is filled by caustic photons, which carry the same light") {
        RenderSettings s = hard::tiny(RenderMode::pm);
        s.caustic_photons = 200'000;
        const RenderResult without = render(glass_room<S>(nothing), camera, s);
        const RenderResult with = render(glass_room<S>(sphere), camera, s);
        HARD_REQUIRE_VALID(with.film);
        hard::dump(with.film, std::string("ior1-pm-with-") + (sizeof(S) == 4 ? "f" : "d"));
        hard::dump(without.film, std::string("ior1-pm-without-") + (sizeof(S) == 4 ? "f" : "d"));
        const auto a = hard::region_means(with.film, 4, 3), b = hard::region_means(without.film, 4, 3);
        for (std::size_t i = 0; i < a.size(); ++i) {
            INFO("region " << i << ": " << a[i] << " with the sphere, " << b[i] << " without");
            CHECK(a[i] == Approx(b[i]).epsilon(0.12));
        }
    }
}

TEMPLATE_TEST_CASE("glass conserves power: ior 1, ior 2.5 with total internal reflection, nested, touching",
                   "[hard][glass]", float, double) {
    using S = TestType;
    const double bare = power_through_glass<S>([](DefaultScene<S>&, ObjectOptions) {});
    CHECK(bare == Approx(1.0).epsilon(1e-3));
    const auto glass = [](S ior) { return Material<S>::glass(ior); };
    const std::vector<std::pair<const char*, std::function<void(DefaultScene<S>&, ObjectOptions)>>> cases{
        {"ior 1 sphere", glass_sphere<S>({0, 0, 0}, S(1), S(1))},
        {"ior 2.5 sphere", glass_sphere<S>({0, 0, 0}, S(1), S(2.5))},
        {"ior 2.5 cube (total internal reflection at its sides)",
         [&](DefaultScene<S>& sc, ObjectOptions o) { sc.add(Box<S>(Vec3<S>(S(-1)), Vec3<S>(S(1))), sc.add_material(glass(S(2.5))), o); }},
        {"ior 2.5 rotated cube",
         [&](DefaultScene<S>& sc, ObjectOptions o) {
             sc.add(Transformed<Box<S>>(Box<S>(Vec3<S>(S(-1)), Vec3<S>(S(1))), Affine<S>::rotate_xyz({20, 30, 40})),
                    sc.add_material(glass(S(2.5))), o);
         }},
        {"ior 2.5 sphere nested in an ior 1.5 sphere",
         [&](DefaultScene<S>& sc, ObjectOptions o) {
             sc.add(Sphere<S>({0, 0, 0}, S(1.2)), sc.add_material(glass(S(1.5))), o);
             sc.add(Sphere<S>({0, 0.2, 0}, S(0.6)), sc.add_material(glass(S(2.5))), o);
         }},
        {"two ior 1.5 spheres touching at the origin",
         [&](DefaultScene<S>& sc, ObjectOptions o) {
             const auto m = sc.add_material(glass(S(1.5)));
             sc.add(Sphere<S>({0, 0.6, 0}, S(0.6)), m, o);
             sc.add(Sphere<S>({0, -0.6, 0}, S(0.6)), m, o);
         }},
    };
    for (const auto& [name, add] : cases) {
        INFO(name);
        // 200 bounces inside glass lose about 0.82^200 of a photon's power at worst.
        CHECK(power_through_glass<S>(add) == Approx(bare).epsilon(2e-3));
    }
}

TEMPLATE_TEST_CASE("glass scenes render finite images in every mode", "[hard][glass]", float, double) {
    using S = TestType;
    const std::vector<std::function<void(DefaultScene<S>&, ObjectOptions)>> cases{
        glass_sphere<S>({0, 0.5, -0.5}, S(0.5), S(2.5)),
        [](DefaultScene<S>& sc, ObjectOptions o) {
            sc.add(Box<S>({-0.5, 0, -0.9}, {0.5, 0.8, -0.1}), sc.add_material(Material<S>::glass(S(2.5))), o);
        },
        [](DefaultScene<S>& sc, ObjectOptions o) {
            sc.add(Sphere<S>({0, 0.6, -0.5}, S(0.6)), sc.add_material(Material<S>::glass(S(1.5))), o);
            sc.add(Sphere<S>({0, 0.6, -0.5}, S(0.3)), sc.add_material(Material<S>::glass(S(2.5))), o);
        },
        [](DefaultScene<S>& sc, ObjectOptions o) {
            const auto m = sc.add_material(Material<S>::glass(S(1.5)));
            sc.add(Sphere<S>({-0.4, 0.4, -0.5}, S(0.4)), m, o);
            sc.add(Sphere<S>({0.4, 0.4, -0.5}, S(0.4)), m, o);
        },
    };
    for (std::size_t i = 0; i < cases.size(); ++i) {
        const DefaultScene<S> scene = glass_room<S>(cases[i]);
        for (const RenderMode mode : {RenderMode::rt, RenderMode::pm, RenderMode::pm_direct}) {
            INFO("case " << i << ", mode " << to_string(mode));
            const RenderResult r = render(scene, glass_room_camera<S>(), hard::tiny(mode));
            HARD_REQUIRE_VALID(r.film);
            CHECK(r.film.mean().y > 0.01);
        }
    }
}

TEMPLATE_TEST_CASE("a ray leaving glass at and around the critical angle", "[hard][glass]", float, double) {
    using S = TestType;
    const S ior = S(2.5);
    const Material<S> glass = Material<S>::glass(ior);
    // The ray travels inside the glass towards -z and meets the surface whose outward normal is
    // -z; the normal facing the ray is +z.
    const Vec3<S> outward{0, 0, -1}, n{0, 0, 1};
    const S critical = std::asin(S(1) / ior);
    std::vector<S> angles;
    for (int k = -100; k <= 100; ++k) angles.push_back(critical * (S(1) + S(k) * std::numeric_limits<S>::epsilon()));
    for (int k = -50; k <= 50; ++k) angles.push_back(critical + S(k) * S(1e-3));
    int bad = 0, transmitted_past_critical = 0, k = 0;
    for (const S theta : angles) {
        ++k;
        const Vec3<S> d{std::sin(theta), S(0), -std::cos(theta)};
        const Scattering<S> s = glass.scattering(Vec3<S>(S(0)), std::cos(theta), false);
        const auto t = refract(d, n, relative_eta(glass, false));
        if (!is_finite(s.specular) || !is_finite(s.transmission)) ++bad;
        if (std::abs(average(s.specular + s.transmission) - S(1)) > S(1e-5)) ++bad;  // nothing is lost
        if (t) {
            // A refracted ray goes out (away from the normal side it came from) and is unit length.
            if (!is_finite(*t) || !(glm::dot(*t, n) <= S(0)) || std::abs(glm::length(*t) - S(1)) > S(1e-4)) ++bad;
            if (theta > critical * (S(1) + S(1e-4))) ++transmitted_past_critical;
        } else if (theta < critical * (S(1) - S(1e-4))) {
            ++bad;  // well below the critical angle the ray must refract
        }
        // Photon tracing at this hit: Russian roulette never yields a NaN direction or weight.
        Pcg32 rng(std::uint64_t(k), 0);
        for (int i = 0; i < 16; ++i) {
            const PhotonScatter<S> p = russian_roulette(glass, Vec3<S>(S(0)), facing(outward, d), d, rng);
            if (p.event == ScatterEvent::absorbed || !is_finite(p.direction) || !is_finite(p.weight)) ++bad;
        }
    }
    CHECK(bad == 0);
    CHECK(transmitted_past_critical == 0);
}
