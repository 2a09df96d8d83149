// SPDX-License-Identifier: MIT
// The sky as a light (light/environment.hpp): its sampling density against its directions, the
// photons' power against the flux a sphere intercepts, what camera rays that leave the scene
// see, a diffuse floor under a uniform sky reflecting rho L in the global-illumination modes, the modes against one
// another on a lit ball, and no NaN at tiny or huge scales or under a black sky.

#include <catch2/catch.hpp>

#include <photon/photon.hpp>

#include "film_compare.hpp"

#include <cmath>
#include <vector>

using namespace photon;

namespace {

/// POV-Ray's sky idiom `gradient y color_map { [0 c0] [1 c1] } scale 2 translate -1`: c0 at the
/// nadir, c1 at the zenith, linear in y between, so its mean over the sphere is (c0 + c1) / 2
/// (y is uniform over the sphere, Archimedes).
template <Scalar S> Environment<S> sky_gradient(const Rgb<S>& c0, const Rgb<S>& c1, unsigned rows = 64) {
    Pattern pattern = Pattern::of(PatternKind::gradient);
    pattern.gradient = {0, 1, 0};
    const auto placement = Affine<double>::scale({2, 2, 2}).then(Affine<double>::translate({-1, -1, -1}));
    return Environment<S>(AnyReflectanceField<S>(Pigment<S>(pattern, ColorMap<S>({{0.0, c0}, {1.0, c1}}), placement)), rows);
}

/// A bright spot near the horizon on a dim sky: what importance sampling is for.
template <Scalar S> Environment<S> sky_spot() {
    struct Spot {
        [[nodiscard]] Rgb<S> operator()(const Vec3<S>& d) const noexcept {
            const S c = glm::dot(d, glm::normalize(Vec3<S>(S(1), S(0.3), S(0.2))));
            return c > S(0.98) ? Rgb<S>(S(40), S(30), S(20)) : Rgb<S>(S(0.1), S(0.2), S(0.4));
        }
        [[nodiscard]] Rgb<S> upper_bound() const noexcept { return Rgb<S>(S(40)); }
    };
    return Environment<S>(AnyReflectanceField<S>(Spot{}), 64);
}

/// A floor plane (albedo rho) under `sky`, seen from above.
template <Scalar S> struct SkyFloor {
    DefaultScene<S> scene;
    PinholeCamera<S> camera;
    SkyFloor(const Environment<S>& sky, S scale, S rho)
        : camera(PinholeCamera<S>::look_at(Vec3<S>(0, 2, -2) * scale, Vec3<S>(0, 0, 0), {0, 1, 0}, 40, S(4.0 / 3.0))) {
        scene.add(Plane<S>({0, 1, 0}, 0), scene.add_material(Material<S>::lambertian(Rgb<S>(rho))));
        scene.set_environment(sky);
        scene.commit();
    }
};

RenderSettings sky_settings(RenderMode mode) {
    RenderSettings s;
    s.mode = mode;
    s.width = 16;
    s.height = 12;
    s.threads = 2;
    s.samples_per_pixel = 1;
    s.global_photons = 20'000;
    s.caustic_photons = 0;
    s.final_gather_rays = 16;
    s.sppm_passes = 4;
    s.sppm_photons_per_pass = 20'000;
    return s;
}

}  // namespace

TEMPLATE_TEST_CASE("a sky's sampling density integrates to 1 and matches the directions it draws", "[environment]",
                   float, double) {
    using S = TestType;
    const Environment<S> skies[] = {Environment<S>(Rgb<S>(S(0.5))), sky_gradient<S>(Rgb<S>(S(0.1)), Rgb<S>(S(2), S(1), S(0.5))),
                                    sky_spot<S>()};
    for (const Environment<S>& sky : skies) {
        Pcg32 rng(3, 1);
        // Integral of pdf over the sphere by uniform directions: 4 pi mean(pdf) = 1.
        double mean_pdf = 0;
        constexpr int n = 200'000;
        for (int i = 0; i < n; ++i) mean_pdf += double(sky.pdf(uniform_sphere(rng.uniform2<S>())));
        CHECK(4 * pi<double> * mean_pdf / n == Approx(1.0).epsilon(0.01));
        // E[L / pdf] over sample() is the integral (unbiased), and sample() reports pdf().
        // (A direction drawn on a cell's edge may round into its neighbour: rare.)
        Rgb<double> integral(0.0);
        int other_cell = 0;
        for (int i = 0; i < n; ++i) {
            const EnvironmentSample<S> s = sky.sample(rng.uniform2<S>());
            REQUIRE(double(glm::length(s.direction)) == Approx(1.0).epsilon(1e-5));
            if (!(double(s.pdf) == Approx(double(sky.pdf(s.direction))).epsilon(1e-4))) ++other_cell;
            integral += Rgb<double>(s.radiance) / (double(s.pdf) * n);
        }
        CHECK(other_cell <= n / 10'000);
        for (int c = 0; c < 3; ++c) CHECK(integral[c] == Approx(double(sky.integral()[c])).epsilon(0.02));
    }
    // The gradient's integral is known: 4 pi (c0 + c1) / 2.
    const Environment<S> g = sky_gradient<S>(Rgb<S>(S(0.1)), Rgb<S>(S(2), S(1), S(0.5)));
    CHECK(double(g.integral().x) == Approx(4 * pi<double> * 1.05).epsilon(1e-3));
    CHECK(double(g.integral().z) == Approx(4 * pi<double> * 0.3).epsilon(1e-3));
    CHECK_THROWS_AS(Environment<S>(Rgb<S>(S(-1))), std::invalid_argument);
    CHECK_THROWS_AS(Environment<S>(AnyReflectanceField<S>{}), std::invalid_argument);
}

TEMPLATE_TEST_CASE("sky photons bring a ball the flux it intercepts: pi r^2 times the sky's integral", "[environment][transport]",
                   float, double) {
    using S = TestType;
    // A ball (alone, so the environment ball is its own) intercepts pi r^2 L(w) from every
    // direction w: pi r^2 times the integral, the exact value for the gradient.
    const S r = S(0.7);
    for (const bool spot : {false, true}) {
        DefaultScene<S> scene;
        scene.add(Sphere<S>({S(1), S(2), S(3)}, r), scene.add_material(Material<S>::lambertian(Rgb<S>(S(0.5)))));
        scene.set_environment(spot ? sky_spot<S>() : sky_gradient<S>(Rgb<S>(S(0.1)), Rgb<S>(S(2), S(1), S(0.5))));
        scene.commit();
        const TracedPhotons traced = trace_global_photons(
            scene, {.photons = 200'000, .max_depth = 1, .store = {.direct = true, .caustic = false, .indirect = false}, .seed = 9});
        Rgb<double> arrived(0.0);
        for (const Photon& p : traced.photons) arrived += Rgb<double>(p.packed.power());
        const Rgb<double> integral = spot ? Rgb<double>(scene.environment()->integral())
                                          : 4 * pi<double> * Rgb<double>(1.05, 0.55, 0.3);
        for (int c = 0; c < 3; ++c) {
            INFO("spot " << spot << ", channel " << c);
            // Photons that miss the ball (its environment ball is the box's, wider) carry power too.
            CHECK(arrived[c] == Approx(pi<double> * double(r * r) * integral[c]).epsilon(spot ? 0.03 : 0.01));
        }
    }
}

TEMPLATE_TEST_CASE("camera rays that leave the scene see the background and the sky_sphere exactly, in every mode",
                   "[environment][render]", float, double) {
    using S = TestType;
    DefaultScene<S> scene;
    scene.add(Sphere<S>({S(0), S(0), S(5)}, S(0.1)), scene.add_material(Material<S>::lambertian(Rgb<S>(S(0.5)))));
    const Environment<S> gradient = sky_gradient<S>(Rgb<S>(S(0.1)), Rgb<S>(S(2), S(1), S(0.5)));
    scene.set_environment(gradient);
    scene.commit();
    RenderSettings settings;
    const PhotonMaps no_maps;
    ShadingContext ctx;
    for (const Vec3<S> d : {Vec3<S>(0, 1, 0), Vec3<S>(0, -1, 0), glm::normalize(Vec3<S>(1, S(0.3), -1)), Vec3<S>(1, 0, 0)}) {
        const Ray<S> ray{{S(0), S(0), S(0)}, d * S(3)};  // any length
        const double y = double(d.y), t = (y + 1) / 2;  // the pigment's value
        const Rgb<double> expected = (1 - t) * Rgb<double>(0.1) + t * Rgb<double>(2, 1, 0.5);
        settings.mode = RenderMode::rt;
        const Rgb<S> rt = RadianceIntegrator<DefaultScene<S>>(scene, no_maps, settings).radiance(ray, 1, ctx);
        const Rgb<S> reference = PathTracer<DefaultScene<S>>(scene, settings).radiance(ray, ctx);
        const Rgb<S> sppm = trace_camera_path(scene, ray, settings, ctx).direct;
        for (int c = 0; c < 3; ++c) {
            CHECK(double(rt[c]) == Approx(expected[c]).epsilon(1e-5));
            CHECK(double(reference[c]) == Approx(expected[c]).epsilon(1e-5));
            CHECK(double(sppm[c]) == Approx(expected[c]).epsilon(1e-5));
        }
    }
    // A constant background: exactly its colour.
    scene.set_environment(Environment<S>(Rgb<S>(S(0.25), S(0.5), S(0.75))));
    settings.mode = RenderMode::rt;
    const Rgb<S> bg = RadianceIntegrator<DefaultScene<S>>(scene, no_maps, settings).radiance(Ray<S>{{0, 0, 0}, {0, 1, 0}}, 1, ctx);
    CHECK(bg == Rgb<S>(S(0.25), S(0.5), S(0.75)));
}

TEMPLATE_TEST_CASE("a diffuse floor under a uniform sky reflects rho L in the global-illumination modes, at any scale",
                   "[environment][render]", float, double) {
    using S = TestType;
    const Rgb<S> sky(S(1), S(0.5), S(0.25));
    const S rho = S(0.6);
    for (const S scale : {S(1e-3), S(1), S(1e4)}) {
        const SkyFloor<S> floor(Environment<S>(sky), scale, rho);
        for (const RenderMode mode : {RenderMode::rt, RenderMode::pm, RenderMode::sppm, RenderMode::reference}) {
            RenderSettings settings = sky_settings(mode);
            if (mode == RenderMode::reference) settings.samples_per_pixel = 64;
            const Film film = render(floor.scene, floor.camera, settings).film;
            // Cosine-sampled shadow rays under a uniform sky bring exactly rho L each: pm and sppm
            // are exact (the floor bounces no light back to itself); the path tracer is unbiased,
            // within its noise. rt, as POV-Ray's ray tracing, lets the sky light nothing (a finish's
            // ambient stands in for it): the floor, without ambient, is black.
            const double tolerance = mode == RenderMode::reference ? 0.03 : 1e-4;
            const Rgb<double> expected = mode == RenderMode::rt ? Rgb<double>(0.0) : Rgb<double>(rho * sky);
            Rgb<double> mean(0.0);
            for (const Rgb<float>& p : film.pixels()) {
                REQUIRE(is_finite(p));
                mean += Rgb<double>(p) / double(film.pixels().size());
                if (mode != RenderMode::reference)
                    for (int c = 0; c < 3; ++c) REQUIRE(double(p[c]) == Approx(expected[c]).epsilon(tolerance));
            }
            INFO("scale " << scale << ", mode " << int(mode));
            for (int c = 0; c < 3; ++c) CHECK(mean[c] == Approx(expected[c]).epsilon(tolerance));
        }
    }
}

TEMPLATE_TEST_CASE("a black sky adds nothing and a sky at tiny and huge scales makes no NaN", "[environment][render]", float,
                   double) {
    using S = TestType;
    for (const S scale : {S(1e-3), S(1e4)}) {
        for (const bool black : {true, false}) {
            DefaultScene<S> scene;
            scene.add(Box<S>(Vec3<S>(-1, -0.1, -1) * scale, Vec3<S>(1, 0, 1) * scale),
                      scene.add_material(Material<S>::lambertian(Rgb<S>(S(0.5)))));
            scene.add(Sphere<S>(Vec3<S>(0, 0.3, 0) * scale, S(0.3) * scale),
                      scene.add_material(Material<S>::lambertian(Rgb<S>(S(0.8), S(0.3), S(0.2)))));
            scene.set_environment(black ? Environment<S>(Rgb<S>(S(0))) : sky_spot<S>());
            scene.commit();
            const auto camera = PinholeCamera<S>::look_at(Vec3<S>(0, 1.5, -2.5) * scale, Vec3<S>(0, 0.2, 0) * scale, {0, 1, 0}, 45,
                                                          S(4.0 / 3.0));
            for (const RenderMode mode : {RenderMode::rt, RenderMode::pm, RenderMode::sppm, RenderMode::reference}) {
                const Film film = render(scene, camera, sky_settings(mode)).film;
                double sum = 0;
                for (const Rgb<float>& p : film.pixels()) {
                    REQUIRE(is_finite(p));
                    sum += double(average(p));
                }
                INFO("scale " << scale << ", mode " << int(mode) << ", black " << black);
                if (black) CHECK(sum == 0.0);
                else CHECK(sum > 0.0);
            }
        }
    }
}

TEST_CASE("under a sky, pm and sppm agree with the path tracer block by block", "[environment][render][heavy]") {
    // A ball on a floor slab under a gradient sky with a bright spot: direct sky light, the
    // ball's colour bled onto the floor (photons) and its shadow, and the sky seen at the top.
    DefaultScene<double> scene;
    scene.add(Box<double>({-3, -0.2, -3}, {3, 0, 3}), scene.add_material(Material<double>::lambertian(Rgb<double>(0.7))));
    scene.add(Sphere<double>({0, 0.5, 0.3}, 0.5), scene.add_material(Material<double>::lambertian(Rgb<double>(0.8, 0.2, 0.1))));
    struct GradientSpot {
        [[nodiscard]] Rgb<double> operator()(const Vec3<double>& d) const noexcept {
            const double c = glm::dot(d, glm::normalize(Vec3<double>(1, 1, -0.5)));
            const double t = (d.y + 1) / 2;
            return (c > 0.97 ? Rgb<double>(20.0) : Rgb<double>(0.0)) + (1 - t) * Rgb<double>(0.3) + t * Rgb<double>(0.4, 0.6, 1.0);
        }
        [[nodiscard]] Rgb<double> upper_bound() const noexcept { return Rgb<double>(21.0); }
    };
    scene.set_environment(Environment<double>(AnyReflectanceField<double>(GradientSpot{})));
    scene.commit();
    const auto camera = PinholeCamera<double>::look_at({0, 1.6, -2.8}, {0, 0.3, 0.3}, {0, 1, 0}, 50, 32.0 / 24.0);
    RenderSettings ref = sky_settings(RenderMode::reference);
    ref.width = 32;
    ref.height = 24;
    ref.samples_per_pixel = 256;
    RenderSettings sppm = ref;
    sppm.mode = RenderMode::sppm;
    sppm.sppm_passes = 16;
    sppm.sppm_photons_per_pass = 100'000;
    sppm.sppm_initial_radius = 0.05f;
    RenderSettings pm = ref;
    pm.mode = RenderMode::pm;
    pm.samples_per_pixel = 4;
    pm.global_photons = 200'000;
    pm.final_gather_rays = 64;
    std::vector<Rgb<double>> blocks[3][2];
    RenderSettings* modes[3] = {&ref, &sppm, &pm};
    for (std::uint64_t seed : {1u, 2u})
        for (int m = 0; m < 3; ++m) {
            modes[m]->seed = seed;
            blocks[m][seed - 1] = block_means(render(scene, camera, *modes[m]).film, 4, 3);
        }
    // Half the squared difference of a block's two means estimates the variance of one mean.
    constexpr std::size_t count = 12;
    double noise2[3] = {0, 0, 0};
    for (int m = 0; m < 3; ++m)
        for (std::size_t b = 0; b < count; ++b)
            for (int c = 0; c < 3; ++c) {
                const double d = blocks[m][0][b][c] - blocks[m][1][b][c];
                noise2[m] += d * d / 2 / (3 * count);
            }
    for (int m = 1; m < 3; ++m)
        for (std::size_t b = 0; b < count; ++b)
            for (int c = 0; c < 3; ++c) {
                const double ours = (blocks[m][0][b][c] + blocks[m][1][b][c]) / 2;
                const double truth = (blocks[0][0][b][c] + blocks[0][1][b][c]) / 2;
                const double sigma = std::sqrt((noise2[m] + noise2[0]) / 2);
                INFO("mode " << m << ", block " << b << ", channel " << c << ": " << ours << " vs " << truth << ", noise " << sigma);
                // Within 4 sigma of the noise, or 3% (the density estimates' blur at the ball's edge).
                CHECK(std::abs(ours - truth) <= std::max(4 * sigma, 0.03 * truth));
            }
}

TEST_CASE("the plan gives the sky its share of the global photons, by power", "[environment][plan]") {
    DefaultScene<double> scene;
    scene.add(Box<double>({-1, -0.1, -1}, {1, 0, 1}), scene.add_material(Material<double>::lambertian(Rgb<double>(0.5))));
    scene.add(Sphere<double>({0, 0.5, 0}, 0.5), scene.add_material(Material<double>::lambertian(Rgb<double>(0.5))));
    scene.set_environment(Environment<double>(Rgb<double>(1.0)));
    scene.commit();
    RenderSettings settings = sky_settings(RenderMode::pm);
    settings.global_photons = 100'000;
    const auto camera = PinholeCamera<double>::look_at({0, 1.5, -2.5}, {0, 0.2, 0}, {0, 1, 0}, 45, 4.0 / 3.0);
    // The sky alone: every global photon is the sky's, and the plan says so.
    const EffectsPlan alone = plan_effects(scene, camera, settings);
    CHECK(alone.global_pass);
    CHECK(alone.environment_photons == 100'000);
    // Beside a point light of the sky's power into its ball (pi r^2 4 pi L): half each.
    const double r = scene.environment_ball().radius;
    scene.add_light(PointLight<double>{{0, 3, 0}, Rgb<double>(pi<double> * r * r * 4 * pi<double>)});
    const EffectsPlan shared = plan_effects(scene, camera, settings);
    CHECK(shared.environment_photons == 50'000);
    CHECK(shared.lights.at(0).global_photons == 50'000);
}
