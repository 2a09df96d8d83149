// SPDX-License-Identifier: MIT
// A textured surface rendered by photon mapping against the consistent judge (sppm), square by
// square of a checker floor; and a constant material rendering exactly as before textures existed.

#include <catch2/catch.hpp>

#include <photon/photon.hpp>

#include <cmath>
#include <map>
#include <vector>

#include "film_compare.hpp"

using namespace photon;

namespace {

/// A closed white box whose floor is a checker of 0.6 m squares, cream and dark blue, under a
/// sphere light; the camera looks down at the floor. Every square's light depends on the
/// reflectance where photons land (the walls' bounce light is the floor's colours, mixed) and
/// where the camera looks.
struct CheckerBox {
    static constexpr double square = 0.6;
    DefaultScene<double> scene;
    PinholeCamera<double> camera = PinholeCamera<double>::look_at({0, 1.25, -1.1}, {0, 0, 0.2}, {0, 1, 0}, 75, 4.0 / 3.0);
    explicit CheckerBox(bool textured = true) {
        const Rgb<double> cream(0.8, 0.75, 0.6), blue(0.1, 0.12, 0.45);
        const auto floor = scene.add_material(
            textured ? Material<double>::lambertian(Pigment<double>::checker(cream, blue, Affine<double>::scale(Vec3<double>(square))))
                     : Material<double>::lambertian((cream + blue) * 0.5));
        const auto white = scene.add_material(Material<double>::lambertian(Rgb<double>(0.7)));
        scene.add(Box<double>({-1.2, -0.02, -1.2}, {1.2, 0.0, 1.2}), floor);
        scene.add(Box<double>({-1.2, 1.8, -1.2}, {1.2, 1.82, 1.2}), white);
        scene.add(Box<double>({-1.2, -0.02, 1.2}, {1.2, 1.82, 1.22}), white);
        scene.add(Box<double>({-1.2, -0.02, -1.22}, {1.2, 1.82, -1.2}), white);
        scene.add(Box<double>({-1.22, -0.02, -1.2}, {-1.2, 1.82, 1.2}), white);
        scene.add(Box<double>({1.2, -0.02, -1.2}, {1.22, 1.82, 1.2}), white);
        scene.add_light(SphereLight<double>{.center = {-0.3, 1.55, 0.2}, .radius = 0.1, .power = Rgb<double>(30.0)});
        scene.commit();
    }
    /// The checker square each pixel centre sees on the floor, -1 for other surfaces and for
    /// points within 6 cm of a square's edge (where a density estimate's disc spans two squares).
    [[nodiscard]] std::vector<int> squares(unsigned width, unsigned height) const {
        std::vector<int> out(std::size_t(width) * height, -1);
        for (unsigned y = 0; y < height; ++y)
            for (unsigned x = 0; x < width; ++x) {
                const auto hit = scene.intersect(*camera.ray((x + 0.5) / width, (y + 0.5) / height));
                if (!hit || hit->object != 0) continue;
                const Vec3<double> p = hit->hit.point / square;
                const double fx = p.x - std::floor(p.x), fz = p.z - std::floor(p.z), margin = 0.06 / square;
                if (fx < margin || fx > 1 - margin || fz < margin || fz > 1 - margin) continue;
                out[std::size_t(y) * width + x] = int(std::floor(p.x) + 2) * 8 + int(std::floor(p.z) + 2);
            }
        return out;
    }
};

std::map<int, Rgb<double>> square_means(const Film& film, const std::vector<int>& square) {
    std::map<int, Rgb<double>> sum;
    std::map<int, int> count;
    for (std::size_t i = 0; i < square.size(); ++i)
        if (square[i] >= 0) sum[square[i]] += Rgb<double>(film.pixels()[i]), ++count[square[i]];
    for (auto& [k, v] : sum) v /= double(count[k]);
    return sum;
}

}  // namespace

TEST_CASE("a checker floor's photon-mapped radiance matches sppm square by square", "[texture][render][heavy]") {
    const CheckerBox box;
    constexpr unsigned width = 48, height = 36;
    const std::vector<int> square = box.squares(width, height);
    RenderSettings pm;
    pm.width = width, pm.height = height, pm.threads = 1;
    pm.global_photons = 100'000;
    pm.caustic_photons = 0;
    pm.final_gather_rays = 64;
    pm.samples_per_pixel = 4;
    RenderSettings judge = pm;
    judge.mode = RenderMode::sppm;
    judge.sppm_passes = 24;
    judge.sppm_photons_per_pass = 50'000;
    judge.sppm_initial_radius = 0.03f;
    judge.shadow_samples = 4;
    // Two seeds per mode: half the squared difference of a square's two means is its variance.
    std::map<int, Rgb<double>> means[2][2];
    for (std::uint64_t seed : {1u, 2u}) {
        pm.seed = judge.seed = seed;
        means[0][seed - 1] = square_means(render(box.scene, box.camera, pm).film, square);
        means[1][seed - 1] = square_means(render(box.scene, box.camera, judge).film, square);
    }
    REQUIRE(means[0][0].size() >= 8);  // the camera sees at least 8 squares' insides
    double noise2[2] = {0, 0};
    std::size_t samples = 0;
    for (const auto& [k, unused] : means[0][0]) {
        for (int m = 0; m < 2; ++m)
            for (int c = 0; c < 3; ++c) {
                const double a = means[m][0][k][c], d = means[m][1][k][c];
                noise2[m] += (a - d) * (a - d) / (2 * ((a + d) / 2) * ((a + d) / 2));
            }
        samples += 3;
    }
    // Relative noise of the two-seed average of pm against sppm's.
    const double sigma = std::sqrt((noise2[0] + noise2[1]) / double(samples) / 2);
    double worst = 0, dark = 1e9, bright = 0;
    for (const auto& [k, unused] : means[0][0])
        for (int c = 0; c < 3; ++c) {
            const double p = (means[0][0][k][c] + means[0][1][k][c]) / 2, j = (means[1][0][k][c] + means[1][1][k][c]) / 2;
            worst = std::max(worst, std::abs(p / j - 1));
            if (c == 0) dark = std::min(dark, j), bright = std::max(bright, j);
        }
    INFO("relative noise of a square's mean: pm " << std::sqrt(noise2[0] / double(samples)) << ", sppm "
                                                  << std::sqrt(noise2[1] / double(samples)) << "; worst square "
                                                  << worst << " = " << worst / sigma << " sigma");
    // The squares differ as their reflectances do (0.8 against 0.1 in red): the texture is seen.
    CHECK(bright > 4 * dark);
    // pm's density estimates and final gathers carry a small bias of their own (docs/accuracy.md);
    // 2% is allowed for it on top of four standard deviations of noise.
    CHECK(worst < 4 * sigma + 0.02);
}

TEST_CASE("an untextured material renders bit for bit as a constant one always did", "[texture][render]") {
    // The same constant floor built twice, as Material::lambertian(Rgb) and through params, renders
    // identically; and a texture whose colours are all that constant renders the same image too
    // (the texture is read where the constant was).
    const CheckerBox plain(false);
    RenderSettings s;
    s.width = 24, s.height = 18, s.threads = 2;
    s.global_photons = 20'000, s.caustic_photons = 0, s.final_gather_rays = 16;
    const Film a = render(plain.scene, plain.camera, s).film;
    s.threads = 1;
    CHECK(identical(a, render(plain.scene, plain.camera, s).film));

    DefaultScene<double> same_texture;
    {
        const Rgb<double> mid = (Rgb<double>(0.8, 0.75, 0.6) + Rgb<double>(0.1, 0.12, 0.45)) * 0.5;
        CheckerBox copy(false);
        // Rebuild the plain box with its floor textured by a checker of two equal colours.
        const auto floor = same_texture.add_material(Material<double>::lambertian(Pigment<double>::checker(mid, mid)));
        const auto white = same_texture.add_material(Material<double>::lambertian(Rgb<double>(0.7)));
        for (std::size_t i = 0; i < copy.scene.objects().size(); ++i)
            same_texture.add(copy.scene.objects()[i].shape, i == 0 ? floor : white);
        same_texture.add_light(copy.scene.lights()[0]);
        same_texture.commit();
    }
    CHECK(identical(a, render(same_texture, plain.camera, s).film));
}
