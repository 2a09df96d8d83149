// SPDX-License-Identifier: MIT
// A tilted shading normal (texture/normal_pattern.hpp) rendered by every mode: direct light on a
// floor whose shading normal leans by a known angle is Lambert's law with that normal, exactly,
// in rt, pm and the path tracer; and in a closed box with a leaning floor and a bumpy wall,
// where photons, gathers and paths must use the same normal, pm and sppm agree with the path
// tracer block by block.

#include <catch2/catch.hpp>

#include <photon/photon.hpp>

#include "film_compare.hpp"

#include <cmath>
#include <vector>

using namespace photon;

namespace {

/// The slope of `gradient x` (bump size `amount`) over a pattern scaled 10 times and moved so
/// that its ramp does not wrap within 4 m of the origin: the same tilt everywhere, the shading
/// normal of an upward surface leaning to -x by tan = 5 * amount * 0.02 * 4/3 (POV-Ray's slope
/// over its tetrahedron, tests/texture/normal_pattern_test.cpp).
template <Scalar S> AnyNormalField<S> leaning(double amount) {
    NormalPattern np;
    np.kind = NormalKind::slope;
    np.pattern = Pattern::of(PatternKind::gradient);
    np.amount = amount;
    const Affine<double> placement = Affine<double>::scale({10, 10, 10}).then(Affine<double>::translate({-5, 0, 0}));
    return AnyNormalField<S>(NormalPerturbation<S>(np, placement));
}
double lean_tangent(double amount) { return 5.0 * amount * 0.02 * 4.0 / 3.0; }

template <Scalar S> struct LeaningFloor {
    static constexpr double rho = 0.5, power = 40.0, amount = 3.0;
    Vec3<double> light{0.3, 1.5, 0.2};
    DefaultScene<S> scene;
    PinholeCamera<S> camera = PinholeCamera<S>::look_at({S(0), S(2.5), S(-2.5)}, {S(0), S(0), S(0.3)},
                                                        {S(0), S(1), S(0)}, S(60), S(32.0 / 24.0));
    LeaningFloor() {
        MaterialParams<S> floor{.diffuse = Rgb<S>(S(rho))};
        floor.normal_field = leaning<S>(amount);
        scene.add(Plane<S>({0, 1, 0}, S(0)), scene.add_material(Material<S>(floor)));
        scene.add_light(PointLight<S>{Vec3<S>(light), Rgb<S>(S(power))});
        // A light under the floor: the leaning normal faces it a little, but light from below
        // the geometric surface must not reach the top.
        scene.add_light(PointLight<S>{Vec3<S>(S(-2.0), S(-0.3), S(0.1)), Rgb<S>(S(power))});
        scene.commit();
    }
    /// Lambert's law with the leaning normal (or, `flat`, the geometric one) at the centre of pixel (x, y).
    [[nodiscard]] double expected(unsigned x, unsigned y, unsigned width, unsigned height, bool flat = false) const {
        const auto c = PinholeCamera<double>::look_at({0, 2.5, -2.5}, {0, 0, 0.3}, {0, 1, 0}, 60, 32.0 / 24.0);
        const Ray<double> ray = *c.ray((x + 0.5) / width, (y + 0.5) / height);
        const Vec3<double> p = ray.at(-ray.origin.y / ray.direction.y);
        const Vec3<double> to_light = light - p;
        const double d2 = glm::dot(to_light, to_light);
        const Vec3<double> n = glm::normalize(Vec3<double>(flat ? 0.0 : -lean_tangent(amount), 1, 0));
        const double cos_theta = std::max(0.0, glm::dot(n, to_light) / std::sqrt(d2));
        return rho / pi<double> * (power / (4 * pi<double>)) * cos_theta / d2;
    }
};

RenderSettings normal_test_settings(RenderMode mode) {
    RenderSettings s;
    s.mode = mode;
    s.width = 32;
    s.height = 24;
    s.samples_per_pixel = 1;
    s.shadow_samples = 1;
    s.global_photons = 20'000;
    s.caustic_photons = 20'000;
    s.final_gather_rays = 16;
    s.sppm_passes = 2;
    s.sppm_photons_per_pass = 10'000;
    s.threads = 2;
    return s;
}

}  // namespace

// sppm is left out here: its camera rays sample the whole pixel (progressive_pixel_sample), not
// its centre; the box below compares it.
TEMPLATE_TEST_CASE("direct light under a leaning shading normal is Lambert's law with it, in rt, pm and the path tracer",
                   "[render][normal]", float, double) {
    using S = TestType;
    const LeaningFloor<S> floor;
    // How much the lean changes the image: what a mode ignoring it would be off by.
    double lean_effect = 0;
    for (unsigned y = 0; y < 24; ++y)
        for (unsigned x = 0; x < 32; ++x)
            lean_effect = std::max(lean_effect, std::abs(floor.expected(x, y, 32, 24) / floor.expected(x, y, 32, 24, true) - 1));
    INFO("the lean changes a pixel by up to " << lean_effect * 100 << "%");
    CHECK(lean_effect > 0.2);
    for (const RenderMode mode : {RenderMode::rt, RenderMode::pm, RenderMode::reference}) {
        const RenderResult r = render(floor.scene, floor.camera, normal_test_settings(mode));
        REQUIRE(r.film.all_finite_nonnegative());
        double worst = 0, worst_exact = 0, worst_got = 0;
        for (unsigned y = 0; y < r.film.height(); ++y)
            for (unsigned x = 0; x < r.film.width(); ++x) {
                const double exact = floor.expected(x, y, r.film.width(), r.film.height());
                for (int c = 0; c < 3; ++c) {
                    const double e = std::abs(double(r.film.at(x, y)[c]) - exact) / std::max(exact, 1e-3);
                    if (e > worst) worst = e, worst_exact = exact, worst_got = r.film.at(x, y)[c];
                }
            }
        INFO("mode " << to_string(mode) << ": worst pixel off by " << worst * 100 << "% (" << worst_got
                     << " for " << worst_exact << ")");
        CHECK(worst < 0.01);
    }
}

namespace {

/// A closed white box with a red and a blue wall, lit by a sphere light: its floor's shading
/// normal leans towards the red wall (so the floor sees more of it, and less of the light), and
/// its back wall is bumpy. Every path is diffuse, so the path tracer sees all the light.
struct LeaningBox {
    DefaultScene<double> scene;
    PinholeCamera<double> camera = PinholeCamera<double>::look_at({0, 0.9, -2.0}, {0, 0.6, 0}, {0, 1, 0}, 60, 4.0 / 3.0);
    explicit LeaningBox(bool bumpy) {
        MaterialParams<double> floor{.diffuse = Rgb<double>(0.75)};
        MaterialParams<double> back{.diffuse = Rgb<double>(0.75)};
        if (bumpy) {
            floor.normal_field = leaning<double>(4.0);
            NormalPattern bumps;
            bumps.amount = 1.0;
            back.normal_field = AnyNormalField<double>(NormalPerturbation<double>(bumps, Affine<double>::scale({0.1, 0.1, 0.1})));
        }
        const auto white = scene.add_material(Material<double>::lambertian(Rgb<double>(0.75)));
        const auto red = scene.add_material(Material<double>::lambertian({0.75, 0.25, 0.25}));
        const auto blue = scene.add_material(Material<double>::lambertian({0.25, 0.25, 0.75}));
        scene.add(Box<double>({-1.22, -0.02, -2.5}, {1.22, 0.0, 1.22}), scene.add_material(Material<double>(floor)));
        scene.add(Box<double>({-1.22, 1.8, -2.5}, {1.22, 1.82, 1.22}), white);    // ceiling
        scene.add(Box<double>({-1.22, -0.02, 1.2}, {1.22, 1.82, 1.22}), scene.add_material(Material<double>(back)));
        scene.add(Box<double>({-1.22, -0.02, -2.5}, {-1.2, 1.82, 1.22}), red);    // left
        scene.add(Box<double>({1.2, -0.02, -2.5}, {1.22, 1.82, 1.22}), blue);     // right
        scene.add(Box<double>({-1.22, -0.02, -2.52}, {1.22, 1.82, -2.5}), white); // front, behind the camera
        scene.add_light(SphereLight<double>{.center = {0.2, 1.5, 0}, .radius = 0.1, .power = Rgb<double>(30.0)});
        scene.commit();
    }
};

}  // namespace

TEST_CASE("under leaning and bumpy shading normals, pm and sppm agree with the path tracer block by block",
          "[render][normal][heavy]") {
    const LeaningBox box(true);
    RenderSettings ref = normal_test_settings(RenderMode::reference);
    ref.samples_per_pixel = 256;
    ref.threads = 2;
    RenderSettings sppm = normal_test_settings(RenderMode::sppm);
    sppm.sppm_passes = 16;
    sppm.sppm_photons_per_pass = 50'000;
    sppm.max_photon_depth = 200;
    sppm.sppm_initial_radius = 0.03f;
    RenderSettings pm = normal_test_settings(RenderMode::pm);
    pm.global_photons = 200'000;
    pm.final_gather_rays = 64;
    pm.shadow_samples = 16;
    pm.samples_per_pixel = 4;
    pm.max_photon_depth = 200;
    // Each mode twice with different seeds: half the squared difference of a block's two means
    // estimates the variance of one block mean (pooled over blocks and channels).
    std::vector<Rgb<double>> blocks[3][2];
    RenderSettings* modes[3] = {&ref, &sppm, &pm};
    for (std::uint64_t seed : {1u, 2u})
        for (int m = 0; m < 3; ++m) {
            modes[m]->seed = seed;
            blocks[m][seed - 1] = block_means(render(box.scene, box.camera, *modes[m]).film, 4, 4);
        }
    double noise2[3] = {0, 0, 0};
    for (int m = 0; m < 3; ++m)
        for (std::size_t b = 0; b < 16; ++b)
            for (int c = 0; c < 3; ++c) {
                const double a = blocks[m][0][b][c], d = blocks[m][1][b][c];
                noise2[m] += (a - d) * (a - d) / (2 * ((a + d) / 2) * ((a + d) / 2)) / 48.0;
            }
    const auto mean_of = [&](int m, std::size_t b, int c) { return (blocks[m][0][b][c] + blocks[m][1][b][c]) / 2; };
    // The same box with flat normals: how far the normals move each block, so that the
    // agreement below is known to be far tighter than what a pass ignoring them would miss by.
    const LeaningBox flat(false);
    ref.seed = 1;
    const auto flat_blocks = block_means(render(flat.scene, flat.camera, ref).film, 4, 4);
    double moved = 0;
    for (std::size_t b = 0; b < 16; ++b)
        for (int c = 0; c < 3; ++c) moved = std::max(moved, std::abs(flat_blocks[b][c] / mean_of(0, b, c) - 1));
    for (int m = 1; m < 3; ++m) {
        const double sigma = std::sqrt((noise2[0] + noise2[m]) / 2);
        double worst = 0;
        for (std::size_t b = 0; b < 16; ++b)
            for (int c = 0; c < 3; ++c) worst = std::max(worst, std::abs(mean_of(m, b, c) / mean_of(0, b, c) - 1));
        INFO((m == 1 ? "sppm" : "pm") << ": relative noise of a block mean " << std::sqrt(noise2[m]) << " (reference "
                                      << std::sqrt(noise2[0]) << "); largest block difference " << worst << " = "
                                      << worst / sigma << " sigma; flat normals move a block by up to " << moved);
        CHECK(worst < std::max(4 * sigma, 0.03));
        CHECK(worst < moved / 4);
    }
}
