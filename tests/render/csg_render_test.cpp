// SPDX-License-Identifier: MIT
// CSG in renders, judged by stochastic progressive photon mapping (the consistent estimator that
// sees every path) with its noise floor measured from two seeds: a glass lens made as the
// intersection of two spheres focuses a point light's caustic with the flux an independent
// quadrature (the two spherical faces traced analytically) predicts, and photon mapping agrees;
// a glass ball made of two CSG hemispheres casts the analytic ball's caustic; through an opaque
// CSG plate's hole, shadow rays (rt) and photons (sppm) light the floor alike.

#include <catch2/catch.hpp>

#include <photon/photon.hpp>

#include "render/pixel_of.hpp"

#include <cmath>
#include <functional>
#include <optional>
#include <vector>

using namespace photon;

namespace {

constexpr unsigned width = 48, height = 48;
constexpr double rho = 0.5, Phi = 100.0, ior = 1.5;

RenderSettings settings(RenderMode mode, std::uint64_t seed) {
    RenderSettings s;
    s.mode = mode;
    s.width = width;
    s.height = height;
    s.threads = 2;
    s.seed = seed;
    s.sppm_passes = 24;
    s.sppm_photons_per_pass = 200'000;
    s.caustic_photons = 1'000'000;
    s.global_photons = 200'000;
    s.max_photon_depth = 3;  // L S S D: the paths the quadrature counts
    s.samples_per_pixel = 4;
    return s;
}

/// The floor (y = 0) seen from above and aside, with the floor area each pixel covers inside a
/// disc of radius `window` about the origin (0 outside, or where the pixel sees anything else).
struct FloorView {
    PinholeCamera<double> camera;
    std::vector<double> area = std::vector<double>(std::size_t(width) * height, 0.0);

    FloorView(const DefaultScene<double>& scene, double window,
              PinholeCamera<double> eye = PinholeCamera<double>::look_at({2.2, 3.2, 0}, {0, 0, 0}, {0, 1, 0}, 30, 1.0))
        : camera(eye) {
        auto floor_point = [&](double u, double v) -> std::optional<Vec3<double>> {
            const auto hit = scene.intersect(*camera.ray(u, v));
            if (!hit || hit->object != 0 || glm::length(hit->hit.point) > window) return std::nullopt;
            return hit->hit.point;
        };
        for (unsigned y = 0; y < height; ++y)
            for (unsigned x = 0; x < width; ++x) {
                auto at = [&](double dx, double dy) { return floor_point((x + dx) / width, (y + dy) / height); };
                const auto a = at(0, 0), b = at(1, 0), c = at(1, 1), d = at(0, 1);
                if (!at(0.5, 0.5) || !a || !b || !c || !d) continue;
                area[std::size_t(y) * width + x] = 0.5 * glm::length(glm::cross(*c - *a, *d - *b));
            }
    }
    /// The pixel that sees floor point p, if any.
    [[nodiscard]] std::optional<std::size_t> pixel_of(const Vec3<double>& p) const {
        return testing::pixel_of(camera, p, width, height);
    }
    /// Flux landing in the window: radiance * pi / rho * area, summed (the floor is Lambertian).
    [[nodiscard]] double flux(const Film& film) const {
        double f = 0;
        for (std::size_t i = 0; i < area.size(); ++i) f += double(film.pixels()[i].x) * pi<double> / rho * area[i];
        return f;
    }
};

DefaultScene<double> floor_scene(const Vec3<double>& light, const std::function<void(DefaultScene<double>&)>& add) {
    DefaultScene<double> scene;
    scene.add(Plane<double>({0, 1, 0}, 0), scene.add_material(Material<double>::lambertian(Rgb<double>(rho))));
    add(scene);
    scene.add_light(PointLight<double>{light, Rgb<double>(Phi)});
    scene.commit();
    return scene;
}

/// Where the ray (o, unit d) meets the sphere (c, r): the near root if `near`, else the far one.
std::optional<Vec3<double>> sphere_root(const Vec3<double>& o, const Vec3<double>& d, const Vec3<double>& c, double r,
                                        bool near) {
    const Vec3<double> oc = o - c;
    const double b = glm::dot(oc, d), disc = b * b - (glm::dot(oc, oc) - r * r);
    if (disc < 0) return std::nullopt;
    const double t = near ? -b - std::sqrt(disc) : -b + std::sqrt(disc);
    if (!(t > 0)) return std::nullopt;
    return o + t * d;
}

}  // namespace

TEST_CASE("a glass CSG lens (two spheres intersected) focuses the caustic the analytic faces predict", "[csg][render][heavy]") {
    // Biconvex lens: unit spheres 1.4 apart, 0.6 thick, aperture radius sqrt(0.51); focal length
    // 1.11, so a light 3 above it is focused about 1.8 below it, on the floor.
    const Vec3<double> center{0, 1.8, 0}, light = center + Vec3<double>{0, 3, 0};
    const Vec3<double> upper_face = center - Vec3<double>{0, 0.7, 0}, lower_face = center + Vec3<double>{0, 0.7, 0};
    const auto scene = floor_scene(light, [&](DefaultScene<double>& s) {
        s.add(DefaultCsg<double>::intersection({Sphere<double>(upper_face, 1), Sphere<double>(lower_face, 1)}),
              s.add_material(Material<double>::glass(ior)));
    });
    const double window = 0.35;
    const FloorView view(scene, window);

    // Expected flux in the window: L S S D paths, by quadrature over the cone of directions the
    // lens's rim subtends, each path refracted by the two spherical faces (not by photon's CSG).
    const double aperture = std::sqrt(0.51), cos_max = 3 / std::sqrt(9 + 0.51);
    constexpr unsigned n = 400;
    const double d_omega = 2 * pi<double> * (1 - cos_max) / (n * n);
    const Frame<double> frame = Frame<double>::from_normal({0, -1, 0});
    double expected = 0;
    for (unsigned i = 0; i < n; ++i)
        for (unsigned j = 0; j < n; ++j) {
            const double cos_b = 1 - (1 - cos_max) * (i + 0.5) / n, phi = 2 * pi<double> * (j + 0.5) / n;
            const double sin_b = std::sqrt(1 - cos_b * cos_b);
            const Vec3<double> d = frame.to_world({sin_b * std::cos(phi), sin_b * std::sin(phi), cos_b});
            const auto p1 = sphere_root(light, d, upper_face, 1, true);
            if (!p1 || p1->y < center.y) continue;  // the upper face is the part above the rim
            const Vec3<double> n1 = *p1 - upper_face;
            const double f1 = fresnel_dielectric(-glm::dot(d, n1), 1.0, ior);
            const Vec3<double> d2 = *refract(d, n1, 1 / ior);
            const auto p2 = sphere_root(*p1, d2, lower_face, 1, false);
            if (!p2 || p2->y > center.y) continue;
            const Vec3<double> n2 = *p2 - lower_face;
            const double f2 = fresnel_dielectric(glm::dot(d2, n2), ior, 1.0);
            const auto d3 = refract(d2, -n2, ior);
            if (!d3 || !(d3->y < 0)) continue;
            const auto pixel = view.pixel_of(*p2 - p2->y / d3->y * *d3);
            if (pixel && view.area[*pixel] > 0) expected += Phi / (4 * pi<double>) * d_omega * (1 - f1) * (1 - f2);
        }
    REQUIRE(aperture > 0);
    REQUIRE(expected > 0);

    const RenderResult sppm = render(scene, view.camera, settings(RenderMode::sppm, 1));
    const RenderResult sppm2 = render(scene, view.camera, settings(RenderMode::sppm, 2));
    const RenderResult pm = render(scene, view.camera, settings(RenderMode::pm, 1));
    const double noise = std::abs(view.flux(sppm.film) - view.flux(sppm2.film)) / std::sqrt(2.0);
    INFO("window flux: expected " << expected << " W, sppm " << view.flux(sppm.film) << " and "
                                  << view.flux(sppm2.film) << " (seed noise " << noise << "), pm "
                                  << view.flux(pm.film));
    // Measured: sppm 0.38% above the quadrature (seed noise 0.11%); what the quadrature leaves
    // out (light reflected off the lens's faces into the window, floor -> lens -> floor) adds.
    CHECK(view.flux(sppm.film) == Approx(expected).epsilon(0.02));
    // Photon mapping's caustic estimate loses part of this sharply focused spot (measured -14%,
    // and more with a smaller max_radius; the analytic ball's wider caustic below is within 1%):
    // a property of its density estimate, not of the CSG, whose hits sppm just confirmed.
    CHECK(view.flux(pm.film) > 0.8 * view.flux(sppm.film));
    CHECK(sppm.film.all_finite_nonnegative());
    CHECK(pm.film.all_finite_nonnegative());
}

TEST_CASE("a glass ball merged from two CSG hemispheres casts the analytic ball's caustic", "[csg][render][heavy]") {
    const Vec3<double> center{0, 1.2, 0}, light = center + Vec3<double>{0.8, 3, 0};
    const auto analytic = floor_scene(light, [&](DefaultScene<double>& s) {
        s.add(Sphere<double>(center, 0.6), s.add_material(Material<double>::glass(ior)));
    });
    const auto halves = floor_scene(light, [&](DefaultScene<double>& s) {
        // Cut by a tilted plane through the centre: its inner disc must not show (merge).
        const Vec3<double> n = glm::normalize(Vec3<double>{1, 2, 0.5});
        DefaultCsg<double> lower = Plane<double>(n, glm::dot(n, center)), upper = lower;
        upper.invert();
        s.add(DefaultCsg<double>::merge({DefaultCsg<double>::intersection({Sphere<double>(center, 0.6), lower}),
                                         DefaultCsg<double>::intersection({Sphere<double>(center, 0.6), upper})}),
              s.add_material(Material<double>::glass(ior)));
    });
    const FloorView view(analytic, 0.6);
    const RenderResult a1 = render(analytic, view.camera, settings(RenderMode::sppm, 1));
    const RenderResult a2 = render(analytic, view.camera, settings(RenderMode::sppm, 2));
    const RenderResult c1 = render(halves, view.camera, settings(RenderMode::sppm, 3));
    const RenderResult cpm = render(halves, view.camera, settings(RenderMode::pm, 1));
    const RenderResult apm = render(analytic, view.camera, settings(RenderMode::pm, 1));
    const double noise = std::abs(view.flux(a1.film) - view.flux(a2.film)) / std::sqrt(2.0);
    INFO("window flux: analytic ball " << view.flux(a1.film) << " and " << view.flux(a2.film) << " (seed noise "
                                       << noise << "), CSG halves " << view.flux(c1.film) << "; pm analytic "
                                       << view.flux(apm.film) << ", CSG " << view.flux(cpm.film));
    CHECK(std::abs(view.flux(c1.film) - view.flux(a1.film)) < 4 * noise + 0.01 * view.flux(a1.film));
    CHECK(view.flux(cpm.film) == Approx(view.flux(apm.film)).epsilon(0.02));
    // The image as a whole (the ball seen, with no inner disc) matches pixel by pixel on average.
    double diff = 0, total = 0;
    for (std::size_t i = 0; i < cpm.film.pixels().size(); ++i) {
        diff += std::abs(double(cpm.film.pixels()[i].x) - double(apm.film.pixels()[i].x));
        total += double(apm.film.pixels()[i].x);
    }
    INFO("mean absolute pixel difference, pm: " << diff / total << " of the mean");
    CHECK(diff < 0.01 * total);  // measured: 0 (the hemispheres' hits are the sphere's own)
}

TEST_CASE("through a hole in an opaque CSG plate, shadow rays and photons light the floor alike", "[csg][render][heavy]") {
    // A black plate (no indirect light from it) with a round hole, above the floor: the floor
    // under the hole is lit directly, which rt sees by shadow rays and sppm by photons.
    const Vec3<double> light{0, 4, 0};
    const auto scene = floor_scene(light, [&](DefaultScene<double>& s) {
        s.add(DefaultCsg<double>::difference({Box<double>({-1.5, 1.0, -1.5}, {1.5, 1.2, 1.5}),
                                              Cylinder<double>({0.2, 0.5, 0}, {0.2, 1.7, 0}, 0.3)}),
              s.add_material(Material<double>::lambertian(Rgb<double>(0))));
    });
    // Seen from above the light, through the hole.
    const FloorView view(scene, 1.0, PinholeCamera<double>::look_at({0.2, 5, 0}, {0.2, 0, 0}, {0, 0, 1}, 30, 1.0));
    RenderSettings rt_settings = settings(RenderMode::rt, 1);
    const RenderResult rt = render(scene, view.camera, rt_settings);
    const RenderResult s1 = render(scene, view.camera, settings(RenderMode::sppm, 1));
    const RenderResult s2 = render(scene, view.camera, settings(RenderMode::sppm, 2));
    const double noise = std::abs(view.flux(s1.film) - view.flux(s2.film)) / std::sqrt(2.0);
    // The lit patch: the hole's disc projected from the light onto the floor, 4/3 wider.
    const double patch = pi<double> * 0.3 * 0.3 * (4.0 / 3.0) * (4.0 / 3.0);
    INFO("window flux: rt " << view.flux(rt.film) << " W, sppm " << view.flux(s1.film) << " and " << view.flux(s2.film)
                            << " (seed noise " << noise << "); lit patch area " << patch);
    REQUIRE(view.flux(rt.film) > 0);
    CHECK(std::abs(view.flux(s1.film) - view.flux(rt.film)) < 4 * noise + 0.03 * view.flux(rt.film));
}
