// SPDX-License-Identifier: MIT
// Adaptive anti-aliasing (film/adaptive_sampling.hpp): the stopping rule alone, then renders: off
// it is the uniform grid of before, on it is the same on any thread count, spends its samples at
// edges and beats a uniform render of as many samples against a brute-force judge.

#include <catch2/catch.hpp>

#include "../../examples/cornell_box.hpp"
#include "film_compare.hpp"

#include <photon/film/adaptive_sampling.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

using namespace photon;

namespace {

RunningStats seen_of(std::initializer_list<double> values) {
    RunningStats s;
    for (double v : values) s.add(v);
    return s;
}

/// Samples taken by the rule for a pixel whose k-th sample is value(k), in rounds of `round`.
template <class F> unsigned samples_taken(const AdaptiveRule& rule, unsigned round, F value) {
    RunningStats s;
    unsigned k = 0;
    do {
        for (unsigned i = 0; i < round; ++i) s.add(value(k++));
    } while (needs_more(s, rule, round));
    return k;
}

/// A white sphere on a white floor under a point light: its silhouette, its shadow's edge and the
/// horizon are the only places a pixel is not flat (rt has no other noise).
struct EdgeScene {
    DefaultScene<float> scene;
    PinholeCamera<float> camera = PinholeCamera<float>::look_at({0, 1.2f, -3}, {0, 0.4f, 0}, {0, 1, 0}, 50.0f, 4.0f / 3.0f);
    EdgeScene() {
        const auto white = scene.add_material(Material<float>::lambertian(Rgb<float>(0.7f)));
        scene.add(Plane<float>({0, 1, 0}, 0.0f), white);
        scene.add(Sphere<float>({0, 0.5f, 0}, 0.5f), white);
        scene.add_light(PointLight<float>{.position = {1.5f, 3, -1}, .power = Rgb<float>(60.0f)});
        scene.commit();
    }
};

RenderSettings edge_settings(unsigned spp) {
    RenderSettings s;
    s.mode = RenderMode::rt;
    s.width = 32;
    s.height = 24;
    s.samples_per_pixel = spp;
    s.shadow_samples = 1;
    return s;
}

Film render_rt(const EdgeScene& e, const RenderSettings& s, RenderStats& stats, std::vector<std::uint32_t>* counts = nullptr) {
    return render_image(e.scene, Camera<float>(e.camera), PhotonMaps{}, s, stats, {}, counts);
}

/// Sum over pixels and channels of the squared difference, over the judge's sum of squares.
double relative_mse(const Film& a, const Film& judge) {
    double err = 0, norm = 0;
    for (std::size_t i = 0; i < judge.pixels().size(); ++i)
        for (int c = 0; c < 3; ++c) {
            const double d = double(a.pixels()[i][c]) - double(judge.pixels()[i][c]);
            err += d * d;
            norm += double(judge.pixels()[i][c]) * double(judge.pixels()[i][c]);
        }
    return err / norm;
}

}  // namespace

TEST_CASE("running statistics: Welford's mean and unbiased variance", "[adaptive]") {
    const RunningStats s = seen_of({1, 2, 3, 4});
    CHECK(s.count() == 4);
    CHECK(s.mean() == Approx(2.5));
    CHECK(s.variance() == Approx(5.0 / 3.0));
    CHECK(s.standard_error() == Approx(std::sqrt(5.0 / 12.0)));
    // Large, close values: no cancellation.
    const RunningStats big = seen_of({1e9 + 1, 1e9 + 2, 1e9 + 3});
    CHECK(big.variance() == Approx(1.0));
    CHECK(seen_of({7}).variance() == 0.0);
}

TEST_CASE("the stopping rule: flat pixels stop at the base count, noisy ones go on to the maximum", "[adaptive]") {
    const AdaptiveRule rule{.threshold = 0.1, .max_samples = 64};
    SECTION("constant samples stop at the base count") {
        CHECK(samples_taken(rule, 4, [](unsigned) { return 0.6; }) == 4);
        CHECK(samples_taken(rule, 16, [](unsigned) { return 3.0; }) == 16);
    }
    SECTION("high-variance samples continue up to the maximum") {
        CHECK(samples_taken(rule, 4, [](unsigned k) { return k % 2 == 0 ? 1.0 : 0.0; }) == 64);
        // Whole rounds only: 9-sample rounds stop at 63, the last that fits.
        CHECK(samples_taken(rule, 9, [](unsigned k) { return k % 3 == 0 ? 1.0 : 0.0; }) == 63);
    }
    SECTION("an edge pixel stops once its mean is known well enough") {
        // Half black, half white: relative standard error 1 / sqrt(n - 1), at most 0.3 from n = 13,
        // so 16 in rounds of 4.
        const AdaptiveRule loose{.threshold = 0.3, .max_samples = 64};
        CHECK(samples_taken(loose, 4, [](unsigned k) { return k % 2 == 0 ? 1.0 : 0.0; }) == 16);
    }
    SECTION("a black pixel stops, a nearly black noisy one does not chase its mean") {
        CHECK(samples_taken(rule, 4, [](unsigned) { return 0.0; }) == 4);
        CHECK(samples_taken(rule, 4, [](unsigned k) { return k % 2 == 0 ? 1e-7 : 0.0; }) == 4);
        CHECK(samples_taken(rule, 4, [](unsigned k) { return k % 2 == 0 ? 0.1 : 0.0; }) > 4);
    }
    SECTION("one sample says nothing of the noise: it takes another") {
        CHECK(samples_taken(rule, 1, [](unsigned) { return 0.5; }) == 2);
    }
    SECTION("off, or no room for a round: the base count") {
        CHECK(samples_taken(AdaptiveRule{.threshold = 0, .max_samples = 64}, 4, [](unsigned k) { return double(k % 2); }) == 4);
        CHECK(samples_taken(AdaptiveRule{.threshold = 0.1, .max_samples = 7}, 4, [](unsigned k) { return double(k % 2); }) == 4);
    }
}

TEST_CASE("adaptive sampling off renders the uniform jittered grid of before", "[adaptive][render]") {
    // The loop render_image ran before adaptive sampling, written out: pixel p's stream, an n x n
    // jittered grid, the mean.
    const EdgeScene e;
    const RenderSettings s = edge_settings(4);
    const Camera<float> camera(e.camera);
    const PhotonMaps maps;
    const RadianceIntegrator<DefaultScene<float>> integrator(e.scene, maps, s);
    Film expected(s.width, s.height);
    ShadingContext ctx;
    for (unsigned y = 0; y < s.height; ++y)
        for (unsigned x = 0; x < s.width; ++x) {
            ctx.rng = Pcg32(s.seed ^ 0x706978656c73ULL, std::uint64_t(y) * s.width + x);
            Rgb<double> sum(0.0);
            for (unsigned i = 0; i < 4; ++i) {
                const Vec2<float> jitter = stratified(i, 2u, ctx.rng.uniform2<float>());
                if (const auto ray = camera.ray((float(x) + jitter.x) / float(s.width), (float(y) + jitter.y) / float(s.height),
                                                lens_sample(camera, ctx.rng)))
                    sum += Rgb<double>(integrator.radiance(*ray, 1, ctx));
            }
            expected.at(x, y) = Rgb<float>(sum / 4.0);
        }
    RenderStats stats;
    std::vector<std::uint32_t> counts;
    CHECK(identical(render_rt(e, s, stats, &counts), expected));
    CHECK(std::all_of(counts.begin(), counts.end(), [](std::uint32_t n) { return n == 4; }));
    CHECK(stats.pixel_samples.pixels == 32 * 24);
    CHECK(stats.pixel_samples.mean() == 4.0);
    CHECK(stats.pixel_samples.most == 4);
    // A threshold with no room for a second round changes nothing either.
    RenderSettings capped = s;
    capped.aa_threshold = 0.1f;
    capped.aa_max_samples = 7;
    RenderStats capped_stats;
    CHECK(identical(render_rt(e, capped, capped_stats), expected));
}

TEST_CASE("adaptive renders are the same on 1 and 2 threads in rt and pm", "[adaptive][render]") {
    const auto box = cornell::make_cornell_box<float>();
    for (const RenderMode mode : {RenderMode::rt, RenderMode::pm}) {
        INFO("mode " << to_string(mode));
        RenderSettings s;
        s.mode = mode;
        s.width = 32;
        s.height = 24;
        s.samples_per_pixel = 4;
        s.shadow_samples = 4;
        s.global_photons = 5'000;
        s.caustic_photons = 5'000;
        s.final_gather_rays = 16;
        s.aa_threshold = 0.1f;
        s.aa_max_samples = 32;
        s.threads = 1;
        const RenderResult one = render(box.scene, box.camera, s);
        s.threads = 2;
        const RenderResult two = render(box.scene, box.camera, s);
        CHECK(identical(one.film, two.film));
        CHECK(one.stats.pixel_samples.samples == two.stats.pixel_samples.samples);
        CHECK(one.stats.pixel_samples.most == two.stats.pixel_samples.most);
        // It did adapt: some pixels took more than the base, none more than the maximum.
        CHECK(one.stats.pixel_samples.mean() > 4.0);
        CHECK(one.stats.pixel_samples.most > 4);
        CHECK(one.stats.pixel_samples.most <= 32);
    }
}

TEST_CASE("adaptive sampling spends its samples at edges and beats a uniform render of as many samples",
          "[adaptive][render]") {
    const EdgeScene e;
    RenderStats judge_stats;
    const Film judge = render_rt(e, edge_settings(1024), judge_stats);

    RenderSettings a = edge_settings(4);
    a.aa_threshold = 0.05f;
    a.aa_max_samples = 64;
    RenderStats adaptive_stats;
    std::vector<std::uint32_t> counts;
    const Film adaptive = render_rt(e, a, adaptive_stats, &counts);
    const double mean_spp = adaptive_stats.pixel_samples.mean();
    // The uniform grid nearest in samples (9 against the adaptive render's ~9.3 here).
    const unsigned n = unsigned(std::lround(std::sqrt(mean_spp)));
    RenderStats uniform_stats;
    const Film uniform = render_rt(e, edge_settings(n * n), uniform_stats);
    const double ratio = double(adaptive_stats.pixel_samples.samples) / double(uniform_stats.pixel_samples.samples);
    REQUIRE(ratio > 0.8);
    REQUIRE(ratio < 1.25);
    const double adaptive_error = relative_mse(adaptive, judge), uniform_error = relative_mse(uniform, judge);
    INFO("adaptive: mean " << mean_spp << " spp, relative MSE " << adaptive_error << "; uniform: " << n * n
                           << " spp, relative MSE " << uniform_error);
    CHECK(mean_spp < 0.5 * a.aa_max_samples);  // most pixels stopped early
    CHECK(adaptive_error < 0.7 * uniform_error);

    // Edges and flats from the judge: a pixel differing from a 4-neighbour by over half its
    // luminance is at an edge; one within 0.1% of all its 8 neighbours is flat.
    double edge_sum = 0, flat_sum = 0;
    unsigned edges = 0, flats = 0;
    auto lum = [&](unsigned x, unsigned y) { return luminance(judge.at(x, y)); };
    for (unsigned y = 1; y + 1 < a.height; ++y)
        for (unsigned x = 1; x + 1 < a.width; ++x) {
            double lo = lum(x, y), hi = lo, cross = 0;
            for (int dy = -1; dy <= 1; ++dy)
                for (int dx = -1; dx <= 1; ++dx) {
                    const double l = lum(x + dx, y + dy);
                    lo = std::min(lo, l), hi = std::max(hi, l);
                    if (dx == 0 || dy == 0) cross = std::max(cross, std::abs(l - lum(x, y)));
                }
            const std::uint32_t c = counts[std::size_t(y) * a.width + x];
            if (cross > 0.5 * std::max(lum(x, y), 0.05)) edge_sum += c, ++edges;
            else if (hi - lo <= 1e-3 * std::max(hi, 1e-3)) flat_sum += c, ++flats;
        }
    REQUIRE(edges >= 20);
    REQUIRE(flats >= 20);
    INFO(edges << " edge pixels, mean " << edge_sum / edges << " samples; " << flats << " flat pixels, mean "
               << flat_sum / flats);
    CHECK(edge_sum / edges > 4 * (flat_sum / flats));
    CHECK(flat_sum / flats < 5);
}
