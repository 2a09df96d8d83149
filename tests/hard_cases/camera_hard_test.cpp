// SPDX-License-Identifier: MIT
// The camera where it should not be (inside an opaque sphere, inside a solid box, inside glass),
// and pixels whose estimate finds no photon at all.

#include "hard_case_util.hpp"

using namespace photon;

namespace {

template <class S> DefaultScene<S> room_with(int inside) {
    DefaultScene<S> scene;
    const auto white = scene.add_material(Material<S>::lambertian(Rgb<S>(S(0.7))));
    scene.add(Box<S>({-3, -0.1, -3}, {3, 0, 3}), white);
    scene.add(Box<S>({-3, 0, 1.2}, {3, 3, 1.3}), white);
    scene.add_light(SphereLight<S>{.center = {0.5, 2.2, -0.5}, .radius = S(0.1), .power = Rgb<S>(S(60))});
    if (inside == 0) scene.add(Sphere<S>({0, 1, -2}, S(0.5)), white);
    if (inside == 1) scene.add(Box<S>({-0.5, 0.5, -2.5}, {0.5, 1.5, -1.5}), white);
    if (inside == 2) scene.add(Sphere<S>({0, 1, -2}, S(0.5)), scene.add_material(Material<S>::glass(S(1.5))));
    scene.commit();
    return scene;
}

}  // namespace

TEMPLATE_TEST_CASE("a camera inside an opaque sphere or a solid box sees black: inside glass it sees the room",
                   "[hard][camera]", float, double) {
    using S = TestType;
    const auto camera = PinholeCamera<S>::look_at({0, 1, -2}, {0, 0.5, 0}, {0, 1, 0}, S(60), S(32.0 / 24.0));
    const char* names[] = {"opaque sphere", "solid box", "glass sphere"};
    for (int inside = 0; inside < 3; ++inside) {
        const DefaultScene<S> scene = room_with<S>(inside);
        for (const RenderMode mode : {RenderMode::rt, RenderMode::pm, RenderMode::pm_direct}) {
            INFO("camera inside the " << names[inside] << ", mode " << to_string(mode));
            const RenderResult r = render(scene, camera, hard::tiny(mode));
            HARD_REQUIRE_VALID(r.film);
            if (inside < 2) {
                // The inner side of the shell gets no light: no shadow ray gets out, no photon in.
                CHECK(r.film.mean().x == 0.0);
            } else {
                CHECK(r.film.mean().x > 0.01);
            }
        }
    }
}

TEMPLATE_TEST_CASE("a pixel whose estimate finds no photon is 0, not NaN", "[hard][camera]", float, double) {
    using S = TestType;
    // Photons only in one corner of the map: an estimate elsewhere finds none within its radius.
    std::vector<Photon> corner;
    for (int i = 0; i < 100; ++i)
        corner.push_back({{0.01f * float(i % 10), 0, 0.01f * float(i / 10)}, PackedPhoton(Rgb<float>(1), {0, -1, 0}, PathKind::direct)});
    const PhotonMap map(corner);
    EstimateScratch scratch;
    for (const float radius : {0.5f, 1e-3f, 1e-30f}) {
        const Rgb<S> e = estimate_irradiance(map, Vec3<S>(5, 0, 5), Vec3<S>(0, 1, 0), EstimateSettings{.k = 50, .max_radius = radius}, scratch);
        CHECK(e == Rgb<S>(0));
    }
    // A whole render where most estimates find nothing: 300 photons, a 1 mm radius.
    const DefaultScene<S> scene = room_with<S>(-1);
    const auto camera = PinholeCamera<S>::look_at({0, 1.2, -3}, {0, 0.5, 0}, {0, 1, 0}, S(55), S(32.0 / 24.0));
    RenderSettings s = hard::tiny(RenderMode::pm_direct);
    s.global_photons = 300;
    s.global_estimate.max_radius = 1e-3f;
    s.global_estimate.boundary_probes = 0;
    const RenderResult r = render(scene, camera, s);
    HARD_REQUIRE_VALID(r.film);
    std::size_t black = 0;
    for (const auto& p : r.film.pixels()) black += p == Rgb<float>(0.0f) ? 1 : 0;
    CHECK(black > r.film.pixels().size() / 2);
    // pm with final gathering over the same sparse map: gathers that find nothing add 0.
    s.mode = RenderMode::pm;
    const RenderResult g = render(scene, camera, s);
    HARD_REQUIRE_VALID(g.film);
}
