// SPDX-License-Identifier: MIT
// The path-traced reference as a judge: multiple importance sampling of sphere lights is
// unbiased and less noisy than shadow rays alone, cone lights emit only inside their cone in
// both strategies, caustic paths keep their weight, per-pixel sums do not drift in float, and
// the render says what the reference cannot see.

#include <catch2/catch.hpp>

#include <photon/photon.hpp>

#include <algorithm>
#include <cmath>
#include <vector>

using namespace photon;

namespace {

constexpr double rho = 0.5;

/// A Lambertian floor y = 0 of albedo `albedo` under a sphere light of radius 1 whose centre
/// is 1.02 above it: from the floor the light fills most of the sky (a 79 degree cone), where
/// shadow rays uniform in the cone are noisy and cosine-distributed continuations are not. The
/// camera looks straight down from inside the light (lights are not objects: camera rays pass
/// through them).
struct BigLight {
    static constexpr double radius = 1.0, height = 1.02, power = 10.0;
    double albedo;
    DefaultScene<double> scene;
    PinholeCamera<double> camera = PinholeCamera<double>::look_at({0, 0.5, 0}, {0, 0, 0}, {0, 0, 1}, 60, 1.0);
    explicit BigLight(double albedo_, std::optional<Cone<double>> cone = {}) : albedo(albedo_) {
        scene.add(Plane<double>({0, 1, 0}, 0), scene.add_material(Material<double>::lambertian(Rgb<double>(albedo))));
        scene.add_light(SphereLight<double>{{0, height, 0}, radius, Rgb<double>(power), cone});
        scene.commit();
    }
    /// The floor point a pixel centre sees.
    [[nodiscard]] Vec3<double> floor_point(unsigned x, unsigned y, unsigned size) const {
        const Ray<double> r = *camera.ray((x + 0.5) / size, (y + 0.5) / size);
        return r.origin - r.direction * (r.origin.y / r.direction.y);
    }
};

RenderSettings reference_settings(unsigned size, unsigned spp, bool mis, std::uint64_t seed = 1) {
    RenderSettings s;
    s.mode = RenderMode::reference;
    s.width = s.height = size;
    s.samples_per_pixel = spp;
    s.reference_mis = mis;
    s.seed = seed;
    s.threads = 2;
    return s;
}

/// Mean over the pixels of film / expected, and the root mean square of film / expected - 1
/// (the noise: the expected image is smooth at the pixel scale).
template <class Expected> std::pair<double, double> relative_error(const Film& film, Expected expected) {
    double sum = 0, sq = 0;
    for (unsigned y = 0; y < film.height(); ++y)
        for (unsigned x = 0; x < film.width(); ++x) {
            const double e = film.at(x, y).x / expected(x, y) - 1.0;
            sum += e;
            sq += e * e;
        }
    const double n = double(film.pixels().size());
    return {1.0 + sum / n, std::sqrt(sq / n)};
}

}  // namespace

TEST_CASE("reference with MIS is unbiased and less noisy than shadow rays alone under a big sphere light", "[reference]") {
    // A Lambertian sphere of intensity I lights a point that sees all of it (here every floor
    // point: the sphere is above the floor) with irradiance I cos(theta) / d^2, as a point light
    // at its centre would: the cap of half-angle alpha (sin alpha = r / d) gives
    // L pi sin^2(alpha) cos(theta) with L = I / (pi r^2). Floor radiance: rho / pi of that.
    // A white floor: every path continues diffusely, so every continuation is a BSDF sample of
    // the light. (With albedo rho only the fraction rho survives Russian roulette, and the BSDF
    // strategy's density pd cos / pi shrinks with it: measured noise 0.042 -> 0.040 at rho 0.5.)
    const BigLight scene(1.0);
    const double intensity = BigLight::power / (4 * pi<double>);
    constexpr unsigned size = 16;
    auto expected = [&](unsigned x, unsigned y) {
        const Vec3<double> to_light = Vec3<double>{0, BigLight::height, 0} - scene.floor_point(x, y, size);
        const double d2 = glm::dot(to_light, to_light);
        return scene.albedo / pi<double> * intensity * (to_light.y / std::sqrt(d2)) / d2;
    };
    const Film mis = render(scene.scene, scene.camera, reference_settings(size, 64, true)).film;
    const Film light_only = render(scene.scene, scene.camera, reference_settings(size, 64, false)).film;
    const auto [mis_mean, mis_noise] = relative_error(mis, expected);
    const auto [lo_mean, lo_noise] = relative_error(light_only, expected);
    INFO("MIS: mean " << mis_mean << ", noise " << mis_noise << "; light sampling only: mean " << lo_mean << ", noise "
                      << lo_noise);
    // 16 x 16 x 64 samples: the mean's standard deviation is noise / 16, under 0.3%.
    CHECK(mis_mean == Approx(1.0).epsilon(0.01));
    CHECK(lo_mean == Approx(1.0).epsilon(0.01));
    CHECK(mis_mean == Approx(lo_mean).epsilon(0.01));
    // Measured: 0.027 against 0.042 per pixel (power heuristic; the balance heuristic: 0.024).
    CHECK(mis_noise < 0.8 * lo_noise);
}

TEST_CASE("reference: a cone light emits only inside its cone, in both strategies", "[reference]") {
    // The cone (40 degrees around straight down) lets out only the light travelling within 40
    // degrees of -y, i.e. arriving from within 40 degrees of the floor's normal. Every floor point
    // in view sees that whole cone of directions on the light (it lies inside the 65+ degree cap
    // the light subtends there, tilted by at most 22 degrees), so E = L pi sin^2(40 deg), the same
    // everywhere, with L = I / (pi r^2) and I = power / the cone's solid angle. Either strategy
    // ignoring the cone would give I cos(theta) / d^2 instead, 2.3 times as much below the light.
    const Cone<double> cone({0, -1, 0}, 40);
    const BigLight scene(rho, cone);
    const double intensity = BigLight::power / cone.solid_angle();
    const double s = std::sin(40 * pi<double> / 180);
    const double radiance = rho / pi<double> * intensity * s * s / (BigLight::radius * BigLight::radius);
    for (const bool mis : {true, false}) {
        const Film film = render(scene.scene, scene.camera, reference_settings(16, 256, mis)).film;
        const auto [mean, noise] = relative_error(film, [&](unsigned, unsigned) { return radiance; });
        INFO((mis ? "MIS" : "light sampling only") << ": mean " << mean << ", noise " << noise);
        CHECK(mean == Approx(1.0).epsilon(0.02));
    }
}

TEST_CASE("reference: a sphere light behind another still lights the floor, by both strategies", "[reference]") {
    // Lights are not objects: shadow rays pass through the near light to the far one, and so
    // must a continuation that meets both (all lights on the ray count, not the nearest).
    DefaultScene<double> scene;
    scene.add(Plane<double>({0, 1, 0}, 0), scene.add_material(Material<double>::lambertian(Rgb<double>(rho))));
    scene.add_light(SphereLight<double>{{0, 1.02, 0}, 1.0, Rgb<double>(10)});
    scene.add_light(SphereLight<double>{{0, 3.5, 0}, 1.0, Rgb<double>(10)});
    scene.commit();
    const auto camera = PinholeCamera<double>::look_at({0, 0.5, 0}, {0, 0, 0}, {0, 0, 1}, 10, 1.0);
    const double intensity = 10 / (4 * pi<double>);
    const double radiance = rho / pi<double> * intensity * (1 / (1.02 * 1.02) + 1 / (3.5 * 3.5));  // near the axis
    const double mis = render(scene, camera, reference_settings(8, 64, true)).film.mean().x;
    const double light_only = render(scene, camera, reference_settings(8, 64, false)).film.mean().x;
    CHECK(mis == Approx(radiance).epsilon(0.01));
    CHECK(light_only == Approx(radiance).epsilon(0.01));
}

TEST_CASE("reference: caustics through glass keep weight 1 under MIS", "[reference]") {
    // A glass ball (r 0.3, ior 1.5) whose focus is just above the floor, under a small sphere
    // light. The caustic (L S+ D E) is found only when a floor point's continuation refracts
    // through the ball into the light: the light sampling cannot make that path, so it keeps
    // weight 1 under MIS. The caustic spot lies in the ball's umbra, where MIS changes only
    // the secondary bounces: its mean must not change, and neither can its fireflies (measured:
    // the spot's peak / mean is 2.34 with MIS and without; no light-sampling weight can reach
    // these paths, only a bidirectional method could).
    DefaultScene<double> scene;
    scene.add(Plane<double>({0, 1, 0}, 0), scene.add_material(Material<double>::lambertian(Rgb<double>(0.75))));
    scene.add(Sphere<double>({0, 0.5, 0}, 0.3), scene.add_material(Material<double>::glass(1.5)));
    scene.add_light(SphereLight<double>{{0, 2, 0}, 0.1, Rgb<double>(10)});
    scene.commit();
    constexpr unsigned size = 32;
    const auto camera = PinholeCamera<double>::look_at({0, 0.18, -0.25}, {0, 0, 0}, {0, 1, 0}, 20, 1.0);
    const double unshadowed = 0.75 / pi<double> * (10 / (4 * pi<double>)) / (2.0 * 2.0);  // floor at the origin, no ball

    struct Spot { double mean = 0, peak = 0; };
    auto spot = [&](const Film& film) {
        Spot s;
        unsigned n = 0;
        for (unsigned y = 0; y < size; ++y)
            for (unsigned x = 0; x < size; ++x) {
                const Ray<double> r = *camera.ray((x + 0.5) / size, (y + 0.5) / size);
                const Vec3<double> p = r.origin - r.direction * (r.origin.y / r.direction.y);
                if (p.x * p.x + p.z * p.z > 0.04 * 0.04) continue;
                s.mean += film.at(x, y).x;
                s.peak = std::max(s.peak, double(film.at(x, y).x));
                ++n;
            }
        REQUIRE(n >= 20);
        s.mean /= n;
        return s;
    };
    const Spot mis1 = spot(render(scene, camera, reference_settings(size, 256, true, 1)).film);
    const Spot mis2 = spot(render(scene, camera, reference_settings(size, 256, true, 2)).film);
    const Spot old1 = spot(render(scene, camera, reference_settings(size, 256, false, 1)).film);
    INFO("caustic spot: MIS seeds 1, 2: mean " << mis1.mean << ", " << mis2.mean << " (peak / mean " << mis1.peak / mis1.mean
                                               << "); light sampling only: mean " << old1.mean << " (peak / mean "
                                               << old1.peak / old1.mean << "); unshadowed floor " << unshadowed);
    CHECK(mis1.mean > 3 * unshadowed);  // the reference finds the caustic: the ball focuses light
    // Between seeds (noise) and between estimators (same seed: the same caustic paths).
    CHECK(mis2.mean == Approx(mis1.mean).epsilon(0.15));
    CHECK(old1.mean == Approx(mis1.mean).epsilon(0.02));
}

TEST_CASE("render_image sums samples in double: a million samples of a pixel do not drift", "[reference]") {
    // A closed diffuse sphere lit by a point light at its centre: direct radiance is the same
    // rho Phi / (4 pi^2 R^2) = 0.1126 everywhere, so rt's samples are all equal (to float
    // rounding). Summed in float, 10^6 of them drift by about 1% (the sum's ulp reaches 0.06).
    constexpr double R = 1.5, Phi = 20.0;
    DefaultScene<float> scene;
    scene.add(Sphere<float>({0, 0, 0}, float(R)), scene.add_material(Material<float>::lambertian(Rgb<float>(float(rho)))));
    scene.add_light(PointLight<float>{{0, 0, 0}, Rgb<float>(float(Phi))});
    scene.commit();
    const auto camera = PinholeCamera<float>::look_at({0, 0.2f, -0.3f}, {0.3f, 0.4f, 1}, {0, 1, 0}, 10, 1.0f);
    const double expected = rho * Phi / (4 * pi<double> * pi<double> * R * R);
    RenderSettings s;
    s.mode = RenderMode::rt;
    s.width = s.height = 1;
    s.threads = 1;
    s.samples_per_pixel = 1;
    const double one = render(scene, camera, s).film.at(0, 0).x;
    s.samples_per_pixel = 1'000'000;
    const double many = render(scene, camera, s).film.at(0, 0).x;
    CHECK(one == Approx(expected).epsilon(1e-5));
    CHECK(many == Approx(expected).epsilon(1e-5));
}

TEST_CASE("reference warns when a point light shines on mirrors or glass", "[reference]") {
    auto scene_with = [](const Light<float>& light, bool glass) {
        DefaultScene<float> scene;
        scene.add(Plane<float>({0, 1, 0}, 0), scene.add_material(Material<float>::lambertian(Rgb<float>(0.5f))));
        if (glass) scene.add(Sphere<float>({0, 0.5f, 0}, 0.3f), scene.add_material(Material<float>::glass(1.5f)));
        scene.add_light(light);
        scene.commit();
        return scene;
    };
    const auto camera = PinholeCamera<float>::look_at({0, 1, -2}, {0, 0, 0}, {0, 1, 0}, 40, 1.0f);
    RenderSettings s = reference_settings(4, 1, true);
    const PointLight<float> point{{0, 2, 0}, Rgb<float>(10)};
    const SphereLight<float> sphere{{0, 2, 0}, 0.1f, Rgb<float>(10)};
    const RenderStats blind = render(scene_with(point, true), camera, s).stats;
    REQUIRE(blind.warnings.size() == 1);
    CHECK_THAT(blind.warnings[0].message, Catch::Contains("point and area lights through mirrors or glass"));
    // An area light is a set of points: blind there too.
    const AreaLight<float> area{.center = {0, 2, 0}, .axis1 = {0.2f, 0, 0}, .axis2 = {0, 0, 0.2f}, .size1 = 3, .size2 = 3,
                                .power = Rgb<float>(10)};
    CHECK(render(scene_with(area, true), camera, s).stats.warnings.size() == 1);
    CHECK(render(scene_with(sphere, true), camera, s).stats.warnings.empty());
    CHECK(render(scene_with(point, false), camera, s).stats.warnings.empty());
    s.mode = RenderMode::rt;
    CHECK(render(scene_with(point, true), camera, s).stats.warnings.empty());
}
