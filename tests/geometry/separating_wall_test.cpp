// SPDX-License-Identifier: MIT
// Walls across shadow rays (integrator/separating_wall.hpp): where wall_between() says a wall
// lies across every segment from a point to a light's ball, every such segment is blocked (by
// brute force, against the scene's own occlusion test), and the cases it must refuse are refused.

#include <catch2/catch.hpp>

#include <photon/photon.hpp>

using namespace photon;

namespace {

/// Two rooms side by side split by a wall box at x in [-0.05, 0.05] that reaches floor, ceiling
/// and both ends, plus a glass pane and a shadowless box standing in room 2 (not walls).
template <Scalar S> struct TwoRooms {
    DefaultScene<S> scene;
    std::uint32_t wall = 0, pane = 0, ghost = 0;
    TwoRooms() {
        const auto white = scene.add_material(Material<S>::lambertian(Rgb<S>(S(0.7))));
        scene.add(Box<S>({-3, -0.1, -2}, {3, 0, 2}), white);  // floor
        scene.add(Box<S>({-3, 2.5, -2}, {3, 2.6, 2}), white);  // ceiling
        wall = scene.add(Box<S>({S(-0.05), 0, -2}, {S(0.05), S(2.5), 2}), white);
        pane = scene.add(Box<S>({1, 0, -1}, {S(1.02), 2, 1}), scene.add_material(Material<S>::glass(S(1.5))));
        ObjectOptions shadowless;
        shadowless.casts_shadow = false;
        ghost = scene.add(Box<S>({2, 0, -1}, {S(2.1), 2, 1}), white, shadowless);
        scene.commit();
    }
    [[nodiscard]] bool across(const Vec3<S>& p, const Vec3<S>& c, S r) const {
        std::vector<std::uint32_t> ids;
        BBox<S> region = BBox<S>::of_point(p);
        region.extend(BBox<S>{c - r, c + r});
        scene.occluders_in(region, ids);
        return wall_between(scene, std::span<const std::uint32_t>(ids), p, c, r);
    }
};

}  // namespace

TEMPLATE_TEST_CASE("a wall across every shadow ray is found, and only then", "[geometry][walls]", float, double) {
    using S = TestType;
    const TwoRooms<S> rooms;
    const Vec3<S> lamp(-1.5, 2.2, 0);  // in room 1, a ball of radius 0.05
    CHECK(rooms.across({1.5, 0.001f, 0.5}, lamp, S(0.05)));      // a floor point in room 2
    CHECK(rooms.across({0.06f, 1, 1.9f}, lamp, S(0.05)));        // on the wall's far face
    CHECK_FALSE(rooms.across({-0.5, 0.001f, 0.5}, lamp, S(0.05)));  // the same room
    CHECK(rooms.across({1.5, 2.7f, 0}, lamp, S(0.05)));          // above the ceiling: the ceiling is the wall
    CHECK(rooms.across({1.5, 0.0001f, 0.5}, lamp, S(0.05)));     // on the floor: the ray meets the wall high up
    CHECK_FALSE(rooms.across({1.5, 2.7f, 0}, {-1.5, 2.8f, 0}, S(0.05)));  // both above the ceiling: over the wall
    CHECK(rooms.across({1.5, 1, 2.5f}, lamp, S(0.05)));          // past the wall's end, but the rays meet it
    CHECK_FALSE(rooms.across({1.5, 1, 6}, lamp, S(0.05)));       // far past its end: the rays go round it
    // Rays that leave the wall's top: the ceiling blocks them, but no one wall blocks them all.
    CHECK_FALSE(rooms.across({1.5, 2.45f, 0}, {-1.5, 2.45f, 0}, S(0.2)));
    // A glass pane and a box that casts no shadow are no walls.
    CHECK_FALSE(rooms.across({1.5, 1, 0}, {2.5, 1, 0}, S(0.05)));
    CHECK_FALSE(rooms.across({2.5, 1, 0}, {1.5, 1, 0}, S(0.05)));
    // An opaque infinite plane is one, with both strictly on opposite sides.
    DefaultScene<S> open;
    const auto white = open.add_material(Material<S>::lambertian(Rgb<S>(S(0.7))));
    open.add(Plane<S>({0, 0, 1}, 0), white);
    open.commit();
    const std::vector<std::uint32_t> plane{0};
    CHECK(wall_between(open, std::span<const std::uint32_t>(plane), Vec3<S>(0, 0, 1), Vec3<S>(5, 5, -1), S(0.5)));
    CHECK_FALSE(wall_between(open, std::span<const std::uint32_t>(plane), Vec3<S>(0, 0, 1), Vec3<S>(5, 5, -0.2f), S(0.5)));
    CHECK_FALSE(wall_between(open, std::span<const std::uint32_t>(plane), Vec3<S>(0, 0, 1), Vec3<S>(5, 5, 2), S(0.5)));
}

TEMPLATE_TEST_CASE("where a wall is found, every segment to the light's ball is blocked", "[geometry][walls]", float, double) {
    using S = TestType;
    const TwoRooms<S> rooms;
    const BBox<S> inside{{-3, 0, -2}, {3, S(2.5), 2}};
    Pcg32 rng(11, 2);
    int found = 0;
    for (int trial = 0; trial < 400; ++trial) {
        const auto somewhere = [&] { return inside.min + Vec3<S>(rng.uniform<S>(), rng.uniform<S>(), rng.uniform<S>()) * inside.extent(); };
        const Vec3<S> p = somewhere(), c = somewhere();
        const S r = S(0.3) * rng.uniform<S>();
        if (!rooms.across(p, c, r)) continue;
        ++found;
        for (int i = 0; i < 64; ++i) {
            const Vec3<S> q = c + r * std::cbrt(rng.uniform<S>()) * uniform_sphere(rng.uniform2<S>());
            const Vec3<S> d = q - p;
            const S length = glm::length(d);
            REQUIRE(rooms.scene.occluded(Ray<S>{p, d / length, length}));
        }
    }
    CHECK(found > 50);  // about a third of the pairs are in opposite rooms
}

TEST_CASE("a lamp behind a wall gets no shadow rays, and the image does not change", "[render][walls]") {
    TwoRooms<float> rooms;
    rooms.scene.add_light(SphereLight<float>{.center = {-1.5f, 2.2f, 0}, .radius = 0.05f, .power = Rgb<float>(20.0f)});
    rooms.scene.add_light(SphereLight<float>{.center = {1.5f, 2.2f, 0}, .radius = 0.05f, .power = Rgb<float>(20.0f)});
    rooms.scene.commit();
    const auto camera = PinholeCamera<float>::look_at({2.8f, 1.5f, -1.8f}, {1.2f, 0.3f, 0.5f}, {0, 1, 0}, 60.0f, 4.0f / 3.0f);
    RenderSettings s;
    s.mode = RenderMode::rt;
    s.width = 40, s.height = 30, s.samples_per_pixel = 4, s.shadow_samples = 4;
    const RenderResult r = render(rooms.scene, camera, s);
    CHECK(r.stats.rays.walled_lights > 0);
    // The reference: room 1's lamp removed, since it adds nothing to room 2.
    TwoRooms<float> alone;
    alone.scene.add_light(SphereLight<float>{.center = {1.5f, 2.2f, 0}, .radius = 0.05f, .power = Rgb<float>(20.0f)});
    alone.scene.commit();
    const RenderResult a = render(alone.scene, camera, s);
    CHECK(a.stats.rays.walled_lights == 0);
    CHECK(r.film.mean().y == Approx(a.film.mean().y).epsilon(0.01));
    // Room 1's lamp costs almost no shadow rays: only from the few points not across the wall.
    INFO("shadow rays: both lamps " << r.stats.rays.shadow << ", room 2's alone " << a.stats.rays.shadow);
    CHECK(r.stats.rays.shadow < a.stats.rays.shadow * 11 / 10);
}
