// SPDX-License-Identifier: MIT
// The paper's "light through thin walls" weakness, measured: a 2 cm wall stands on a black floor;
// a point light on one side aims down. Next to the wall the dark side must get no light and
// the lit side exactly I cos(theta) / d^2.

#include <catch2/catch.hpp>

#include <photon/photon.hpp>

using namespace photon;

namespace {

struct WallScene {
    DefaultScene<double> scene;
    double intensity = 0;
    WallScene() {
        const auto black = scene.add_material(Material<double>::lambertian(Rgb<double>(0.0)));
        const auto floor = scene.add_material(Material<double>::lambertian(Rgb<double>(0.5)));
        scene.add(Box<double>({-5, -0.02, -5}, {5, 0, 5}), floor);
        scene.add(Box<double>({-0.01, 0, -5}, {0.01, 2, 5}), black);  // thin wall on the floor
        const Cone<double> cone({0, -1, 0}, 75);
        intensity = 100.0 / cone.solid_angle();
        scene.add_light(PointLight<double>{{0.5, 1, 0}, Rgb<double>(100.0), cone});
        scene.commit();
    }
    [[nodiscard]] double exact(const Vec3<double>& p) const {
        const Vec3<double> d = Vec3<double>{0.5, 1, 0} - p;
        const double len = glm::length(d);
        return intensity * d.y / (len * len * len);
    }
};

/// Irradiance at p on the floor from a map of direct photons, as the renderer computes it.
double irradiance(const WallScene& w, const PhotonMap& map, const Vec3<double>& p, const EstimateSettings& es) {
    const Vec3<double> n{0, 1, 0};
    const Vec3<double> x = offset_origin(p, n, intersection_error(p, p));
    EstimateScratch scratch;
    ShadingContext ctx;
    if (es.boundary_probes == 0) return estimate_irradiance(map, x, n, es, scratch).x;
    const VisibleDisc disc = probe_visible_disc(w.scene, x, n, es.max_radius, es.boundary_probes, ctx);
    return estimate_irradiance(map, x, n, es, scratch, &disc).x;
}

}  // namespace

TEST_CASE("thin walls: boundary probes stop the leak and the corner darkening", "[transport][thin-wall]") {
    const WallScene w;
    const TracedPhotons traced = trace_global_photons(
        w.scene, {.photons = 1'000'000, .store = {.direct = true, .caustic = false, .indirect = false}, .seed = 5});
    const PhotonMap map(traced.photons);
    // k = 1600 photons need a disc of about 5 cm here: it reaches across the wall from 1 cm.
    EstimateSettings es{.k = 1600, .max_radius = 0.15f};

    const Vec3<double> dark{-0.02, 0, 0.2}, lit{0.02, 0, 0.2};
    // Without probes the disc around a point 1 cm behind the wall reaches the lit side: light
    // leaks through; and part of the lit side's disc lies behind the wall, where no photon can
    // be, so the estimate there comes out too dark.
    const double leak = irradiance(w, map, dark, es);
    const double lit_naive = irradiance(w, map, lit, es);
    CHECK(leak > 0.1 * w.exact(lit));
    CHECK(lit_naive < 0.85 * w.exact(lit));

    es.boundary_probes = 16;
    CHECK(irradiance(w, map, dark, es) == 0.0);
    CHECK(irradiance(w, map, lit, es) == Approx(w.exact(lit)).epsilon(0.08));
    // Far from the wall the probes change nothing.
    const Vec3<double> open{1.0, 0, 0.3};
    CHECK(irradiance(w, map, open, es) == Approx(w.exact(open)).epsilon(0.1));
}
