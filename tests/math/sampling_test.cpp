// SPDX-License-Identifier: MIT
// Samplers are uniform in the measure they claim: chi-square tests over equal-probability cells,
// with fixed seeds so that a failure reproduces.

#include <catch2/catch.hpp>

#include <photon/light/light.hpp>
#include <photon/math/rng.hpp>
#include <photon/math/sampling.hpp>

#include <cmath>
#include <functional>
#include <vector>

using namespace photon;

namespace {

/// Chi-square critical value for `dof` degrees of freedom at significance 1e-4
/// (Wilson-Hilferty approximation, z = 3.719).
double chi2_critical(int dof) {
    const double k = dof, z = 3.719;
    const double t = 1.0 - 2.0 / (9.0 * k) + z * std::sqrt(2.0 / (9.0 * k));
    return k * t * t * t;
}

/// Draws `n` samples, maps each to a cell in [0, cells) and returns the chi-square statistic
/// against equal expected counts.
double chi2(int cells, int n, const std::function<int()>& draw_cell) {
    std::vector<int> count(cells, 0);
    for (int i = 0; i < n; ++i) {
        const int c = draw_cell();
        REQUIRE(c >= 0);
        REQUIRE(c < cells);
        ++count[c];
    }
    const double expected = double(n) / cells;
    double x2 = 0;
    for (int c : count) x2 += (c - expected) * (c - expected) / expected;
    return x2;
}

constexpr int z_bins = 16, phi_bins = 32, cells = z_bins * phi_bins, samples = 400'000;

/// Equal-area cell of a unit direction on the sphere (Archimedes: uniform z is uniform area).
int sphere_cell(const Vec3<double>& d) {
    const int zi = std::min(z_bins - 1, int((d.z + 1) * 0.5 * z_bins));
    double phi = std::atan2(d.y, d.x);
    if (phi < 0) phi += 2 * pi<double>;
    const int pi_ = std::min(phi_bins - 1, int(phi / (2 * pi<double>) * phi_bins));
    return zi * phi_bins + pi_;
}

}  // namespace

TEST_CASE("both emission samplers are uniform over the sphere", "[sampling]") {
    Pcg32 rng(7, 1);
    const double direct = chi2(cells, samples, [&] { return sphere_cell(uniform_sphere(rng.uniform2<double>())); });
    const double rejection = chi2(cells, samples, [&] { return sphere_cell(rejection_sphere<double>(rng)); });
    CHECK(direct < chi2_critical(cells - 1));
    CHECK(rejection < chi2_critical(cells - 1));
    // The test can fail: normalising points of the cube without rejecting the corners is not
    // uniform, and the statistic sees it.
    const double biased = chi2(cells, samples, [&] {
        const Vec3<double> p{2 * rng.uniform<double>() - 1, 2 * rng.uniform<double>() - 1, 2 * rng.uniform<double>() - 1};
        return sphere_cell(glm::normalize(p));
    });
    CHECK(biased > chi2_critical(cells - 1));
}

TEST_CASE("light cones: both samplers are uniform within the cone and never outside", "[sampling]") {
    const Light<double> light = PointLight<double>{{0, 0, 0}, {1, 1, 1}, Cone<double>({1, 1, 0}, 40)};
    const Cone<double>& cone = *light_cone(light);
    const Frame<double> frame = Frame<double>::from_normal(cone.axis());
    for (const auto sampler : {EmissionSampler::direct, EmissionSampler::rejection}) {
        Pcg32 rng(11, int(sampler));
        const double x2 = chi2(cells, samples, [&] {
            const Vec3<double> d = sample_emission_direction(light, sampler, rng);
            REQUIRE(cone.contains(d));
            const Vec3<double> l = frame.to_local(d);
            // cos(theta) is uniform in [cos_max, 1] within a cone.
            const double u = (l.z - cone.cos_half_angle()) / (1 - cone.cos_half_angle());
            double phi = std::atan2(l.y, l.x);
            if (phi < 0) phi += 2 * pi<double>;
            return std::min(z_bins - 1, int(u * z_bins)) * phi_bins + std::min(phi_bins - 1, int(phi / (2 * pi<double>) * phi_bins));
        });
        CHECK(x2 < chi2_critical(cells - 1));
    }
}

TEST_CASE("cosine hemisphere sampling follows cos(theta) / pi", "[sampling]") {
    Pcg32 rng(3, 3);
    // P(theta < t) = sin^2 t, so sin^2(theta) = 1 - z^2 is uniform.
    const double x2 = chi2(cells, samples, [&] {
        const Vec3<double> d = cosine_hemisphere(rng.uniform2<double>());
        REQUIRE(d.z >= 0);
        double phi = std::atan2(d.y, d.x);
        if (phi < 0) phi += 2 * pi<double>;
        return std::min(z_bins - 1, int((1 - d.z * d.z) * z_bins)) * phi_bins +
               std::min(phi_bins - 1, int(phi / (2 * pi<double>) * phi_bins));
    });
    CHECK(x2 < chi2_critical(cells - 1));
}

TEST_CASE("sphere light photons leave uniformly over the silhouette disc", "[sampling]") {
    const Light<double> light = SphereLight<double>{{1, 2, 3}, 0.5, {1, 1, 1}};
    Pcg32 rng(5, 5);
    const Vec3<double> dir = glm::normalize(Vec3<double>{0.3, -0.2, 0.9});
    const Frame<double> frame = Frame<double>::from_normal(dir);
    const double x2 = chi2(cells, samples, [&] {
        const Vec3<double> o = sample_emission_origin(light, dir, rng.uniform2<double>()) - Vec3<double>{1, 2, 3};
        REQUIRE(glm::length(o) == Approx(0.5));
        REQUIRE(glm::dot(o, dir) >= -1e-12);  // on the side facing the direction
        const Vec3<double> l = frame.to_local(o) / 0.5;
        double phi = std::atan2(l.y, l.x);
        if (phi < 0) phi += 2 * pi<double>;
        const double r2 = l.x * l.x + l.y * l.y;  // uniform in a disc
        return std::min(z_bins - 1, int(r2 * z_bins)) * phi_bins + std::min(phi_bins - 1, int(phi / (2 * pi<double>) * phi_bins));
    });
    CHECK(x2 < chi2_critical(cells - 1));
}

TEST_CASE("sphere light seen from a point: irradiance matches the point light of equal power", "[sampling]") {
    // A Lambertian sphere radiates like a point source of the same intensity: E = I / d^2 on a
    // surface facing it, whatever the radius, as long as it is fully above the horizon.
    const Rgb<double> power(4 * pi<double> * 2.5);
    const Light<double> sphere = SphereLight<double>{{0, 0, 0}, 0.3, power};
    const Vec3<double> x{0, 0, -1.7};
    Rgb<double> sum(0);
    const unsigned n = 64;
    Pcg32 rng(1, 2);
    for (unsigned i = 0; i < n * n; ++i) {
        const auto s = sample_incident(sphere, x, stratified(i, n, rng.uniform2<double>()));
        REQUIRE(s);
        CHECK(s->distance == Approx(glm::length(s->direction * s->distance)));
        sum += s->irradiance * glm::dot(s->direction, Vec3<double>{0, 0, 1});
    }
    CHECK((sum / double(n * n)).x == Approx(2.5 / (1.7 * 1.7)).epsilon(1e-3));
    CHECK_FALSE(sample_incident(sphere, Vec3<double>{0, 0.1, 0}, {0.5, 0.5}));  // inside the light
}

TEST_CASE("stratified samples put one sample in each cell", "[sampling]") {
    Pcg32 rng(9, 9);
    const unsigned n = 7;
    std::vector<int> seen(n * n, 0);
    for (unsigned i = 0; i < n * n; ++i) {
        const Vec2<float> u = stratified(i, n, rng.uniform2<float>());
        REQUIRE(u.x < 1.0f);
        REQUIRE(u.y < 1.0f);
        ++seen[unsigned(u.y * n) * n + unsigned(u.x * n)];
    }
    for (int c : seen) CHECK(c == 1);
}
