// SPDX-License-Identifier: MIT
// Light transport against closed-form answers.

#include <catch2/catch.hpp>

#include <photon/photon.hpp>

#include <algorithm>
#include <vector>

#include "transport/furnace_sphere.hpp"

using namespace photon;

TEST_CASE("photon map irradiance on a Lambertian plane under a point light is I cos(theta) / d^2", "[transport]") {
    // A point light 1 m above the plane y = 0, limited to a 60 degree cone pointing down so that
    // every photon lands where we measure. Intensity I = power / cone solid angle.
    DefaultScene<double> scene;
    scene.add(Plane<double>({0, 1, 0}, 0), scene.add_material(Material<double>::lambertian(Rgb<double>(0.5))));
    const Cone<double> cone({0, -1, 0}, 60);
    const double power = 10.0, intensity = power / cone.solid_angle();
    scene.add_light(PointLight<double>{{0, 1, 0}, Rgb<double>(power), cone});
    scene.commit();
    const PhotonTracingSettings settings{.photons = 4'000'000, .store = {.direct = true, .caustic = false, .indirect = false}, .seed = 11};
    const TracedPhotons traced = trace_global_photons(scene, settings);
    const PhotonMap map(traced.photons);
    // k = 20000 photons give a relative standard deviation of 0.7%; the disc (r ~ 0.07 m) blurs
    // the cos^3 falloff by under 0.4%.
    const EstimateSettings estimate{.k = 20'000, .max_radius = 0.5f};
    EstimateScratch scratch;
    for (const double x : {0.0, 0.3, 0.6, 0.8, 1.0}) {
        const Vec3<double> p{x, 0, 0.1 * x};
        const double d2 = glm::dot(p - Vec3<double>{0, 1, 0}, p - Vec3<double>{0, 1, 0});
        const double expected = intensity * (1.0 / std::sqrt(d2)) / d2;  // cos = 1 / d
        const Rgb<double> e = estimate_irradiance(map, p, Vec3<double>{0, 1, 0}, estimate, scratch);
        INFO("at x = " << x << ": " << e.x << " vs " << expected);
        CHECK(e.x == Approx(expected).epsilon(0.02));
        CHECK(e.y == e.x);
    }
}

namespace {

using photon::testing::FurnaceSphere;

/// Mean of the red channel, and the fraction of pixels within `tolerance` of `expected`.
std::pair<double, double> mean_and_within(const Film& film, double expected, double tolerance) {
    double sum = 0;
    std::size_t within = 0;
    for (const auto& p : film.pixels()) {
        sum += p.x;
        within += std::abs(p.x / expected - 1.0) <= tolerance ? 1 : 0;
    }
    return {sum / double(film.pixels().size()), double(within) / double(film.pixels().size())};
}

RenderSettings furnace_settings(RenderMode mode) {
    RenderSettings s;
    s.mode = mode;
    s.width = s.height = 32;
    s.samples_per_pixel = 1;
    s.global_photons = 400'000;
    s.max_photon_depth = 200;  // rho^200: the series is complete
    s.global_estimate = {.k = 400, .max_radius = 1.0f};
    return s;
}

}  // namespace

TEST_CASE("closed diffuse sphere: ray tracing gives the exact direct radiance", "[transport]") {
    const FurnaceSphere f;
    const RenderResult r = render(f.scene, f.camera, furnace_settings(RenderMode::rt));
    for (const auto& p : r.film.pixels()) CHECK(p.x == Approx(FurnaceSphere::direct()).epsilon(1e-4));
}

TEST_CASE("closed diffuse sphere: photon mapping gives rho Phi / (4 pi^2 R^2 (1 - rho))", "[transport]") {
    const FurnaceSphere f;
    const double expected = FurnaceSphere::radiance();
    SECTION("pm-direct: all light from the global map") {
        const RenderResult r = render(f.scene, f.camera, furnace_settings(RenderMode::pm_direct));
        // k = 400: one standard deviation is 5%; 3 of them hold 99.7% of the pixels.
        const auto [mean, within] = mean_and_within(r.film, expected, 0.15);
        CHECK(mean == Approx(expected).epsilon(0.02));
        CHECK(within > 0.99);
    }
    SECTION("pm: shadow rays + global map") {
        RenderSettings s = furnace_settings(RenderMode::pm);
        s.final_gather_rays = 0;
        const RenderResult r = render(f.scene, f.camera, s);
        // Half of the light is exact (direct), the other half has the map's 5% noise.
        const auto [mean, within] = mean_and_within(r.film, expected, 0.075);
        CHECK(mean == Approx(expected).epsilon(0.02));
        CHECK(within > 0.99);
    }
    SECTION("pm with final gathering over precomputed irradiance") {
        const RenderResult r = render(f.scene, f.camera, furnace_settings(RenderMode::pm));
        const auto [mean, within] = mean_and_within(r.film, expected, 0.05);
        CHECK(mean == Approx(expected).epsilon(0.02));
        CHECK(within > 0.99);
    }
}

TEST_CASE("closed diffuse sphere: the path-traced reference converges to the same answer", "[transport]") {
    const FurnaceSphere f;
    RenderSettings s = furnace_settings(RenderMode::reference);
    s.width = s.height = 16;
    s.samples_per_pixel = 256;
    const RenderResult r = render(f.scene, f.camera, s);
    CHECK(r.film.mean().x == Approx(FurnaceSphere::radiance()).epsilon(0.02));
    CHECK(r.stats.global.emitted == 0);
}
