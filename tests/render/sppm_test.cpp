// SPDX-License-Identifier: MIT
// Stochastic progressive photon mapping (integrator/sppm.hpp) as the judge: it converges to a
// closed-form answer, its error falls with passes, it agrees with the path tracer where both can
// see the light, and it sees the caustic of a point light that the path tracer cannot.

#include <catch2/catch.hpp>

#include <photon/photon.hpp>

#include "../../examples/cornell_box.hpp"

#include "film_compare.hpp"
#include "render/pixel_of.hpp"

#include <cmath>
#include <vector>

#include "transport/furnace_sphere.hpp"

using namespace photon;

namespace {

using photon::testing::FurnaceSphere;

RenderSettings sppm_settings(unsigned width, unsigned height, unsigned passes, std::size_t photons) {
    RenderSettings s;
    s.mode = RenderMode::sppm;
    s.width = width;
    s.height = height;
    s.sppm_passes = passes;
    s.sppm_photons_per_pass = photons;
    s.max_photon_depth = 200;  // rho^200: the furnace's series is complete
    s.threads = 1;
    return s;
}

/// Root mean square of film / expected - 1 over the red channel.
double rms_relative_error(const Film& film, double expected) {
    double sum = 0;
    for (const auto& p : film.pixels()) sum += (p.x / expected - 1) * (p.x / expected - 1);
    return std::sqrt(sum / double(film.pixels().size()));
}

}  // namespace

TEST_CASE("sppm converges to the closed diffuse sphere's radiance, and its error falls with passes", "[sppm][heavy]") {
    const FurnaceSphere f;
    const double expected = FurnaceSphere::radiance();
    RenderSettings s = sppm_settings(32, 32, 32, 100'000);
    std::vector<double> error(s.sppm_passes + 1);
    RenderStats stats;
    const Film film = render_sppm(f.scene, f.camera, s, stats, [&](unsigned passes, const Film& image) {
        error[passes] = rms_relative_error(image, expected);
    });
    INFO("mean " << film.mean().x << " expected " << expected << "; rms error after 4 passes " << error[4]
                 << ", after 32 " << error[32]);
    // The photons' density is uniform here, so the radius adds no bias and the mean's error is
    // noise: half the light is exact (shadow rays), the other half comes from the ~16 000 photon
    // hits per pass on the part of the wall in view, 500 000 over 32 passes: 0.1% (measured:
    // +0.09%). 1% is ten times that, and small enough to catch a lost bounce (rho^n) or a wrong
    // normalisation (pi, alpha, R^2).
    CHECK(film.mean().x == Approx(expected).epsilon(0.01));
    // Noise falls as passes^-(alpha/2) = 8^-1/3 = 0.5 from 4 to 32 passes (measured 0.51).
    CHECK(error[32] < 0.75 * error[4]);
    CHECK(stats.sppm.passes == 32);
    CHECK(stats.sppm.emitted == 32u * 100'000u);
    CHECK(film.all_finite_nonnegative());
}

TEST_CASE("sppm gives the same image on 1 and 2 threads, and another for another seed", "[sppm]") {
    const auto box = cornell::make_cornell_box<float>();  // mirror and glass: every branch of the camera path
    RenderSettings s = sppm_settings(48, 36, 4, 20'000);
    s.max_photon_depth = 10;
    s.shadow_samples = 4;
    const RenderResult one = render(box.scene, box.camera, s);
    s.threads = 2;
    const RenderResult two = render(box.scene, box.camera, s);
    CHECK(identical(one.film, two.film));
    CHECK(one.stats.sppm.photon_hits == two.stats.sppm.photon_hits);
    CHECK(one.stats.rays.total() == two.stats.rays.total());
    CHECK(one.stats.sppm.mean_radius == two.stats.sppm.mean_radius);
    s.seed = 2;
    const RenderResult other = render(box.scene, box.camera, s);
    CHECK_FALSE(identical(one.film, other.film));
    CHECK(one.film.all_finite_nonnegative());
    CHECK(one.stats.mode == "sppm");
    CHECK(one.stats.sppm.passes == 4);
}

TEST_CASE("a cancelled sppm render stops after the current pass and is partial", "[sppm]") {
    const FurnaceSphere f;
    RenderSettings s = sppm_settings(16, 16, 10, 2'000);
    std::atomic<bool> cancel{false};
    s.cancel = &cancel;
    s.progress = [&](RenderPhase phase, double done) {
        CHECK(phase == RenderPhase::sppm_pass);
        if (done >= 0.2) cancel = true;  // during pass 2's report
    };
    const RenderResult r = render(f.scene, f.camera, s);
    CHECK(r.stats.partial);
    CHECK(r.stats.sppm.passes == 2);
    CHECK(r.film.mean().x > 0);
    cancel = true;
    const RenderResult none = render(f.scene, f.camera, s);
    CHECK(none.stats.partial);
    CHECK(none.stats.sppm.passes == 0);
    CHECK(none.film.mean().x == 0);
}

namespace {

/// A closed white box with a red and a blue wall, a diffuse ball on the floor and a sphere light
/// under the ceiling: every path is diffuse, so the path tracer sees all the light too.
struct DiffuseBox {
    DefaultScene<double> scene;
    PinholeCamera<double> camera = PinholeCamera<double>::look_at({0, 0.9, -2.0}, {0, 0.9, 0}, {0, 1, 0}, 60, 4.0 / 3.0);
    DiffuseBox() {
        const auto white = scene.add_material(Material<double>::lambertian(Rgb<double>(0.75)));
        const auto red = scene.add_material(Material<double>::lambertian({0.75, 0.25, 0.25}));
        const auto blue = scene.add_material(Material<double>::lambertian({0.25, 0.25, 0.75}));
        scene.add(Box<double>({-1.22, -0.02, -2.5}, {1.22, 0.0, 1.22}), white);   // floor
        scene.add(Box<double>({-1.22, 1.8, -2.5}, {1.22, 1.82, 1.22}), white);    // ceiling
        scene.add(Box<double>({-1.22, -0.02, 1.2}, {1.22, 1.82, 1.22}), white);   // back
        scene.add(Box<double>({-1.22, -0.02, -2.5}, {-1.2, 1.82, 1.22}), red);    // left
        scene.add(Box<double>({1.2, -0.02, -2.5}, {1.22, 1.82, 1.22}), blue);     // right
        scene.add(Box<double>({-1.22, -0.02, -2.52}, {1.22, 1.82, -2.5}), white); // front, behind the camera
        scene.add(Sphere<double>({0.35, 0.35, 0.3}, 0.35), white);
        scene.add_light(SphereLight<double>{.center = {-0.2, 1.5, 0}, .radius = 0.1, .power = Rgb<double>(30.0)});
        scene.commit();
    }
};

}  // namespace

TEST_CASE("sppm agrees with the path-traced reference on a diffuse box, block by block", "[sppm][heavy]") {
    const DiffuseBox box;
    RenderSettings ref = sppm_settings(32, 24, 1, 1);
    ref.mode = RenderMode::reference;
    ref.samples_per_pixel = 400;
    // Photons are followed as far as the path tracer's paths (max_photon_depth 200; at 10, the
    // pm default, 0.75^10 = 6% of the light that bounces on is lost, 2% of the image). The
    // automatic radius, two pixel footprints, is 18 cm in this coarse image and darkens the
    // corners' blocks by 4-5% (every visible point within R of an edge gathers over a disc that
    // hangs over it); 3 cm leaves that bias below the noise.
    RenderSettings pm = sppm_settings(32, 24, 32, 50'000);
    pm.shadow_samples = 1;
    pm.sppm_initial_radius = 0.03f;
    // Each mode twice with different seeds: the difference of a block's two means is noise
    // only, and its square halved estimates the variance of one block mean.
    std::vector<Rgb<double>> blocks[2][2];
    for (std::uint64_t seed : {1u, 2u}) {
        ref.seed = pm.seed = seed;
        blocks[0][seed - 1] = block_means(render(box.scene, box.camera, ref).film, 4, 4);
        blocks[1][seed - 1] = block_means(render(box.scene, box.camera, pm).film, 4, 4);
    }
    // The relative noise of a block mean, pooled over blocks and channels (one difference per
    // block is too few to estimate each block's alone).
    double noise2[2] = {0, 0};
    for (int m = 0; m < 2; ++m) {
        for (std::size_t b = 0; b < 16; ++b)
            for (int c = 0; c < 3; ++c) {
                const double a = blocks[m][0][b][c], d = blocks[m][1][b][c];
                noise2[m] += (a - d) * (a - d) / (2 * ((a + d) / 2) * ((a + d) / 2)) / 48.0;
            }
    }
    // The two renders' average against the other's: its variance is half of each one's.
    const double sigma = std::sqrt((noise2[0] + noise2[1]) / 2);
    double worst = 0;
    for (std::size_t b = 0; b < 16; ++b)
        for (int c = 0; c < 3; ++c) {
            const double r = (blocks[0][0][b][c] + blocks[0][1][b][c]) / 2, p = (blocks[1][0][b][c] + blocks[1][1][b][c]) / 2;
            worst = std::max(worst, std::abs(p / r - 1));
        }
    INFO("relative noise of a block mean: reference " << std::sqrt(noise2[0]) << ", sppm " << std::sqrt(noise2[1])
                                                      << "; largest block difference " << worst << " = " << worst / sigma
                                                      << " sigma");
    CHECK(worst < 4 * sigma);
}

namespace {

/// A glass ball (ior 1.5) just above a dark floor, under a point light 40 degrees above the
/// horizon, and a camera looking down on the ball's shadow, where the ball focuses the light.
struct GlassBall {
    static constexpr double R = 0.5, ior = 1.5, rho = 0.2, Phi = 100.0;
    static constexpr unsigned width = 64, height = 48;
    Vec3<double> center{0, 0.6, 0}, light;
    DefaultScene<double> scene;
    PinholeCamera<double> camera =
        PinholeCamera<double>::look_at({1.4, 3.5, 0}, {0.8, 0, 0}, {0, 0, 1}, 40, double(width) / height);
    GlassBall() {
        const double elevation = 40 * pi<double> / 180;
        light = center + 4.0 * Vec3<double>{-std::cos(elevation), std::sin(elevation), 0};
        scene.add(Plane<double>({0, 1, 0}, 0), scene.add_material(Material<double>::lambertian(Rgb<double>(rho))));
        scene.add(Sphere<double>(center, R), scene.add_material(Material<double>::glass(ior)));
        scene.add_light(PointLight<double>{light, Rgb<double>(Phi)});
        scene.commit();
    }
    /// Where a ray from `origin` along unit `d` enters the ball, if it does.
    [[nodiscard]] std::optional<double> enters_ball(const Vec3<double>& origin, const Vec3<double>& d) const {
        const Vec3<double> oc = origin - center;
        const double b = glm::dot(oc, d), disc = b * b - (glm::dot(oc, oc) - R * R);
        if (disc < 0 || -b - std::sqrt(disc) <= 0) return std::nullopt;
        return -b - std::sqrt(disc);
    }
    [[nodiscard]] bool in_shadow(const Vec3<double>& p) const {
        const Vec3<double> to_light = light - p;
        const auto t = enters_ball(p, glm::normalize(to_light));
        return t && *t < glm::length(to_light);
    }
    /// The pixel that sees floor point p, if any.
    [[nodiscard]] std::optional<std::size_t> pixel_of(const Vec3<double>& p) const {
        return testing::pixel_of(camera, p, width, height);
    }
};

}  // namespace

TEST_CASE("sppm renders the caustic of a point light through a glass ball, which the path tracer cannot", "[sppm][heavy]") {
    const GlassBall ball;
    // The measuring window: pixels whose centre and four corners see the floor itself inside the
    // ball's shadow, with the floor area each covers (a quadrilateral, from its corners' rays).
    std::vector<double> area(std::size_t(GlassBall::width) * GlassBall::height, 0.0);
    auto floor_point = [&](double u, double v) -> std::optional<Vec3<double>> {
        const auto hit = ball.scene.intersect(*ball.camera.ray(u, v));
        if (!hit || hit->object != 0 || !ball.in_shadow(hit->hit.point)) return std::nullopt;
        return hit->hit.point;
    };
    for (unsigned y = 0; y < GlassBall::height; ++y)
        for (unsigned x = 0; x < GlassBall::width; ++x) {
            auto at = [&](double dx, double dy) { return floor_point((x + dx) / GlassBall::width, (y + dy) / GlassBall::height); };
            const auto a = at(0, 0), b = at(1, 0), c = at(1, 1), d = at(0, 1);
            if (!at(0.5, 0.5) || !a || !b || !c || !d) continue;
            area[std::size_t(y) * GlassBall::width + x] = 0.5 * glm::length(glm::cross(*c - *a, *d - *b));
        }
    // Expected: the flux of L S S D paths (in and out of the ball, (1 - F_in)(1 - F_out) of it)
    // that land in the window, by quadrature over the cone of directions the ball subtends.
    const double intensity = GlassBall::Phi / (4 * pi<double>);
    const Vec3<double> axis = glm::normalize(ball.center - ball.light);
    const double cos_max = std::sqrt(1 - GlassBall::R * GlassBall::R / glm::dot(ball.center - ball.light, ball.center - ball.light));
    const Frame<double> frame = Frame<double>::from_normal(axis);
    constexpr unsigned n = 400;
    const double d_omega = 2 * pi<double> * (1 - cos_max) / (n * n);
    double expected = 0;
    for (unsigned i = 0; i < n; ++i)
        for (unsigned j = 0; j < n; ++j) {
            const double cos_b = 1 - (1 - cos_max) * (i + 0.5) / n, phi = 2 * pi<double> * (j + 0.5) / n;
            const double sin_b = std::sqrt(1 - cos_b * cos_b);
            const Vec3<double> d = frame.to_world({sin_b * std::cos(phi), sin_b * std::sin(phi), cos_b});
            const auto t = ball.enters_ball(ball.light, d);
            if (!t) continue;
            const Vec3<double> p1 = ball.light + *t * d, n1 = (p1 - ball.center) / GlassBall::R;
            const double f1 = fresnel_dielectric(-glm::dot(d, n1), 1.0, GlassBall::ior);
            const Vec3<double> d2 = *refract(d, n1, 1 / GlassBall::ior);
            const Vec3<double> p2 = p1 - 2 * glm::dot(p1 - ball.center, d2) * d2, n2 = (p2 - ball.center) / GlassBall::R;
            const double f2 = fresnel_dielectric(glm::dot(d2, n2), GlassBall::ior, 1.0);
            const auto d3 = refract(d2, -n2, GlassBall::ior);
            if (!d3 || !(d3->y < 0)) continue;
            const auto pixel = ball.pixel_of(p2 - p2.y / d3->y * *d3);
            if (pixel && area[*pixel] > 0) expected += intensity * d_omega * (1 - f1) * (1 - f2);
        }
    REQUIRE(expected > 0);

    RenderSettings s = sppm_settings(GlassBall::width, GlassBall::height, 32, 400'000);
    // Three surface hits: L S S D. Longer paths (internal reflections, floor -> ball -> floor)
    // would add light the quadrature leaves out.
    s.max_photon_depth = 3;
    const RenderResult sppm = render(ball.scene, ball.camera, s);
    s.mode = RenderMode::rt;
    s.samples_per_pixel = 4;
    const RenderResult rt = render(ball.scene, ball.camera, s);
    s.mode = RenderMode::reference;
    s.samples_per_pixel = 64;
    const RenderResult reference = render(ball.scene, ball.camera, s);
    // Flux = sum of radiance * pi / rho * area over the window (the floor is Lambertian).
    auto window_flux = [&](const Film& film) {
        double flux = 0;
        for (std::size_t i = 0; i < area.size(); ++i) flux += double(film.pixels()[i].x) * pi<double> / GlassBall::rho * area[i];
        return flux;
    };
    std::size_t brightest = 0;
    for (std::size_t i = 0; i < area.size(); ++i)
        if (area[i] > 0 && sppm.film.pixels()[i].x > sppm.film.pixels()[brightest].x) brightest = i;
    const double lit_floor = rt.film.at(GlassBall::width - 1, GlassBall::height / 2).x;  // beside the shadow
    INFO("window flux: sppm " << window_flux(sppm.film) << " W, expected " << expected << " W, rt "
                              << window_flux(rt.film) << ", reference " << window_flux(reference.film)
                              << "; brightest window pixel " << sppm.film.pixels()[brightest].x << " (rt "
                              << rt.film.pixels()[brightest].x << ", reference " << reference.film.pixels()[brightest].x
                              << "), the lit floor " << lit_floor);
    // 32 x 400 000 photons put ~50 000 through the ball (1% noise); the rest of the tolerance is
    // for what the quadrature leaves out: Fresnel reflections off the ball that reach the window
    // and floor -> ball -> floor light (rho 0.2), about 1% each.
    CHECK(window_flux(sppm.film) == Approx(expected).epsilon(0.05));
    // rt, as POV-Ray without photons: its shadow rays pass the glass straight, filtered
    // (filtered_shadow.hpp), so the shadow is lit as if the ball were not there: no focus.
    CHECK(window_flux(rt.film) > 0);
    CHECK(rt.film.pixels()[brightest].x < 3 * lit_floor);
    CHECK(window_flux(reference.film) < 0.1 * expected);
    CHECK(sppm.film.pixels()[brightest].x > 3 * lit_floor);  // a focused spot, brighter than the lit floor
    CHECK(reference.film.pixels()[brightest].x < 0.1 * sppm.film.pixels()[brightest].x);
}
