// SPDX-License-Identifier: MIT
// Energy at the extremes: a closed box that absorbs nothing (photon paths must still end, at the
// maximum depth, with every bounce's power accounted for) and a scene that absorbs everything.

#include "hard_case_util.hpp"

using namespace photon;

namespace {

/// A closed box of `albedo` with a point light inside, off-centre.
template <class S> DefaultScene<S> closed_box(const Rgb<S>& albedo) {
    DefaultScene<S> scene;
    const auto wall = scene.add_material(Material<S>::lambertian(albedo));
    // Six walls 0.1 thick around [-1, 1] x [0, 2] x [-1, 1].
    scene.add(Box<S>({-1.1, -0.1, -1.1}, {1.1, 0, 1.1}), wall);
    scene.add(Box<S>({-1.1, 2, -1.1}, {1.1, 2.1, 1.1}), wall);
    scene.add(Box<S>({-1.1, 0, -1.1}, {-1, 2, 1.1}), wall);
    scene.add(Box<S>({1, 0, -1.1}, {1.1, 2, 1.1}), wall);
    scene.add(Box<S>({-1, 0, -1.1}, {1, 2, -1}), wall);
    scene.add(Box<S>({-1, 0, 1}, {1, 2, 1.1}), wall);
    scene.add_light(PointLight<S>{{0.2, 1.5, -0.3}, Rgb<S>(S(1))});
    scene.commit();
    return scene;
}

Rgb<double> stored_power(const TracedPhotons& traced) {
    Rgb<double> sum(0.0);
    for (const Photon& p : traced.photons) sum += Rgb<double>(p.packed.power());
    return sum;
}

}  // namespace

TEMPLATE_TEST_CASE("closed box of albedo 1: paths end at the maximum depth and every bounce is stored",
                   "[hard][energy]", float, double) {
    using S = TestType;
    const auto scene = closed_box<S>(Rgb<S>(S(1)));
    for (const unsigned depth : {1u, 7u, 40u}) {
        const std::size_t photons = 4'000;
        const TracedPhotons traced = trace_global_photons(scene, {.photons = photons, .max_depth = depth, .seed = 4, .threads = 2});
        INFO("max depth " << depth);
        // Nothing escapes and nothing is absorbed: each photon is stored at each of its `depth`
        // hits with the full power 1 / photons, and traces exactly `depth` rays.
        CHECK(traced.photons.size() == photons * depth);
        CHECK(traced.rays == photons * depth);
        const Rgb<double> sum = stored_power(traced);
        for (int c = 0; c < 3; ++c) CHECK(sum[c] == Approx(double(depth)).epsilon(2e-4));  // 12-bit power encoding
    }
    // And it renders: finite, and brighter than direct light alone.
    const auto camera = PinholeCamera<S>::look_at({0, 1, -0.9}, {0, 0.8, 1}, {0, 1, 0}, S(70), S(32.0 / 24.0));
    RenderSettings s = hard::tiny(RenderMode::pm);
    s.max_photon_depth = 40;
    s.global_photons = 5'000;  // 200,000 stored at 40 bounces each
    const RenderResult pm = render(scene, camera, s);
    HARD_REQUIRE_VALID(pm.film);
    const RenderResult rt = render(scene, camera, hard::tiny(RenderMode::rt));
    HARD_REQUIRE_VALID(rt.film);
    CHECK(pm.film.mean().x > 10 * rt.film.mean().x);  // about 40 bounces' worth against one
}

// [heavy]: 400,000 photons for a 1% check, the same tracing as the test above (the sanitizer run
// of scripts/test.sh leaves it out).
TEMPLATE_TEST_CASE("closed grey box: the stored power is the analytic sum over bounces", "[hard][energy][heavy]", float,
                   double) {
    using S = TestType;
    // Phi (1 - rho^D) / (1 - rho) for albedo rho and D bounces.
    const Rgb<S> rho{S(0.9), S(0.6), S(0.3)};
    const auto grey = closed_box<S>(rho);
    const unsigned depth = 6;
    const Rgb<double> sum = stored_power(trace_global_photons(grey, {.photons = 400'000, .max_depth = depth, .seed = 9, .threads = 2}));
    for (int c = 0; c < 3; ++c) {
        const double r = double(rho[c]);
        INFO("channel " << c);
        CHECK(sum[c] == Approx((1 - std::pow(r, depth)) / (1 - r)).epsilon(0.01));
    }
}

TEMPLATE_TEST_CASE("albedo 0 everywhere: only direct photons, and a black, finite image", "[hard][energy]", float,
                   double) {
    using S = TestType;
    // Albedo exactly 0 is not diffuse at all: nothing is stored and the image is black.
    const auto black = closed_box<S>(Rgb<S>(S(0)));
    const TracedPhotons none = trace_global_photons(black, {.photons = 10'000, .max_depth = 10, .threads = 2});
    CHECK(none.photons.empty());
    CHECK(none.rays == 10'000);  // one ray per photon: absorbed at the first wall
    // Albedo just above 0 stores every direct photon; the first bounce survives with probability
    // 1e-6, so indirect photons essentially never appear.
    const auto almost = closed_box<S>(Rgb<S>(S(1e-6)));
    const TracedPhotons direct = trace_global_photons(almost, {.photons = 10'000, .max_depth = 10, .threads = 2});
    CHECK(direct.photons.size() == 10'000);
    std::size_t not_direct = 0;
    for (const Photon& p : direct.photons) not_direct += p.packed.kind() == PathKind::direct ? 0 : 1;
    CHECK(not_direct == 0);
    const auto camera = PinholeCamera<S>::look_at({0, 1, -0.9}, {0, 0.8, 1}, {0, 1, 0}, S(70), S(32.0 / 24.0));
    for (const DefaultScene<S>* scene : {&black, &almost})
        for (const RenderMode mode : {RenderMode::rt, RenderMode::pm, RenderMode::pm_direct}) {
            const RenderResult r = render(*scene, camera, hard::tiny(mode));
            HARD_REQUIRE_VALID(r.film);
            CHECK(r.film.mean().x < 1e-5);
        }
}
