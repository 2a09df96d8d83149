// SPDX-License-Identifier: MIT
// Energy bookkeeping of photon tracing: Russian roulette with per-channel power scaling keeps
// the expected stored power equal to the analytic sum over bounces.

#include <catch2/catch.hpp>

#include <photon/scene/scene.hpp>
#include <photon/tracing/photon_tracer.hpp>

using namespace photon;

namespace {

/// Photons from a point light at the centre of a closed sphere of `material`: every emitted
/// photon hits the wall, is stored there, and survives each bounce with probability rho_avg.
/// With reflectance rho (diffuse + specular) the stored power per channel sums to
/// Phi * (1 + rho + rho^2 + ...) = Phi / (1 - rho).
Rgb<double> stored_power(const Material<double>& material, std::size_t photons, unsigned max_depth,
                         EmissionSampler sampler) {
    DefaultScene<double> scene;
    scene.add(Sphere<double>({0, 0, 0}, 1.0), scene.add_material(material));
    scene.add_light(PointLight<double>{{0.1, -0.2, 0.05}, Rgb<double>(1.0)});
    scene.commit();
    const PhotonTracingSettings settings{.photons = photons, .max_depth = max_depth, .sampler = sampler, .seed = 3};
    const TracedPhotons traced = trace_global_photons(scene, settings);
    Rgb<double> sum(0.0);
    for (const Photon& p : traced.photons) sum += Rgb<double>(p.packed.power());
    return sum;
}

}  // namespace

TEST_CASE("Russian roulette: stored power per channel equals Phi / (1 - rho)", "[transport]") {
    const Rgb<double> rho{0.8, 0.5, 0.2};  // rho_avg = 0.5, so red photons gain power, blue lose it
    const Rgb<double> sum = stored_power(Material<double>::lambertian(rho), 1'000'000, 10'000, EmissionSampler::direct);
    for (int c = 0; c < 3; ++c) {
        INFO("channel " << c);
        CHECK(sum[c] == Approx(1.0 / (1.0 - rho[c])).epsilon(0.01));
    }
}

TEST_CASE("Russian roulette: diffuse + mirror reflectances add up, with the rejection sampler", "[transport]") {
    const Material<double> m({.diffuse = {0.3, 0.4, 0.1}, .specular = {0.4, 0.2, 0.1}});
    const Rgb<double> sum = stored_power(m, 1'000'000, 10'000, EmissionSampler::rejection);
    for (int c = 0; c < 3; ++c) {
        const double rho = m.params().diffuse[c] + m.params().specular[c];
        INFO("channel " << c);
        CHECK(sum[c] == Approx(1.0 / (1.0 - rho)).epsilon(0.01));
    }
}

TEST_CASE("the maximum photon depth truncates the series where it should", "[transport]") {
    // Depth 3 stores at the first three hits only: Phi (1 + rho + rho^2).
    const Rgb<double> sum = stored_power(Material<double>::lambertian(Rgb<double>(0.5)), 400'000, 3, EmissionSampler::direct);
    CHECK(sum.x == Approx(1.75).epsilon(0.01));
}

TEST_CASE("a closed box of albedo 1 ends at the maximum depth and conserves power", "[transport]") {
    // No absorption: every photon survives every bounce and is stored max_depth times with its
    // full power. Tracing must still end. The only error left is the photon record's power
    // encoding (12-bit mantissas, relative error <= 2^-13).
    const Rgb<double> sum = stored_power(Material<double>::lambertian(Rgb<double>(1.0)), 20'000, 25, EmissionSampler::direct);
    CHECK(sum.x == Approx(25.0).epsilon(2e-4));
}

TEST_CASE("photons split among lights by power", "[transport]") {
    const std::vector<Light<float>> lights{PointLight<float>{{0, 0, 0}, Rgb<float>(1)},
                                           SphereLight<float>{{1, 0, 0}, 0.1f, Rgb<float>(3)},
                                           PointLight<float>{{2, 0, 0}, Rgb<float>(0)}};
    const auto counts = photons_per_light<float>(lights, 1001);
    CHECK(counts[0] + counts[1] + counts[2] == 1001);
    CHECK(counts[0] == 250);
    CHECK(counts[1] == 751);
    CHECK(counts[2] == 0);
}
