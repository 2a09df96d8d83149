// SPDX-License-Identifier: MIT
// POV-Ray's parallel light (light/parallel_light.hpp): photons that all travel one way from a
// beam covering the scene, shadow rays back to the light's plane, an irradiance that does not
// depend on the distance, photons agreeing with shadow rays (also at grazing incidence), and
// photon mapping, SPPM and the path tracer agreeing on a scene it lights, in float and double.

#include <catch2/catch.hpp>

#include <photon/photon.hpp>

#include "mode_mean.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

using namespace photon;

namespace {

constexpr double parallel_pi = 3.14159265358979323846;

template <Scalar S> ParallelLight<S> sun(Vec3<S> position, Vec3<S> towards, S irradiance) {
    ParallelLight<S> light;
    light.position = position;
    light.direction = glm::normalize(towards);
    light.irradiance = Rgb<S>(irradiance);
    return light;
}

/// A 4 x 4 floor slab (top at y = 0) of albedo 0.5 under `light`, and optionally a box on it.
template <Scalar S> DefaultScene<S> parallel_floor_scene(const ParallelLight<S>& light, bool box) {
    DefaultScene<S> scene;
    const auto white = scene.add_material(Material<S>::lambertian(Rgb<S>(S(0.5))));
    scene.add(Box<S>({-2, -0.1, -2}, {2, 0, 2}), white);
    if (box) scene.add(Box<S>({-0.3, 0, -0.3}, {0.3, 0.6, 0.3}), white);
    scene.add_light(light);
    scene.commit();
    return scene;
}

/// The irradiance direct_lighting finds at p on the floor (normal +y), from its radiance off a
/// Lambertian surface of albedo 0.5.
template <Scalar S> double parallel_direct(const DefaultScene<S>& scene, const Vec3<S>& p) {
    ShadingContext ctx;
    const Vec3<S> n{0, 1, 0};
    const Material<S> m = Material<S>::lambertian(Rgb<S>(S(0.5)));
    return double(direct_lighting(scene, p, p + Vec3<S>(0, S(1e-4), 0), n, n, n, m, Rgb<S>(S(0.5)), 1, ctx).x) * parallel_pi / 0.5;
}

}  // namespace

TEMPLATE_TEST_CASE("parallel light: photons leave the beam disc on the light's plane, all one way", "[light][parallel][photons]",
                   float, double) {
    using S = TestType;
    const Vec3<S> direction = glm::normalize(Vec3<S>(S(0.3), S(-1), S(0.2)));
    const auto scene = parallel_floor_scene(sun<S>({1, 10, -2}, direction, S(2)), false);
    const auto& light = std::get<ParallelLight<S>>(scene.lights()[0]);
    // The beam is the objects' ball seen along the direction, centred on its projection.
    const Ball<S> ball = scene.environment_ball();
    CHECK(light.beam_radius == Approx(double(ball.radius)));
    CHECK(double(light.plane_distance(light.beam_center)) == Approx(0.0).margin(1e-4));
    const Vec3<S> off = ball.center - light.beam_center;
    CHECK(double(glm::length(off - glm::dot(off, direction) * direction)) == Approx(0.0).margin(1e-4));
    CHECK(double(light.power.x) == Approx(2.0 * parallel_pi * double(ball.radius * ball.radius)).epsilon(1e-5));

    Pcg32 rng(7, 1);
    double mean_r2 = 0;
    constexpr int n = 20'000;
    for (int i = 0; i < n; ++i) {
        const Vec3<S> d = sample_emission_direction(scene.lights()[0], EmissionSampler::rejection, rng);
        REQUIRE(d == direction);
        const Vec3<S> o = sample_emission_origin(scene.lights()[0], d, rng.uniform2<S>());
        REQUIRE(std::abs(double(light.plane_distance(o))) < 1e-4);
        const double r = glm::length(Vec3<double>(o - light.beam_center));
        REQUIRE(r <= double(light.beam_radius) * (1 + 1e-5));
        mean_r2 += r * r / n;
    }
    // Uniform over the disc: the mean of r^2 is R^2 / 2 (the standard error is 0.2% at n = 20k).
    CHECK(mean_r2 == Approx(0.5 * double(light.beam_radius * light.beam_radius)).epsilon(0.01));
}

TEMPLATE_TEST_CASE("parallel light: the same irradiance at any distance, none behind its plane", "[light][parallel]", float,
                   double) {
    using S = TestType;
    const Vec3<S> direction = glm::normalize(Vec3<S>(S(-0.2), S(-1), S(0.4)));
    const Light<S> light = sun<S>({0, 0, 0}, direction, S(3));
    for (const double d : {1e-3, 1.0, 10.0, 1e4}) {
        // A point d in front of the plane, moved sideways too: its irradiance is the stated one,
        // its shadow ray runs back along the direction to the plane.
        const Vec3<S> x = S(d) * direction + Vec3<S>(S(5), S(0), S(-7)) - S(glm::dot(Vec3<S>(5, 0, -7), direction)) * direction;
        const auto in = sample_incident(light, x, Vec2<S>(S(0.5)));
        REQUIRE(in);
        CHECK(double(in->irradiance.x) == Approx(3.0).epsilon(1e-6));
        CHECK(double(in->distance) == Approx(d).epsilon(1e-3));
        CHECK(double(glm::dot(in->direction, -direction)) == Approx(1.0).epsilon(1e-6));
    }
    // Behind the plane (POV-Ray lights it without shadows there; no photon could reach it).
    CHECK_FALSE(sample_incident(light, -direction, Vec2<S>(S(0.5))));
    // POV-Ray's fade of the plane distance: 1 / (1 + (d / D)^p) of the irradiance.
    ParallelLight<S> faded = std::get<ParallelLight<S>>(light);
    faded.falloff = Falloff<S>::fade(S(2), S(2));
    const auto in = sample_incident(Light<S>(faded), S(4) * direction, Vec2<S>(S(0.5)));
    REQUIRE(in);
    CHECK(double(in->irradiance.x) == Approx(3.0 / 5.0).epsilon(1e-5));
    // Direct lighting on a tilted-lit floor: E cos(theta), at every distance below the light.
    const auto scene = parallel_floor_scene(sun<S>({0, 50, 0}, direction, S(3)), false);
    const double cos_theta = -double(direction.y);
    CHECK(parallel_direct(scene, Vec3<S>(0, 0, 0)) == Approx(3.0 * cos_theta).epsilon(1e-4));
    CHECK(parallel_direct(scene, Vec3<S>(S(1.5), 0, S(-1.5))) == Approx(3.0 * cos_theta).epsilon(1e-4));
}

TEMPLATE_TEST_CASE("parallel light photons: first-hit irradiance equals the shadow rays', also grazing", "[light][parallel][photons]",
                   float, double) {
    using S = TestType;
    // Steep and grazing (84 degrees from the normal: cos 0.1): the floor sees a tenth of the beam.
    for (const double tilt : {0.4, 9.95}) {
        const Vec3<S> direction = glm::normalize(Vec3<S>(S(tilt), S(-1), S(0)));
        const auto scene = parallel_floor_scene(sun<S>(S(-30) * direction, direction, S(1)), true);
        const PhotonTracingSettings settings{.photons = 800'000, .store = {.direct = true, .caustic = false, .indirect = false}, .seed = 3};
        const PhotonMap map(trace_global_photons(scene, settings).photons);
        // About 800k cos / (pi 2.9^2 / 16) photons per unit area of the floor: k = 1000 is 3.2%
        // standard deviation.
        const EstimateSettings estimate{.k = 1'000, .max_radius = 0.5f};
        EstimateScratch scratch;
        // A point in the open, and one in the box's shadow (behind it, away from the light: the
        // shadow reaches 0.6 tilt past the box's side at x = 0.3).
        for (const double x : {-1.2, std::min(0.3 + 0.3 * tilt, 1.5)}) {
            const Vec3<S> p(S(x), S(0), S(0.1));
            const double shadow_rays = parallel_direct(scene, p);
            const Rgb<double> e = estimate_irradiance(map, Vec3<double>(p), Vec3<double>{0, 1, 0}, estimate, scratch);
            INFO("tilt " << tilt << " at x = " << x << ": photons " << e.x << ", shadow rays " << shadow_rays);
            if (x < 0) {
                CHECK(shadow_rays == Approx(-double(direction.y)).epsilon(1e-4));
                CHECK(e.x == Approx(shadow_rays).epsilon(0.1));
            } else {
                // The shadow is narrow (0.6 across): the estimate's disc reaches its lit sides.
                CHECK(shadow_rays == 0.0);
                CHECK(e.x < 0.4 * -double(direction.y));
            }
        }
    }
}

TEST_CASE("parallel light: photon mapping, SPPM and the path tracer agree", "[light][parallel][render]") {
    // A floor slab, a wall at x = 1.5 and a box casting a shadow under a slanting parallel light.
    DefaultScene<double> scene;
    const auto white = scene.add_material(Material<double>::lambertian(Rgb<double>(0.6)));
    scene.add(Box<double>({-2, -0.1, -2}, {2, 0, 2}), white);
    scene.add(Box<double>({1.5, 0, -2}, {1.6, 2, 2}), white);
    scene.add(Box<double>({-0.3, 0, -0.3}, {0.1, 0.4, 0.1}), white);
    scene.add_light(sun<double>({-3, 6, -1}, {0.5, -1, 0.2}, 2.0));
    scene.commit();
    const auto camera = PinholeCamera<double>::look_at({-1.5, 1.8, -2.5}, {0.3, 0.2, 0}, {0, 1, 0}, 50, 1.0);
    const auto mean = [&](RenderMode mode, unsigned spp) { return photon_test::mode_mean(scene, camera, mode, spp); };
    const double rt = mean(RenderMode::rt, 4), pm = mean(RenderMode::pm, 4), reference = mean(RenderMode::reference, 48),
                 sppm = mean(RenderMode::sppm, 1);
    INFO("rt " << rt << ", pm " << pm << ", reference " << reference << ", sppm " << sppm);
    CHECK(pm > 1.05 * rt);  // indirect light is there
    CHECK(pm == Approx(reference).epsilon(0.03));
    CHECK(sppm == Approx(reference).epsilon(0.03));
}

TEMPLATE_TEST_CASE("parallel light: validation, a scene of infinite planes, a light added after commit", "[light][parallel][hard]",
                   float, double) {
    using S = TestType;
    ParallelLight<S> bad = sun<S>({0, 1, 0}, {0, -1, 0}, S(1));
    bad.direction = {0, -2, 0};
    CHECK_THROWS_AS(validate(Light<S>(bad)), std::invalid_argument);
    bad.direction = {0, -1, 0};
    bad.irradiance = Rgb<S>(S(-1));
    CHECK_THROWS_AS(validate(Light<S>(bad)), std::invalid_argument);
    // Only an infinite plane: no finite beam covers it, so no photon and no power; shadow rays
    // still light it, far from the origin too.
    DefaultScene<S> planes;
    const auto white = planes.add_material(Material<S>::lambertian(Rgb<S>(S(0.5))));
    planes.add(Plane<S>({0, 1, 0}, 0), white);
    planes.add_light(sun<S>({0, 10, 0}, {0, -1, 0}, S(2)));
    planes.commit();
    CHECK(is_black(light_power(planes.lights()[0])));
    CHECK(light_is_lit(planes.lights()[0]));
    CHECK(trace_global_photons(planes, PhotonTracingSettings{.photons = 1000}).photons.empty());
    CHECK(parallel_direct(planes, Vec3<S>(S(1e4), 0, S(-1e4))) == Approx(2.0).epsilon(1e-4));
    // A light added after commit gets its beam at once.
    DefaultScene<S> late;
    late.add(Box<S>({-1, -1, -1}, {1, 1, 1}), late.add_material(Material<S>::lambertian(Rgb<S>(S(0.5)))));
    late.commit();
    late.add_light(sun<S>({0, 10, 0}, {0, -1, 0}, S(2)));
    CHECK(double(std::get<ParallelLight<S>>(late.lights()[0]).beam_radius) == Approx(std::sqrt(3.0)).epsilon(1e-5));
}
