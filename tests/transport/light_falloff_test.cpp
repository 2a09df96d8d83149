// SPDX-License-Identifier: MIT
// Lights that compute what POV-Ray 3.7 computes (Attenuate_Light): no falloff, the fade
// 2 / (1 + (d / D)^p), the spotlight profile cos^tightness times a cubic step between falloff and
// radius; and `shadowless`. Each against a closed form written here from POV-Ray's formulas, by
// shadow rays and by photons, in float and double, and the integrators against each other.

#include <catch2/catch.hpp>

#include <photon/photon.hpp>

#include "mode_mean.hpp"

#include <cmath>
#include <vector>

using namespace photon;

namespace {

constexpr double pi_d = 3.14159265358979323846;

/// POV-Ray's brightness factor for `fade_distance D fade_power p` at distance d (1 without a fade).
double pov_fade(double d, double D, double p) { return p > 0 && D > 0 ? 2.0 / (1.0 + std::pow(d / D, p)) : 1.0; }

/// POV-Ray's spotlight factor for the angle theta (radians) off the axis, written as POV-Ray does
/// with cosines (cubic_spline(low, high, pos)).
double pov_spot(double cos_theta, double radius_deg, double falloff_deg, double tightness) {
    if (!(cos_theta > 0)) return 0;
    const double cr = std::cos(radius_deg * pi_d / 180), cf = std::cos(falloff_deg * pi_d / 180);
    double a = std::pow(cos_theta, tightness);
    if (cr > 0 && cos_theta < cr) {
        if (cos_theta < cf) return 0;
        const double t = (cos_theta - cf) / (cr - cf);
        a *= (3 - 2 * t) * t * t;
    }
    return a;
}

/// A floor y = 0 lit by `light`; camera looking down at it.
template <Scalar S> DefaultScene<S> floor_scene(const Light<S>& light, double albedo = 0.5) {
    DefaultScene<S> scene;
    scene.add(Plane<S>({0, 1, 0}, 0), scene.add_material(Material<S>::lambertian(Rgb<S>(S(albedo)))));
    std::visit([&](const auto& l) { scene.add_light(l); }, light);
    scene.commit();
    return scene;
}

}  // namespace

TEMPLATE_TEST_CASE("Falloff: POV-Ray's fades in closed form, finite at the light and far away", "[light][falloff]",
                   float, double) {
    using S = TestType;
    const double D = 0.7;
    for (const double p : {0.5, 1.0, 2.0, 3.0}) {
        const Falloff<S> f = Falloff<S>::fade(S(D), S(p));
        for (const double d : {0.01, 0.3, 0.7, 2.0, 50.0}) {
            // I g(d) with I = 2 pi D^2 colour is pi colour times POV-Ray's factor.
            const double expected = pi_d * pov_fade(d, D, p);
            CHECK(2 * pi_d * D * D * double(f.irradiance_per_intensity(S(d))) == Approx(expected).epsilon(1e-5));
            CHECK(double(f.relative_to_inverse_square(S(d))) == Approx(d * d * pov_fade(d, D, p) / (2 * D * D)).epsilon(1e-5));
        }
        // At the light, and beyond any scene: finite, no NaN.
        for (const double d : {0.0, 1e-30, 1e-12, 1e12, 1e30}) {
            CHECK(std::isfinite(double(f.relative_to_inverse_square(S(d)))));
            CHECK(std::isfinite(double(f.irradiance_per_intensity(S(d)))));
        }
        CHECK(f.relative_to_inverse_square(S(0)) == S(0));
    }
    const Falloff<S> c = Falloff<S>::constant(S(1));
    CHECK(c.irradiance_per_intensity(S(123)) == S(1));
    CHECK(c.relative_to_inverse_square(S(3)) == Approx(9.0));
    CHECK(Falloff<S>::inverse_square().relative_to_inverse_square(S(1e30)) == S(1));
    CHECK(std::isfinite(double(c.relative_to_inverse_square(S(1e30)))));  // saturates in float
    CHECK_THROWS_AS(Falloff<S>::fade(S(0), S(2)).validate(), std::invalid_argument);
    CHECK_THROWS_AS(Falloff<S>::fade(S(1), S(-1)).validate(), std::invalid_argument);
}

TEMPLATE_TEST_CASE("Cone::pov_spotlight: POV-Ray's profile, its power and its bounds", "[light][spotlight]", float,
                   double) {
    using S = TestType;
    struct Spot { double radius, falloff, tightness, bound; };
    for (const Spot sp : {Spot{30, 45, 0, 45}, Spot{11, 25, 50, 25}, Spot{20, 20, 0, 20}, Spot{40, 20, 3, 40},
                          Spot{90, 90, 1, 90}, Spot{0.05, 0.1, 0, 0.1}, Spot{15, 120, 2, 90}}) {
        INFO("radius " << sp.radius << " falloff " << sp.falloff << " tightness " << sp.tightness);
        const Cone<S> cone = Cone<S>::pov_spotlight({0, -1, 0}, sp.radius, sp.falloff, sp.tightness);
        CHECK(double(cone.half_angle_degrees()) == Approx(sp.bound).epsilon(1e-5));
        // The profile along directions theta off the axis.
        for (int i = 0; i <= 40; ++i) {
            const double theta = sp.bound * 1.2 * i / 40 * pi_d / 180;
            const Vec3<S> dir(S(std::sin(theta)), S(-std::cos(theta)), S(0));
            const double expected = pov_spot(std::cos(theta), sp.radius, sp.falloff, sp.tightness);
            CHECK(double(cone.profile(glm::normalize(dir))) == Approx(expected).margin(std::is_same_v<S, float> ? 2e-4 : 1e-9));
        }
        // Power / axial intensity: 2 pi times the integral of the profile over cos(theta), here by
        // the midpoint rule in theta with 2^16 steps (the reference is independent of the Simpson
        // rule and closed forms inside the cone).
        double integral = 0;
        constexpr int n = 1 << 16;
        const double top = sp.bound * pi_d / 180;
        for (int i = 0; i < n; ++i) {
            const double theta = (i + 0.5) * top / n;
            integral += pov_spot(std::cos(theta), sp.radius, sp.falloff, sp.tightness) * std::sin(theta) * top / n;
        }
        CHECK(double(cone.effective_solid_angle()) == Approx(2 * pi_d * integral).epsilon(std::is_same_v<S, float> ? 1e-4 : 1e-6));
    }
    // POV-Ray's radiosity Cornell box: radius -90 (read as 90) falloff 90 tightness 1 is a cosine lobe of power pi I.
    CHECK(double(Cone<S>::pov_spotlight({0, -1, 0}, 90, 90, 1).effective_solid_angle()) == Approx(pi_d).epsilon(1e-6));
    CHECK_THROWS_AS(Cone<S>::pov_spotlight({0, -1, 0}, 0, 0, 0), std::invalid_argument);
}

TEMPLATE_TEST_CASE("shadow rays: irradiance on a plane under POV-Ray lights in closed form", "[light][falloff][spotlight]",
                   float, double) {
    using S = TestType;
    const Vec3<S> at{0, 2, 0};
    const double colour = 0.8;
    // A fading spotlight (POV-Ray: colour 0.8, fade_distance 1.5 fade_power 1, spotlight radius 20
    // falloff 40 tightness 5 point_at <0.3, 0, 0>), and a plain light without a fade.
    const Cone<S> cone = Cone<S>::pov_spotlight(Vec3<S>(0.3, -2, 0), 20, 40, 5);
    const PointLight<S> spot{at, Rgb<S>(S(2 * pi_d * 1.5 * 1.5 * colour) * cone.effective_solid_angle()), cone,
                             Falloff<S>::fade(S(1.5), S(1))};
    const PointLight<S> plain{at, Rgb<S>(S(pi_d * colour * 4 * pi_d)), {}, Falloff<S>::constant(S(1))};
    const Vec3<double> axis = glm::normalize(Vec3<double>(0.3, -2, 0));
    for (const double x : {-2.0, -0.5, 0.0, 0.3, 0.8, 1.2, 1.6, 3.0, 40.0}) {
        const Vec3<S> p(S(x), S(0), S(0.1));
        const Vec3<double> to = Vec3<double>(p) - Vec3<double>(at);
        const double d = glm::length(to), cos_floor = 2.0 / d;
        const double e_spot = pi_d * colour * pov_fade(d, 1.5, 1) * pov_spot(glm::dot(to / d, axis), 20, 40, 5);
        const double e_plain = pi_d * colour;
        for (const auto& [light, expected] : {std::pair{Light<S>(spot), e_spot}, std::pair{Light<S>(plain), e_plain}}) {
            const auto in = sample_incident(light, p, Vec2<S>(S(0.5)));
            const double got = in ? double(in->irradiance.x) * double(glm::dot(in->direction, Vec3<S>(0, 1, 0))) : 0.0;
            INFO("x = " << x);
            CHECK(got == Approx(expected * cos_floor).epsilon(2e-5).margin(1e-12));
        }
    }
    // A light on the surface: nothing (the direction is undefined), and no NaN just above it.
    CHECK_FALSE(sample_incident(Light<S>(plain), at, Vec2<S>(S(0.5))));
    for (const double h : {1e-3, 1e-8, 1e-15}) {
        const auto in = sample_incident(Light<S>(spot), Vec3<S>(at.x, S(double(at.y) - h), at.z), Vec2<S>(S(0.5)));
        if (in) CHECK(std::isfinite(double(in->irradiance.x)));
    }
}

TEMPLATE_TEST_CASE("photons from a non-physical light: first-hit irradiance equals the shadow rays'", "[light][falloff][photons]",
                   float, double) {
    using S = TestType;
    // POV-Ray's light without a fade (constant irradiance) and a fade with power 3, each a soft
    // spotlight so every photon lands near where we measure.
    const Cone<S> cone = Cone<S>::pov_spotlight({0, -1, 0}, 30, 60, 2);
    for (const Falloff<S> falloff : {Falloff<S>::constant(S(1)), Falloff<S>::fade(S(0.8), S(3))}) {
        const Light<S> light = PointLight<S>{{0, 1, 0}, Rgb<S>(S(3) * cone.effective_solid_angle()), cone, falloff};
        const auto scene = floor_scene<S>(light);
        const PhotonTracingSettings settings{.photons = 1'500'000, .store = {.direct = true, .caustic = false, .indirect = false}, .seed = 5};
        const PhotonMap map(trace_global_photons(scene, settings).photons);
        // k = 8000: 1.1% standard deviation (float and double draw different azimuths, so their
        // noise differs); the disc (r ~ 0.07) blurs the peak by under 0.5%. 4% is 3.5 sigma.
        const EstimateSettings estimate{.k = 8'000, .max_radius = 0.5f};
        EstimateScratch scratch;
        for (const double x : {0.0, 0.4, 0.8}) {
            const Vec3<S> p(S(x), S(0), S(0));
            const auto in = sample_incident(light, p, Vec2<S>(S(0.5)));
            REQUIRE(in);
            const double shadow_ray = double(in->irradiance.x) * double(in->direction.y);
            const Rgb<double> e = estimate_irradiance(map, Vec3<double>(p), Vec3<double>{0, 1, 0}, estimate, scratch);
            INFO("falloff kind " << int(falloff.kind) << " at x = " << x << ": photons " << e.x << ", shadow ray " << shadow_ray);
            CHECK(e.x == Approx(shadow_ray).epsilon(0.04));
        }
    }
}

TEST_CASE("a light without falloff: photon mapping, SPPM and the path tracer agree on indirect light", "[light][falloff][render]") {
    // Floor and a wall at x = 1: the wall's light on the floor is indirect. The light (POV-Ray's
    // default, no fade) lights the wall 1.5 m away as brightly as the floor below it.
    DefaultScene<double> scene;
    scene.add(Plane<double>({0, 1, 0}, 0), scene.add_material(Material<double>::lambertian(Rgb<double>(0.5))));
    scene.add(Plane<double>({-1, 0, 0}, -1), scene.add_material(Material<double>::lambertian(Rgb<double>(0.8))));
    scene.add_light(PointLight<double>{{0, 1, 0}, Rgb<double>(4 * pi_d), {}, Falloff<double>::constant(1)});
    scene.commit();
    const auto camera = PinholeCamera<double>::look_at({-0.5, 2, -1.5}, {0.5, 0.3, 0}, {0, 1, 0}, 50, 1.0);
    const photon_test::ModeMeanSettings settings{.size = 24, .sppm_passes = 16, .seed = 3};
    const auto mean = [&](RenderMode mode, unsigned spp) { return photon_test::mode_mean(scene, camera, mode, spp, settings); };
    const double rt = mean(RenderMode::rt, 4), pm = mean(RenderMode::pm, 4), reference = mean(RenderMode::reference, 64),
                 sppm = mean(RenderMode::sppm, 1);
    INFO("rt " << rt << ", pm " << pm << ", reference " << reference << ", sppm " << sppm);
    CHECK(pm > 1.05 * rt);  // the indirect light is there, and not negligible
    CHECK(pm == Approx(reference).epsilon(0.03));
    CHECK(sppm == Approx(reference).epsilon(0.03));
}

TEMPLATE_TEST_CASE("shadowless: direct light through occluders, photons still blocked", "[light][shadowless]", float, double) {
    using S = TestType;
    DefaultScene<S> scene;
    const auto white = scene.add_material(Material<S>::lambertian(Rgb<S>(S(0.5))));
    scene.add(Plane<S>({0, 1, 0}, 0), white);
    scene.add(Box<S>({-0.5, 0.4, -0.5}, {0.5, 0.5, 0.5}), white);  // a roof between light and floor point
    scene.add_light(PointLight<S>{{0, 1, 0}, Rgb<S>(S(4) * pi<S>), {}, {}, false});
    scene.commit();
    ShadingContext ctx;
    const Vec3<S> x{0, 0, 0}, n{0, 1, 0};
    const Material<S> m = Material<S>::lambertian(Rgb<S>(S(0.5)));
    const Rgb<S> l = direct_lighting(scene, x, Vec3<S>(0, S(1e-4), 0), n, n, n, m, Rgb<S>(S(0.5)), 1, ctx);
    CHECK(double(l.x) == Approx(0.5 / pi_d * 1.0).epsilon(1e-5));  // I / d^2 = 1, unshadowed
    CHECK(ctx.rays.shadow == 0);
}

TEMPLATE_TEST_CASE("POV-Ray lights at the surface, very near and very far: finite images", "[light][falloff][hard]", float,
                   double) {
    using S = TestType;
    const Cone<S> spot = Cone<S>::pov_spotlight({0.2, -1, 0}, 10, 40, 20);
    for (const double height : {0.0, 1e-6, 1e6}) {
        for (const Falloff<S> falloff : {Falloff<S>::constant(S(1)), Falloff<S>::fade(S(0.5), S(3)), Falloff<S>::fade(S(1e-3), S(2))}) {
            DefaultScene<S> scene;
            const auto white = scene.add_material(Material<S>::lambertian(Rgb<S>(S(0.7))));
            scene.add(Plane<S>({0, 1, 0}, 0), white);
            scene.add(Sphere<S>({0.3, 0.3, 0.2}, S(0.3)), white);
            scene.add_light(PointLight<S>{{0, S(height), 0}, Rgb<S>(S(10)), {}, falloff});
            scene.add_light(SphereLight<S>{{-0.5, S(height) + S(0.2), 0}, S(0.1), Rgb<S>(S(5)), spot, falloff});
            scene.commit();
            const auto camera = PinholeCamera<S>::look_at({0, 1.5, -2}, {0, 0, 0}, {0, 1, 0}, S(60), S(1));
            for (const RenderMode mode : {RenderMode::rt, RenderMode::pm, RenderMode::reference}) {
                RenderSettings s;
                s.mode = mode;
                s.width = s.height = 12;
                s.samples_per_pixel = 2;
                s.global_photons = 20'000;
                s.caustic_photons = 0;
                s.threads = 2;
                const RenderResult r = render(scene, camera, s);
                for (const auto& p : r.film.pixels()) {
                    INFO("height " << height << ", mode " << to_string(mode));
                    REQUIRE(is_finite(p));
                    REQUIRE(min_component(p) >= 0);
                }
            }
        }
    }
}
