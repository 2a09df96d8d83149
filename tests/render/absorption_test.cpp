// SPDX-License-Identifier: MIT
// Absorbing glass (material/absorption.hpp): POV-Ray 3.7's fade laws by hand; a camera ray
// through a slab of known thickness against the closed form with its internal reflections, in
// rt, the path tracer and sppm's camera paths; photons leaving an absorbing ball against theirs;
// and pm and sppm against the path tracer on a floor lit and seen through a tinted slab.

#include <catch2/catch.hpp>

#include <photon/photon.hpp>

#include "film_compare.hpp"

#include <cmath>
#include <vector>

using namespace photon;

namespace {

constexpr double absorb_ior = 1.5;
constexpr double absorb_f0 = 0.04;  // ((1.5 - 1) / (1.5 + 1))^2, Fresnel at normal incidence

/// A slab z in [0, thickness] of absorbing glass in front of a wall (z = 2) that shows radiance 1
/// and lights nothing; no lights.
template <Scalar S> struct AbsorbingSlab {
    DefaultScene<S> scene;
    AbsorbingSlab(S thickness, const Absorption<S>& absorption) {
        MaterialParams<S> glass{.transmission = Rgb<S>(S(1)), .ior = S(absorb_ior), .fresnel = true};
        glass.absorption = absorption;
        scene.add(Box<S>({S(-50), S(-50), S(0)}, {S(50), S(50), thickness}), scene.add_material(Material<S>(glass)));
        scene.add(Box<S>({S(-50), S(-50), S(2)}, {S(50), S(50), S(2.1)}),
                  scene.add_material(Material<S>(MaterialParams<S>{.ambient = Rgb<S>(S(1))})));
        scene.commit();
    }
};

/// Radiance seen straight through the slab: in (1 - F), across (T), out (1 - F), with the light
/// reflected back and forth inside adding (F T)^2 each round trip (what leaves towards the
/// camera's back sees nothing).
double slab_closed_form(double t) { return (1 - absorb_f0) * (1 - absorb_f0) * t / (1 - absorb_f0 * absorb_f0 * t * t); }

/// Photon power reaching an enclosing wall first, from a light at the centre of an absorbing
/// ball of radius r: out through the surface (1 - F) after r, or reflected back across the
/// diameter (F, T(2r)) to try again.
double ball_closed_form(double t_r, double t_2r) { return (1 - absorb_f0) * t_r / (1 - absorb_f0 * t_2r); }

}  // namespace

TEMPLATE_TEST_CASE("POV-Ray 3.7's interior fade laws", "[absorption]", float, double) {
    using S = TestType;
    CHECK_FALSE(Absorption<S>().absorbs());
    CHECK(Absorption<S>().transmittance(S(5)).x == S(1));
    // fade_distance 0 is clear, whatever the power (POV-Ray tests |fade_distance| > epsilon).
    CHECK_FALSE(Absorption<S>::pov_fade(S(0), S(2)).absorbs());
    // fade_power >= 1000: exp(-(1 - fade_color) d / fade_distance) per channel.
    const auto e = Absorption<S>::pov_fade(S(2), S(1001), Rgb<S>(S(0), S(0.5), S(1)));
    CHECK(e.law() == Absorption<S>::Law::beer_lambert);
    CHECK(e.transmittance(S(3)).x == Approx(std::exp(-1.5)));
    CHECK(e.transmittance(S(3)).y == Approx(std::exp(-0.75)));
    CHECK(e.transmittance(S(3)).z == Approx(1.0));
    // Below 1000: fade_color + (1 - fade_color) / (1 + (d / fade_distance)^fade_power).
    const auto q = Absorption<S>::pov_fade(S(2), S(2), Rgb<S>(S(0.2), S(0), S(0)));
    CHECK(q.transmittance(S(3)).x == Approx(0.2 + 0.8 / (1 + 2.25)));
    CHECK(q.transmittance(S(3)).y == Approx(1 / 3.25));
    // fade_power 0 (POV-Ray's default) halves what is not fade_color, at any depth.
    const auto zero = Absorption<S>::pov_fade(S(2), S(0), Rgb<S>(S(0.5)));
    CHECK(zero.transmittance(S(0.01)).x == Approx(0.75));
    CHECK(zero.transmittance(S(100)).x == Approx(0.75));
    // Values that would make light grow are refused.
    CHECK_THROWS_AS(Absorption<S>::pov_fade(S(-1), S(2)), std::invalid_argument);
    CHECK_THROWS_AS(Absorption<S>::pov_fade(S(1), S(2), Rgb<S>(S(1.5))), std::invalid_argument);
    CHECK_THROWS_AS(Absorption<S>::beer_lambert(Rgb<S>(S(-0.1))), std::invalid_argument);
}

TEMPLATE_TEST_CASE("a camera ray through an absorbing slab sees Fresnel times exp(-sigma d), in rt, the path tracer and sppm",
                   "[absorption][render]", float, double) {
    using S = TestType;
    const Rgb<S> sigma(S(0.2), S(0.7), S(1.5));
    const S thickness = S(0.8);
    const AbsorbingSlab<S> slab(thickness, Absorption<S>::beer_lambert(sigma));
    RenderSettings settings;
    settings.max_ray_depth = 64;
    const Ray<S> ray{{S(0), S(0), S(-1)}, {S(0), S(0), S(1)}};
    ShadingContext ctx;
    ctx.rng = Pcg32(7, 1);
    const PhotonMaps no_maps;
    settings.mode = RenderMode::rt;
    const RadianceIntegrator<DefaultScene<S>> rt(slab.scene, no_maps, settings);
    const Rgb<S> exact = rt.radiance(ray, 1, ctx);
    const PathTracer<DefaultScene<S>> reference(slab.scene, settings);
    Rgb<double> path_sum(0.0), sppm_sum(0.0);
    constexpr int paths = 40'000;
    for (int i = 0; i < paths; ++i) {
        path_sum += Rgb<double>(reference.radiance(ray, ctx));
        sppm_sum += Rgb<double>(trace_camera_path(slab.scene, ray, settings, ctx).direct);
    }
    // float: the ray's offsets off each face are larger than double's
    const double exact_eps = sizeof(S) == sizeof(float) ? 1e-4 : 1e-7;
    for (int c = 0; c < 3; ++c) {
        const double expected = slab_closed_form(std::exp(-double(sigma[c]) * double(thickness)));
        INFO("channel " << c << ": expected " << expected);
        CHECK(double(exact[c]) == Approx(expected).epsilon(exact_eps));
        CHECK(path_sum[c] / paths == Approx(expected).epsilon(0.01));
        CHECK(sppm_sum[c] / paths == Approx(expected).epsilon(0.01));
    }
    // The same slab, clear: the absorption is what made the difference.
    const AbsorbingSlab<S> clear(thickness, Absorption<S>{});
    const RadianceIntegrator<DefaultScene<S>> clear_rt(clear.scene, no_maps, settings);
    CHECK(double(clear_rt.radiance(ray, 1, ctx).x) == Approx(slab_closed_form(1.0)).epsilon(exact_eps));
}

TEMPLATE_TEST_CASE("photons leaving an absorbing ball carry Fresnel times its transmittance", "[absorption][transport]",
                   float, double) {
    using S = TestType;
    const S radius = S(0.5);
    // Beer-Lambert, and POV-Ray's rational fade (which photon applies per straight segment).
    const Absorption<S> laws[] = {Absorption<S>::beer_lambert(Rgb<S>(S(0.3), S(1), S(2.5))),
                                  Absorption<S>::pov_fade(S(0.4), S(2), Rgb<S>(S(0.1), S(0.5), S(0)))};
    for (const Absorption<S>& law : laws) {
        DefaultScene<S> scene;
        MaterialParams<S> glass{.transmission = Rgb<S>(S(1)), .ior = S(absorb_ior), .fresnel = true};
        glass.absorption = law;
        scene.add(Sphere<S>({S(0), S(0), S(0)}, radius), scene.add_material(Material<S>(glass)));
        // A dark enclosing wall: photons are stored there first as caustics, and rarely come back.
        scene.add(Sphere<S>({S(0), S(0), S(0)}, S(3)), scene.add_material(Material<S>::lambertian(Rgb<S>(S(0.05)))));
        scene.add_light(PointLight<S>{{S(0), S(0), S(0)}, Rgb<S>(S(1))});
        scene.commit();
        const TracedPhotons traced = trace_global_photons(
            scene, {.photons = 200'000, .max_depth = 100, .store = {.direct = false, .caustic = true, .indirect = false},
                    .seed = 5});
        Rgb<double> arrived(0.0);
        for (const Photon& p : traced.photons) arrived += Rgb<double>(p.packed.power());
        for (int c = 0; c < 3; ++c) {
            const double expected = ball_closed_form(double(law.transmittance(radius)[c]),
                                                     double(law.transmittance(2 * radius)[c]));
            INFO("law " << int(law.law()) << ", channel " << c << ": expected " << expected << " W");
            CHECK(arrived[c] == Approx(expected).epsilon(0.01));
        }
    }
}

namespace {

/// A floor lit by a sphere light through a tinted slab, which the camera also looks through:
/// under the slab every light path and every camera path crosses absorbing glass.
struct TintedSlabRoom {
    DefaultScene<double> scene;
    PinholeCamera<double> camera =
        PinholeCamera<double>::look_at({0, 2.2, -2.2}, {0, 0, 0.2}, {0, 1, 0}, 55, 32.0 / 24.0);
    explicit TintedSlabRoom(bool absorbing) {
        scene.add(Plane<double>({0, 1, 0}, 0), scene.add_material(Material<double>::lambertian(Rgb<double>(0.6))));
        MaterialParams<double> glass{.transmission = Rgb<double>(1.0), .ior = absorb_ior, .fresnel = true};
        if (absorbing) glass.absorption = Absorption<double>::beer_lambert(Rgb<double>(0.5, 2.0, 5.0));
        scene.add(Box<double>({-0.7, 0.35, -0.5}, {0.5, 0.6, 0.7}), scene.add_material(Material<double>(glass)));
        scene.add_light(SphereLight<double>{.center = {0.2, 2.0, 0.1}, .radius = 0.35, .power = Rgb<double>(60.0)});
        scene.commit();
    }
};

RenderSettings absorb_settings(RenderMode mode) {
    RenderSettings s;
    s.mode = mode;
    s.width = 32;
    s.height = 24;
    s.threads = 2;
    s.max_ray_depth = 10;
    s.max_photon_depth = 100;
    return s;
}

}  // namespace

TEST_CASE("through a tinted slab, pm and sppm agree with the path tracer block by block", "[absorption][render][heavy]") {
    const TintedSlabRoom room(true);
    RenderSettings ref = absorb_settings(RenderMode::reference);
    ref.samples_per_pixel = 512;
    RenderSettings sppm = absorb_settings(RenderMode::sppm);
    sppm.sppm_passes = 24;
    sppm.sppm_photons_per_pass = 100'000;
    sppm.sppm_initial_radius = 0.03f;
    RenderSettings pm = absorb_settings(RenderMode::pm);
    pm.samples_per_pixel = 4;
    pm.shadow_samples = 16;
    pm.global_photons = 100'000;
    pm.caustic_photons = 400'000;
    pm.final_gather_rays = 32;
    // Each mode twice with different seeds: half the squared difference of a block's two means
    // estimates the variance of one block mean (pooled over blocks and channels).
    std::vector<Rgb<double>> blocks[3][2];
    RenderSettings* modes[3] = {&ref, &sppm, &pm};
    for (std::uint64_t seed : {1u, 2u})
        for (int m = 0; m < 3; ++m) {
            modes[m]->seed = seed;
            blocks[m][seed - 1] = block_means(render(room.scene, room.camera, *modes[m]).film, 4, 3);
        }
    constexpr std::size_t count = 12;
    double noise2[3] = {0, 0, 0};
    for (int m = 0; m < 3; ++m)
        for (std::size_t b = 0; b < count; ++b)
            for (int c = 0; c < 3; ++c) {
                const double a = blocks[m][0][b][c], d = blocks[m][1][b][c];
                noise2[m] += (a - d) * (a - d) / (2 * ((a + d) / 2) * ((a + d) / 2)) / double(3 * count);
            }
    const auto mean_of = [&](int m, std::size_t b, int c) { return (blocks[m][0][b][c] + blocks[m][1][b][c]) / 2; };
    // The clear slab: how far the absorption moves each block, so that the agreement below is
    // known to be far tighter than what a pass ignoring it would miss by.
    const TintedSlabRoom clear(false);
    ref.seed = 1;
    const auto clear_blocks = block_means(render(clear.scene, clear.camera, ref).film, 4, 3);
    double moved = 0;
    for (std::size_t b = 0; b < count; ++b)
        for (int c = 0; c < 3; ++c) moved = std::max(moved, std::abs(clear_blocks[b][c] / mean_of(0, b, c) - 1));
    for (int m = 1; m < 3; ++m) {
        const double sigma = std::sqrt((noise2[0] + noise2[m]) / 2);
        double worst = 0;
        for (std::size_t b = 0; b < count; ++b)
            for (int c = 0; c < 3; ++c) worst = std::max(worst, std::abs(mean_of(m, b, c) / mean_of(0, b, c) - 1));
        INFO((m == 1 ? "sppm" : "pm") << ": relative noise of a block mean " << std::sqrt(noise2[m]) << " (reference "
                                      << std::sqrt(noise2[0]) << "); largest block difference " << worst << " = "
                                      << worst / sigma << " sigma; absorption moves a block by up to " << moved);
        CHECK(worst < std::max(4 * sigma, 0.03));
        CHECK(worst < moved / 4);
    }
}
