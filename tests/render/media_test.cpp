// SPDX-License-Identifier: MIT
// Participating media (material/medium.hpp, integrator/media_march.hpp, media_seen.hpp) against
// closed forms and a quadrature written here, one camera ray at a time in every mode (rt/pm's
// radiance, the path tracer, sppm's camera path), and whole images: the same for any thread
// count, and finite.

#include <catch2/catch.hpp>

#include <photon/photon.hpp>

#include <cmath>
#include <vector>

using namespace photon;

namespace {

/// The radiance the three integrators see along one camera ray.
template <class SceneT>
std::vector<Rgb<double>> media_seen_by_every_mode(const SceneT& scene, const Ray<typename SceneT::scalar_type>& ray) {
    RenderSettings settings;
    settings.mode = RenderMode::rt;
    const PhotonMaps no_maps;
    ShadingContext ctx;
    return {Rgb<double>(RadianceIntegrator<SceneT>(scene, no_maps, settings).radiance(ray, 1, ctx)),
            Rgb<double>(PathTracer<SceneT>(scene, settings).radiance(ray, ctx)),
            Rgb<double>(trace_camera_path(scene, ray, settings, ctx).direct)};
}

/// A clear ball (ior 1: rays pass straight) filled with `medium`.
template <Scalar S> Material<S> media_container(const Medium<S>& medium) {
    MaterialParams<S> p{.transmission = Rgb<S>(S(1)), .ior = S(1)};
    p.media = {medium};
    return Material<S>(p);
}

}  // namespace

TEMPLATE_TEST_CASE("an absorbing medium dims what lies behind it by Beer-Lambert's law", "[media][render]", float, double) {
    using S = TestType;
    const Rgb<S> sigma(S(0.2), S(0.5), S(1.1));
    const Rgb<S> wall(S(0.8), S(0.6), S(0.4));
    for (const S scale : {S(1e-2), S(1), S(1e3)}) {
        Medium<S> medium;
        medium.absorption = sigma / scale;
        DefaultScene<S> scene;
        scene.add(Sphere<S>(Vec3<S>(S(0), S(0), S(3)) * scale, S(1.5) * scale), scene.add_material(media_container(medium)));
        scene.add(Plane<S>({S(0), S(0), S(-1)}, S(-8) * scale), scene.add_material(Material<S>({.ambient = wall})));
        scene.commit();
        INFO("scale " << scale);
        for (const Rgb<double>& seen : media_seen_by_every_mode(scene, Ray<S>{Vec3<S>(S(0)), {S(0), S(0), S(1)}}))
            for (int c = 0; c < 3; ++c) CHECK(seen[c] == Approx(double(wall[c]) * std::exp(-3.0 * double(sigma[c]))).epsilon(1e-4));
    }
}

TEMPLATE_TEST_CASE("an emitting medium adds e (1 - exp(-sigma L)) / sigma, and e L where it absorbs nothing",
                   "[media][render]", float, double) {
    using S = TestType;
    const Rgb<S> e(S(0.3), S(0.1), S(0.7));
    for (const S sigma : {S(0), S(0.4), S(3)}) {
        Medium<S> medium;
        medium.emission = e;
        medium.absorption = Rgb<S>(sigma);
        DefaultScene<S> scene;  // a ball of radius 2: the ray through its centre runs 4 inside
        scene.add(Sphere<S>(Vec3<S>(S(0), S(0), S(5)), S(2)), scene.add_material(media_container(medium)));
        scene.commit();
        const double share = sigma > S(0) ? (1 - std::exp(-4.0 * double(sigma))) / double(sigma) : 4.0;
        INFO("sigma " << sigma);
        for (const Rgb<double>& seen : media_seen_by_every_mode(scene, Ray<S>{Vec3<S>(S(0)), {S(0), S(0), S(1)}}))
            for (int c = 0; c < 3; ++c) CHECK(seen[c] == Approx(double(e[c]) * share).epsilon(1e-4));
    }
}

TEST_CASE("a point light scattered by a thin homogeneous slab matches a quadrature of single scattering", "[media][render]") {
    // A slab 0.3 thick between z = 2 and 2.3 (a box), isotropic scattering and absorption; a point
    // light beside it outside. Along the ray x(t) = (0, 0, t), each point receives I / d^2 dimmed by
    // the medium between it and the slab's face towards the light (the light is above, so the
    // shadow ray leaves through the top face y = 1 ... whichever face it meets first), and sends
    // sigma_s / (4 pi) of it towards the eye, dimmed by the medium before it.
    const double sigma_a = 0.7, sigma_s = 1.9, half = 1.0;
    const Vec3<double> light_at(0.4, 3.0, 1.0);
    const double power = 500.0;
    Medium<double> medium;
    medium.absorption = Rgb<double>(sigma_a);
    medium.scattering = Rgb<double>(sigma_s);
    medium.sampling = {.intervals = 4, .samples = 100, .jitter = 0.0};
    DefaultScene<double> scene;
    scene.add(Box<double>({-half, -half, 2.0}, {half, half, 2.3}), scene.add_material(media_container(medium)));
    scene.add_light(PointLight<double>{.position = light_at, .power = Rgb<double>(power)});
    scene.commit();

    const double sigma_t = sigma_a + sigma_s, intensity = power / (4 * std::acos(-1.0));
    const auto inside_towards_light = [&](const Vec3<double>& x) {  // distance to the box's boundary
        const Vec3<double> d = glm::normalize(light_at - x);
        double t = 1e30;
        const Vec3<double> lo(-half, -half, 2.0), hi(half, half, 2.3);
        for (int a = 0; a < 3; ++a)
            if (d[a] != 0) t = std::min(t, ((d[a] > 0 ? hi[a] : lo[a]) - x[a]) / d[a]);
        return t;
    };
    constexpr int n = 20'000;  // Simpson's rule over the 0.3 inside
    double expected = 0;
    for (int i = 0; i <= n; ++i) {
        const double t = 0.3 * i / n;
        const Vec3<double> x(0, 0, 2.0 + t);
        const double d2 = glm::dot(light_at - x, light_at - x);
        const double f = std::exp(-sigma_t * t) * sigma_s / (4 * std::acos(-1.0)) * intensity / d2 *
                         std::exp(-sigma_t * inside_towards_light(x));
        expected += (i == 0 || i == n ? 1 : (i % 2 ? 4 : 2)) * f;
    }
    expected *= 0.3 / n / 3;
    for (const Rgb<double>& seen : media_seen_by_every_mode(scene, Ray<double>{Vec3<double>(0), {0, 0, 1}}))
        for (int c = 0; c < 3; ++c) CHECK(seen[c] == Approx(expected).epsilon(1e-3));
    // Henyey-Greenstein forward scattering: looking towards the light shows more than looking away.
    medium.phase = PhaseFunction::henyey_greenstein;
    medium.eccentricity = 0.6;
    DefaultScene<double> forward;
    forward.add(Box<double>({-half, -half, 2.0}, {half, half, 2.3}), forward.add_material(media_container(medium)));
    forward.add_light(PointLight<double>{.position = {0.0, 0.15, 6.0}, .power = Rgb<double>(power)});
    forward.commit();
    const auto towards = media_seen_by_every_mode(forward, Ray<double>{Vec3<double>(0, 0.15, 0), {0, 0, 1}});
    CHECK(towards[0][0] > 0.0);
    CHECK(phase_value(PhaseFunction::henyey_greenstein, 0.6, 1.0) > phase_value(PhaseFunction::henyey_greenstein, 0.6, -1.0));
}

TEST_CASE("phase functions are POV-Ray's divided by 4 pi, and Henyey-Greenstein integrates to 1", "[media]") {
    const double inv4pi = 1 / (4 * std::acos(-1.0));
    CHECK(phase_value(PhaseFunction::isotropic, 0.0, 0.3) == Approx(inv4pi));
    CHECK(phase_value(PhaseFunction::rayleigh, 0.0, 1.0) == Approx(inv4pi * 0.799372013 * 2));
    CHECK(phase_value(PhaseFunction::mie_murky, 0.0, 1.0) == Approx(inv4pi * 0.495714547 * 51));
    for (const double g : {-0.7, 0.0, 0.5, 0.9}) {
        double integral = 0;  // over the sphere: 2 pi times the integral over alpha in [-1, 1]
        constexpr int n = 200'000;
        for (int i = 0; i < n; ++i) integral += phase_value(PhaseFunction::henyey_greenstein, g, -1 + 2 * (i + 0.5) / n);
        CHECK(integral * 2.0 / n * 2 * std::acos(-1.0) == Approx(1.0).epsilon(1e-3));
    }
}

TEST_CASE("photons and the path tracer's later segments are dimmed by media, and scattered light is not carried",
          "[media][render]") {
    Medium<double> medium;
    medium.absorption = Rgb<double>(0.5);
    DefaultScene<double> scene;
    scene.add(Sphere<double>({0, 0, 3}, 1), scene.add_material(media_container(medium)));
    scene.commit();
    Pcg32 rng(1, 2);
    const Ray<double> ray{Vec3<double>(0), {0, 0, 1}};
    const auto surface = scene.intersect(ray);  // the ball's near side, from outside: no medium before it
    REQUIRE(surface);
    const Facing<double> f = facing(*surface->material, surface->hit.point, surface->hit.normal, ray.direction);
    CHECK(media_transmittance_seen(scene, ray, surface, &f, rng)[0] == Approx(1.0));
    const Ray<double> inside{Vec3<double>(0, 0, 2.5), {0, 0, 1}};
    const auto far = scene.intersect(inside);
    REQUIRE(far);
    const Facing<double> g = facing(*far->material, far->hit.point, far->hit.normal, inside.direction);
    CHECK(media_transmittance_seen(scene, inside, far, &g, rng)[0] == Approx(std::exp(-0.5 * 1.5)).epsilon(1e-6));
}

TEST_CASE("an image with jittered, patterned, scattering media is the same for any thread count, and finite",
          "[media][render]") {
    DefaultScene<float> scene;
    scene.add(Plane<float>({0, 1, 0}, 0), scene.add_material(Material<float>::lambertian(Rgb<float>(0.6f))));
    Medium<float> glow;
    glow.emission = Rgb<float>(0.4f, 0.2f, 0.1f);
    glow.absorption = Rgb<float>(0.3f);
    glow.scattering = Rgb<float>(0.5f);
    glow.phase = PhaseFunction::mie_hazy;
    glow.density = {AnyReflectanceField<float>(
        Pigment<float>(Pattern::of(PatternKind::spherical), ColorMap<float>({{0.0, Rgb<float>(0)}, {1.0, Rgb<float>(1)}})))};
    glow.sampling = {.intervals = 2, .samples = 5, .jitter = 0.8};
    scene.add(Sphere<float>({0, 1, 2}, 1), scene.add_material(media_container(glow)));
    Medium<float> haze;
    haze.scattering = Rgb<float>(0.02f);
    haze.sampling.jitter = 1.0;
    scene.add_medium(haze);
    scene.add(Sphere<float>({0, 0, 0}, 40), scene.add_material(Material<float>::lambertian(Rgb<float>(0.2f))));
    scene.add_light(PointLight<float>{.position = {2, 4, -1}, .power = Rgb<float>(300)});
    scene.commit();
    const auto camera = PinholeCamera<float>::look_at({0, 1.5f, -3}, {0, 1, 2}, {0, 1, 0}, 50, 4.0f / 3.0f);
    for (const RenderMode mode : {RenderMode::rt, RenderMode::pm, RenderMode::sppm, RenderMode::reference}) {
        INFO("mode " << int(mode));
        std::vector<Rgb<float>> first;
        for (const unsigned threads : {1u, 2u}) {
            RenderSettings settings;
            settings.mode = mode;
            settings.width = 16;
            settings.height = 12;
            settings.threads = threads;
            settings.samples_per_pixel = 2;
            settings.global_photons = 3'000;
            settings.caustic_photons = 3'000;
            settings.final_gather_rays = 8;
            settings.sppm_passes = 2;
            settings.sppm_photons_per_pass = 3'000;
            const Film film = render(scene, camera, settings).film;
            std::vector<Rgb<float>> pixels(film.pixels().begin(), film.pixels().end());
            double sum = 0;
            for (const Rgb<float>& p : pixels) {
                REQUIRE(is_finite(p));
                sum += double(average(p));
            }
            CHECK(sum > 0.0);
            if (first.empty()) first = pixels;
            else CHECK(pixels == first);
        }
    }
}

TEST_CASE("a light's media_interaction off scatters nothing, and media_attenuation dims its shadow rays in the atmosphere",
          "[media][render]") {
    Medium<double> medium;
    medium.scattering = Rgb<double>(1.0);
    DefaultScene<double> dark;
    dark.add(Sphere<double>({0, 0, 3}, 1), dark.add_material(media_container(medium)));
    dark.add_light(PointLight<double>{.position = {0, 2, 3}, .power = Rgb<double>(100), .media_interaction = false});
    dark.commit();
    for (const Rgb<double>& seen : media_seen_by_every_mode(dark, Ray<double>{Vec3<double>(0), {0, 0, 1}}))
        CHECK(seen[0] == 0.0);

    // A white floor 2 below the eye, a light 3 above the point the ray meets; an absorbing
    // atmosphere. The camera's segment (length 2 sqrt 2) is dimmed either way; the shadow ray
    // (length 3) only with media_attenuation.
    const double sigma = 0.15, power = 80.0, albedo = 0.7;
    for (const bool attenuation : {false, true}) {
        Medium<double> air;
        air.absorption = Rgb<double>(sigma);
        DefaultScene<double> scene;
        scene.add(Plane<double>({0, 1, 0}, -2), scene.add_material(Material<double>::lambertian(Rgb<double>(albedo))));
        scene.add_light(PointLight<double>{.position = {0, 1, 2}, .power = Rgb<double>(power), .media_attenuation = attenuation});
        scene.add_medium(air);
        scene.commit();
        const double irradiance = power / (4 * std::acos(-1.0)) / 9.0 * (attenuation ? std::exp(-sigma * 3) : 1.0);
        const double expected = albedo / std::acos(-1.0) * irradiance * std::exp(-sigma * 2 * std::sqrt(2.0));
        RenderSettings settings;
        settings.mode = RenderMode::rt;
        ShadingContext ctx;
        const Ray<double> ray{Vec3<double>(0), glm::normalize(Vec3<double>(0, -1, 1))};
        INFO("media_attenuation " << attenuation);
        CHECK(RadianceIntegrator<DefaultScene<double>>(scene, PhotonMaps{}, settings).radiance(ray, 1, ctx)[0] ==
              Approx(expected).epsilon(1e-6));
    }
}

TEST_CASE("a spotlight's beam is sampled where the ray crosses its cone, and matches a quadrature", "[media][render]") {
    // A sharp 10-degree cone pointing down from (0, 5, 3) crosses the ray along +z between
    // z = 3 -+ 5 tan 10 deg. Atmospheric isotropic scattering; a black wall at z = 8.
    const double sigma_s = 0.2, power = 40.0, half_angle = 10.0;
    const Vec3<double> apex(0, 5, 3);
    Medium<double> haze;
    haze.scattering = Rgb<double>(sigma_s);
    haze.sampling = {.intervals = 4, .samples = 40, .jitter = 0.0};
    DefaultScene<double> scene;
    scene.add(Plane<double>({0, 0, -1}, -8), scene.add_material(Material<double>::lambertian(Rgb<double>(0))));
    PointLight<double> spot{.position = apex, .power = Rgb<double>(power)};
    spot.cone = Cone<double>({0, -1, 0}, half_angle);
    scene.add_light(spot);
    scene.add_medium(haze);
    scene.commit();

    const LitSpan<double> span = cone_span(apex, Vec3<double>(0, -1, 0), std::cos(half_angle * std::acos(-1.0) / 180),
                                           Vec3<double>(0), Vec3<double>(0, 0, 1), 8.0);
    const double reach = 5 * std::tan(half_angle * std::acos(-1.0) / 180);
    CHECK(span.start == Approx(3 - reach));
    CHECK(span.end == Approx(3 + reach));
    const auto intervals = media_intervals<double>(std::span<const LitSpan<double>>(&span, 1), 8.0, haze.sampling, true);
    REQUIRE(intervals.size() == 4);  // POV-Ray's share: int(0.1 / 1.1 * 4) + 1 unlit on each side, the rest lit
    CHECK(!intervals[0].lit);
    CHECK(intervals[1].lit);
    CHECK(intervals[1].start + intervals[1].length * 2 == Approx(3 + reach));

    const double intensity = power / spot.cone->solid_angle();  // a sharp cone's power over its solid angle
    constexpr int n = 40'000;
    const double a = 3 - reach, b = 3 + reach, h = (b - a) / n;
    double expected = 0;
    for (int i = 0; i <= n; ++i) {
        const double z = a + h * i;
        const double d2 = glm::dot(apex - Vec3<double>(0, 0, z), apex - Vec3<double>(0, 0, z));
        expected += (i == 0 || i == n ? 1 : (i % 2 ? 4 : 2)) * std::exp(-sigma_s * z) * sigma_s / (4 * std::acos(-1.0)) *
                    intensity / d2;
    }
    expected *= h / 3;
    for (const Rgb<double>& seen : media_seen_by_every_mode(scene, Ray<double>{Vec3<double>(0), {0, 0, 1}}))
        CHECK(seen[0] == Approx(expected).epsilon(2e-3));
}
