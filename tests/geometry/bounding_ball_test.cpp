// SPDX-License-Identifier: MIT
// The balls caustic photons are aimed at (geometry/bounding_ball.hpp) hold their shapes: every
// point where a ray meets the shape lies inside, by brute force, and the round shapes' balls are
// no larger than the box's.

#include <catch2/catch.hpp>

#include <photon/photon.hpp>

using namespace photon;

namespace {

/// Every hit of 4000 rays from a sphere around the shape towards points near it lies in the ball
/// (with 1e-5 of its radius for rounding); returns how many rays hit.
template <Primitive Shape> int hits_inside_ball(const Shape& shape, std::uint64_t seed) {
    using S = scalar_of<Shape>;
    const Ball<S> ball = bounding_ball(shape);
    REQUIRE(std::isfinite(ball.radius));
    const BBox<S> box = shape.bounds();
    const S reach = S(2) * glm::length(box.extent()) + S(1);
    Pcg32 rng(seed, 3);
    int hits = 0;
    for (int i = 0; i < 4000; ++i) {
        const Vec3<S> from = box.center() + reach * uniform_sphere(rng.uniform2<S>());
        const Vec3<S> to = box.min + Vec3<S>(rng.uniform<S>(), rng.uniform<S>(), rng.uniform<S>()) * box.extent();
        const auto hit = shape.intersect(Ray<S>{from, glm::normalize(to - from)});
        if (!hit) continue;
        ++hits;
        const S d = glm::length(hit->point - ball.center);
        INFO("hit at distance " << d << " from the ball's centre, radius " << ball.radius);
        REQUIRE(d <= ball.radius * S(1 + 1e-5) + S(1e-6));
    }
    return hits;
}

}  // namespace

TEMPLATE_TEST_CASE("a shape's bounding ball holds it, and a round shape's is tighter than its box's", "[geometry][aim]", float,
                   double) {
    using S = TestType;
    const Sphere<S> sphere({1, 2, 3}, S(0.4));
    const Ball<S> b = bounding_ball(sphere);
    CHECK(b.center == Vec3<S>(1, 2, 3));
    CHECK(b.radius == S(0.4));  // the box's ball would be sqrt(3) times as large
    CHECK(hits_inside_ball(sphere, 1) > 1000);

    const Cylinder<S> cylinder({0, 0, 0}, {1, 2, -1}, S(0.3));
    CHECK(bounding_ball(cylinder).radius < ball_around(cylinder.bounds()).radius);
    CHECK(hits_inside_ball(cylinder, 2) > 500);
    const TruncatedCone<S> cone({0, 0, 0}, S(0.5), {0, 0, 3}, S(0.1));
    CHECK(bounding_ball(cone).radius == Approx(std::sqrt(1.5 * 1.5 + 0.25)).epsilon(1e-5));
    CHECK(hits_inside_ball(cone, 3) > 500);
    const Disc<S> disc({1, 1, 1}, glm::normalize(Vec3<S>(1, 1, 0)), S(2));
    CHECK(bounding_ball(disc).radius == S(2));
    CHECK(hits_inside_ball(disc, 4) > 200);

    // Squashed and turned: the ball grows by the largest stretch, 3 here, not by the box.
    const Transformed<Sphere<S>> ellipsoid(Sphere<S>({0, 0, 0}, 1),
                                           Affine<S>::scale({3, 1, 0.5}).then(Affine<S>::rotate_xyz({30, 40, 50})).then(
                                               Affine<S>::translate({5, -2, 1})));
    const Ball<S> e = bounding_ball(ellipsoid);
    CHECK(e.radius == Approx(3).epsilon(1e-4));
    CHECK(glm::length(e.center - Vec3<S>(5, -2, 1)) < S(1e-4));
    CHECK(hits_inside_ball(ellipsoid, 5) > 500);

    // No ball of its own: the box's.
    const Box<S> box({0, 0, 0}, {1, 2, 3});
    CHECK(bounding_ball(box).radius == Approx(0.5 * std::sqrt(14.0)).epsilon(1e-6));
    CHECK(hits_inside_ball(box, 6) > 1000);
    CHECK(std::isinf(bounding_ball(Plane<S>({0, 1, 0}, 0)).radius));
}

TEST_CASE("a sphere's caustic cone is the sphere's own, not its box's", "[geometry][aim]") {
    // A light 2 m above a ball of radius 0.5: the cone's 1 - cos is that of asin(0.5 / 2).
    DefaultScene<double> scene;
    scene.add(Box<double>({-3, -0.1, -3}, {3, 0, 3}), scene.add_material(Material<double>::lambertian(Rgb<double>(0.5))));
    scene.add(Sphere<double>({0, 0.5, 0}, 0.5), scene.add_material(Material<double>::glass(1.5)));
    scene.add_light(PointLight<double>{.position = {0, 2.5, 0}, .power = Rgb<double>(1.0)});
    scene.commit();
    const auto aim = caustic_aim(scene);
    REQUIRE(aim.cones.size() == 1);
    REQUIRE(aim.cones[0].size() == 1);
    CHECK(aim.cones[0][0].one_minus_cos == Approx(1.0 - std::sqrt(1.0 - 0.0625)).epsilon(1e-9));
    CHECK(aim.cones[0][0].axis.y == Approx(-1.0));
}
