// SPDX-License-Identifier: MIT
// Colour bleeding from a convex diffuse object. A final-gather ray that lands on a ball reads the
// irradiance precomputed at the nearest photon there, after a visibility test; on a convex
// surface the straight chord to that sample runs inside the ball, so every sample was rejected
// and the ball's bounce light read black: a red ball left no red on the white floor around it.

#include <catch2/catch.hpp>

#include <photon/photon.hpp>

#include <utility>
#include <vector>

using namespace photon;

namespace {

struct RedBall {
    DefaultScene<float> scene;
    PinholeCamera<float> camera =
        PinholeCamera<float>::look_at({0, 0.6f, -1.6f}, {0, 0.2f, 0}, {0, 1, 0}, 60.0f, 4.0f / 3.0f);

    RedBall() {
        scene.add(Box<float>({-3, -0.1f, -3}, {3, 0, 3}), scene.add_material(Material<float>::lambertian(Rgb<float>(0.75f))));
        scene.add(Sphere<float>({0, 0.4f, 0}, 0.4f),
                  scene.add_material(Material<float>::lambertian({0.8f, 0.1f, 0.1f})));
        scene.add_light(SphereLight<float>{.center = {0.9f, 1.6f, -0.6f}, .radius = 0.05f, .power = Rgb<float>(40.0f)});
        scene.commit();
    }
};

/// Mean red and green of the floor's pixels in the image's lower quarter (all floor next to the ball).
Rgb<double> lower_floor_mean(const Film& film) {
    Rgb<double> sum(0.0);
    unsigned n = 0;
    for (unsigned y = film.height() * 3 / 4; y < film.height(); ++y)
        for (unsigned x = 0; x < film.width(); ++x, ++n) sum += Rgb<double>(film.at(x, y));
    return sum / double(n);
}

}  // namespace

TEST_CASE("a red diffuse ball bleeds red onto the floor through precomputed irradiance", "[transport][bleeding]") {
    const RedBall b;
    RenderSettings s;
    s.width = 48, s.height = 36, s.samples_per_pixel = 1;
    s.global_photons = 100'000;
    s.final_gather_rays = 64;
    s.irradiance_cache_error = 0;  // a gather at every pixel: the lookups alone differ
    s.threads = 2;
    s.irradiance_stride = 4;
    const Rgb<double> precomputed = lower_floor_mean(render(b.scene, b.camera, s).film);
    s.irradiance_stride = 0;  // a full density estimate per gather ray: no visibility test involved
    const Rgb<double> estimated = lower_floor_mean(render(b.scene, b.camera, s).film);
    INFO("floor red/green: precomputed " << precomputed.x << " / " << precomputed.y << ", per-ray estimate "
                                         << estimated.x << " / " << estimated.y);
    // The floor is white and the ball reflects 0.8 red but 0.1 green, so red minus green is
    // (nearly all) the ball's bounce light.
    const double red_excess = estimated.x - estimated.y, precomputed_red_excess = precomputed.x - precomputed.y;
    CHECK(red_excess > 0.02 * estimated.y);
    // Both read the same global map; they differ by the precomputation's nearest-sample
    // approximation and the gathers' noise (the same random numbers), a few per cent of the
    // excess here. Rejecting every sample on the ball left the excess at about 0.
    CHECK(precomputed_red_excess == Approx(red_excess).epsilon(0.15));
    CHECK(precomputed.y == Approx(estimated.y).epsilon(0.03));
}

TEST_CASE("the ball's underside at its contact with the floor is not lit by the open floor's photons", "[transport][bleeding]") {
    // The ball's lowest band of pixels sees the floor's crevice around the contact at distances
    // well under the global map's estimate radius; read there, the map blurred the open floor's
    // light into the crevice and the band came out 18% to 60% too bright (issue 47, three seeds).
    // Gather hits that near are traced on instead. The judge: sppm, consistent.
    const RedBall b;
    RenderSettings s;
    s.width = 160, s.height = 120, s.threads = 2;
    s.mode = RenderMode::sppm;
    s.sppm_passes = 256;
    s.sppm_photons_per_pass = 100'000;
    const Film judge = render(b.scene, b.camera, s).film;
    // The band: in the middle half of the ball's columns, the 3 rows above its lowest pixel.
    std::vector<std::pair<unsigned, unsigned>> band;
    std::vector<unsigned> columns;
    for (unsigned x = 0; x < judge.width(); ++x)
        for (unsigned y = 0; y < judge.height(); ++y)
            if (judge.at(x, y).x > 3 * judge.at(x, y).y + 1e-6f) {
                columns.push_back(x);
                break;
            }
    REQUIRE(columns.size() > 20);
    for (std::size_t i = columns.size() / 4; i < 3 * columns.size() / 4; ++i) {
        const unsigned x = columns[i];
        unsigned lowest = 0;
        for (unsigned y = 0; y < judge.height(); ++y)
            if (judge.at(x, y).x > 3 * judge.at(x, y).y + 1e-6f) lowest = y;
        for (unsigned y = lowest - 3; y < lowest; ++y) band.emplace_back(x, y);
    }
    auto band_mean = [&](const Film& f) {
        double sum = 0;
        for (const auto& [x, y] : band) sum += double(f.at(x, y).x) + f.at(x, y).y + f.at(x, y).z;
        return sum / double(band.size());
    };
    s.mode = RenderMode::pm;
    for (std::uint64_t seed : {1u, 2u, 3u}) {
        s.seed = seed;
        const double ratio = band_mean(render(b.scene, b.camera, s).film) / band_mean(judge);
        INFO("seed " << seed << ": the band at " << ratio << " of the judge's, " << band.size() << " pixels");
        CHECK(ratio == Approx(1.0).margin(0.1));
    }
}
