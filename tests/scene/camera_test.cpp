// SPDX-License-Identifier: MIT
// POV-Ray 3.7's camera projections (scene/projection.hpp, scene/camera.hpp): each against POV-Ray's
// formula (TracePixel::CreateCameraRay) worked out by hand at a few image positions, the
// projections' symmetries, the image positions they have no ray for, and focal blur's sharp plane.

#include <catch2/catch.hpp>

#include <photon/scene/camera.hpp>

#include <cmath>
#include <optional>

using namespace photon;

namespace {

template <class S> bool camera_near(const Vec3<S>& a, const Vec3<S>& b, double tol = 1e-5) {
    return glm::length(Vec3<double>(a) - Vec3<double>(b)) < tol;
}

/// A frame looking along +z from (1, 2, 3) with POV-Ray's raw vector lengths left in:
/// |direction| 2, |right| 1.5, |up| 1 unless given.
template <class S> CameraFrame<S> camera_frame(S angle = S(90), S vertical_angle = S(180), Vec3<S> up = {0, 1, 0}) {
    return {{1, 2, 3}, {0, 0, 2}, {1.5, 0, 0}, up, angle, vertical_angle};
}

template <class S> Vec3<S> camera_dir(const Camera<S>& c, S u, S v) {
    const auto r = c.ray(u, v);
    REQUIRE(r);
    return r->direction;
}

constexpr double deg = 3.14159265358979323846 / 180.0;

}  // namespace

TEMPLATE_TEST_CASE("perspective: direction + (u - 1/2) right + (1/2 - v) up from the location", "[camera]", float, double) {
    using S = TestType;
    const Camera<S> c(Projection::perspective, camera_frame<S>());
    const auto r = c.ray(S(0.75), S(0.25));
    REQUIRE(r);
    CHECK(camera_near(r->origin, Vec3<S>(1, 2, 3)));
    CHECK(camera_near(r->direction, glm::normalize(Vec3<S>(0.375, 0.25, 2))));
    CHECK(camera_near(camera_dir(c, S(0.5), S(0.5)), Vec3<S>(0, 0, 1)));
    // The old four-vector constructor is the same camera, and the alias still names it.
    const PinholeCamera<S> old({1, 2, 3}, {0, 0, 2}, {1.5, 0, 0}, {0, 1, 0});
    CHECK(camera_near(camera_dir(old, S(0.75), S(0.25)), r->direction));
    CHECK(c.eye() == std::optional<Vec3<S>>(Vec3<S>(1, 2, 3)));
}

TEMPLATE_TEST_CASE("orthographic: parallel rays whose origins span right x up", "[camera]", float, double) {
    using S = TestType;
    const Camera<S> c(Projection::orthographic, camera_frame<S>());
    for (const S u : {S(0), S(0.3), S(1)})
        for (const S v : {S(0), S(0.8), S(1)}) {
            const auto r = c.ray(u, v);
            REQUIRE(r);
            CHECK(camera_near(r->direction, Vec3<S>(0, 0, 1)));
            // location + (u - 1/2) right + (1/2 - v) up
            CHECK(camera_near(r->origin, Vec3<S>(1 + (u - 0.5) * 1.5, 2 + (0.5 - v), 3)));
        }
    CHECK(camera_near(c.ray(S(1), S(0))->origin - c.ray(S(0), S(1))->origin, Vec3<S>(1.5, 1, 0)));
    CHECK_FALSE(c.eye());
}

TEMPLATE_TEST_CASE("fisheye: angle / 2 at the rim of the circle on the image's shorter side, nothing outside", "[camera]",
                   float, double) {
    using S = TestType;
    // Square pixels of a square image: |right| = |up| = 1, the circle touches all four sides.
    CameraFrame<S> square = camera_frame<S>(S(180));
    square.right = {1, 0, 0};
    const Camera<S> c(Projection::fisheye, square);
    CHECK(camera_near(camera_dir(c, S(0.5), S(0.5)), Vec3<S>(0, 0, 1)));
    CHECK(camera_near(camera_dir(c, S(1), S(0.5)), Vec3<S>(1, 0, 0)));   // rim: 90 degrees off the axis
    CHECK(camera_near(camera_dir(c, S(0.5), S(0)), Vec3<S>(0, 1, 0)));   // top
    CHECK(camera_near(camera_dir(c, S(0.75), S(0.5)), Vec3<S>(std::sin(45 * deg), 0, std::cos(45 * deg))));
    CHECK(camera_near(camera_dir(c, S(0.5), S(0.25)), Vec3<S>(0, std::sin(45 * deg), std::cos(45 * deg))));
    // (0.75, 0.25): radius sqrt(2)/2 at azimuth 45 degrees, so 63.64 degrees off the axis.
    const double theta = std::sqrt(0.5) * 90 * deg;
    CHECK(camera_near(camera_dir(c, S(0.75), S(0.25)),
                      Vec3<S>(std::sin(theta) * std::sqrt(0.5), std::sin(theta) * std::sqrt(0.5), std::cos(theta))));
    CHECK_FALSE(c.ray(S(1), S(0)));      // image corner: outside the circle
    CHECK_FALSE(c.ray(S(0.95), S(0.9)));
    // 360 degrees: the rim looks backwards.
    const Camera<S> full(Projection::fisheye, CameraFrame<S>{{0, 0, 0}, {0, 0, 1}, {1, 0, 0}, {0, 1, 0}, S(360)});
    CHECK(camera_near(camera_dir(full, S(1), S(0.5)), Vec3<S>(0, 0, -1), 1e-4));
    // A 4:3 image (|right| 4/3): the circle spans the height; u = 1/2 + 3/8 is its right rim.
    CameraFrame<S> wide = square;
    wide.right = {S(4) / S(3), 0, 0};
    const Camera<S> w(Projection::fisheye, wide);
    CHECK(camera_near(camera_dir(w, S(0.875), S(0.5)), Vec3<S>(1, 0, 0)));
    CHECK_FALSE(w.ray(S(0.9), S(0.5)));
    // Mirror symmetry in right and in up.
    for (const S u : {S(0.1), S(0.3), S(0.45)})
        for (const S v : {S(0.2), S(0.4)}) {
            const Vec3<S> d = camera_dir(c, u, v), dx = camera_dir(c, 1 - u, v), dy = camera_dir(c, u, 1 - v);
            CHECK(camera_near(dx, Vec3<S>(-d.x, d.y, d.z)));
            CHECK(camera_near(dy, Vec3<S>(d.x, -d.y, d.z)));
        }
}

TEMPLATE_TEST_CASE("ultra_wide_angle: angle across the width, angle x |up| / |right| across the height", "[camera]",
                   float, double) {
    using S = TestType;
    const Camera<S> c(Projection::ultra_wide_angle, camera_frame<S>(S(180)));  // |up| / |right| = 2/3
    CHECK(camera_near(camera_dir(c, S(1), S(0.5)), Vec3<S>(1, 0, 0)));
    CHECK(camera_near(camera_dir(c, S(0.75), S(0.5)), Vec3<S>(std::sin(45 * deg), 0, std::cos(45 * deg))));
    const double y = 0.25 * 180 * (2.0 / 3.0) * deg;  // 30 degrees
    CHECK(camera_near(camera_dir(c, S(0.5), S(0.25)), Vec3<S>(0, std::sin(y), std::cos(y))));
    // Off both axes the direction is sin(x) right + sin(y) up + cos(x) cos(y) direction, normalised.
    const double x = 0.25 * 180 * deg;
    CHECK(camera_near(camera_dir(c, S(0.75), S(0.25)),
                      Vec3<S>(glm::normalize(Vec3<double>(std::sin(x), std::sin(y), std::cos(x) * std::cos(y))))));
    for (const S u : {S(0.05), S(0.3)})
        for (const S v : {S(0.1), S(0.35)}) {
            const Vec3<S> d = camera_dir(c, u, v);
            CHECK(camera_near(camera_dir(c, 1 - u, v), Vec3<S>(-d.x, d.y, d.z)));
            CHECK(camera_near(camera_dir(c, u, 1 - v), Vec3<S>(d.x, -d.y, d.z)));
        }
}

TEMPLATE_TEST_CASE("omnimax: its polynomial off the axis, nothing 45 degrees below it or outside the circle", "[camera]",
                   float, double) {
    using S = TestType;
    CameraFrame<S> square = camera_frame<S>();
    square.right = {1, 0, 0};
    const Camera<S> c(Projection::omnimax, square);
    CHECK(camera_near(camera_dir(c, S(0.5), S(0.5)), Vec3<S>(0, 0, 1)));
    // Radius 1/2: theta = 1.411269 r - 0.09439 r^3 + 0.25674 r^5.
    const double t = 1.411269 * 0.5 - 0.09439 * 0.125 + 0.25674 * 0.03125;
    CHECK(camera_near(camera_dir(c, S(0.75), S(0.5)), Vec3<S>(std::sin(t), 0, std::cos(t))));
    CHECK(camera_dir(c, S(0.5), S(0.02)).y > S(0.9));  // near the top: up
    CHECK_FALSE(c.ray(S(0.5), S(0.98)));               // near the bottom: too far below the axis
    CHECK_FALSE(c.ray(S(0.99), S(0.01)));              // a corner
    const Vec3<S> d = camera_dir(c, S(0.3), S(0.4));
    CHECK(camera_near(camera_dir(c, S(0.7), S(0.4)), Vec3<S>(-d.x, d.y, d.z)));
}

TEMPLATE_TEST_CASE("panoramic: 180 degrees across, tan(elevation) up, on the raw vectors", "[camera]", float, double) {
    using S = TestType;
    const Camera<S> c(Projection::panoramic, camera_frame<S>());  // direction <0,0,2>, right <1.5,0,0>
    CHECK(camera_near(camera_dir(c, S(0.5), S(0.5)), Vec3<S>(0, 0, 1)));
    CHECK(camera_near(camera_dir(c, S(0), S(0.5)), Vec3<S>(-1, 0, 0)));
    CHECK(camera_near(camera_dir(c, S(1), S(0.5)), Vec3<S>(1, 0, 0)));
    CHECK(camera_near(camera_dir(c, S(0.5), S(0.25)), glm::normalize(Vec3<S>(0, 1, 2))));  // tan 45 = 1
    // u = 1/4: azimuth 135 degrees, cos(135) right + sin(135) direction.
    CHECK(camera_near(camera_dir(c, S(0.25), S(0.5)), glm::normalize(Vec3<S>(-std::sqrt(0.5) * 1.5, 0, std::sqrt(0.5) * 2))));
    CHECK(camera_dir(c, S(0.5), S(0)).y > S(0.999));  // the top row looks straight up
    for (const S u : {S(0.1), S(0.4)})
        for (const S v : {S(0.1), S(0.3)}) {
            const Vec3<S> d = camera_dir(c, u, v);
            CHECK(camera_near(camera_dir(c, 1 - u, v), Vec3<S>(-d.x, d.y, d.z)));
            CHECK(camera_near(camera_dir(c, u, 1 - v), Vec3<S>(d.x, -d.y, d.z)));
        }
}

TEMPLATE_TEST_CASE("cylinders 1 to 4: angle around the axis, |up| or |right| along it", "[camera]", float, double) {
    using S = TestType;
    const CameraFrame<S> f = camera_frame<S>(S(90), S(180), Vec3<S>(0, 2, 0));  // |right| 1.5, |up| 2
    const Vec3<S> eye(1, 2, 3);
    const Vec3<S> side45(std::sin(45 * deg), 0, std::cos(45 * deg)), up45(0, std::sin(45 * deg), std::cos(45 * deg));
    const Camera<S> c1(Projection::cylinder_1, f), c2(Projection::cylinder_2, f), c3(Projection::cylinder_3, f),
        c4(Projection::cylinder_4, f);
    CHECK(camera_near(camera_dir(c1, S(1), S(0.5)), side45));
    CHECK(camera_near(camera_dir(c1, S(0.5), S(0)), glm::normalize(Vec3<S>(0, 1, 1))));  // 0.5 |up| along the axis
    CHECK(camera_near(camera_dir(c2, S(0.5), S(0)), up45));
    CHECK(camera_near(camera_dir(c2, S(1), S(0.5)), glm::normalize(Vec3<S>(0.75, 0, 1))));
    // 3 and 4: the rays start along the axis, level with it.
    CHECK(camera_near(c3.ray(S(1), S(0.5))->origin, eye));
    CHECK(camera_near(camera_dir(c3, S(1), S(0.5)), side45));
    CHECK(camera_near(c3.ray(S(0.5), S(0))->origin, eye + Vec3<S>(0, 1, 0)));
    CHECK(std::abs(camera_dir(c3, S(0.3), S(0)).y) < S(1e-6));
    CHECK(camera_near(c4.ray(S(1), S(0.5))->origin, eye + Vec3<S>(0.75, 0, 0)));
    CHECK(camera_near(camera_dir(c4, S(0.5), S(0)), up45));
    CHECK(std::abs(camera_dir(c4, S(0.2), S(0.7)).x) < S(1e-6));
    CHECK(c1.eye());
    CHECK_FALSE(c3.eye());
    CHECK_FALSE(c4.eye());
}

TEMPLATE_TEST_CASE("spherical: latitude about right, then longitude about up, over its two angles", "[camera]", float,
                   double) {
    using S = TestType;
    const Camera<S> c(Projection::spherical, camera_frame<S>(S(360), S(180)));
    CHECK(camera_near(camera_dir(c, S(0.5), S(0.5)), Vec3<S>(0, 0, 1)));
    CHECK(camera_near(camera_dir(c, S(0.75), S(0.5)), Vec3<S>(1, 0, 0)));
    CHECK(camera_near(camera_dir(c, S(1), S(0.5)), Vec3<S>(0, 0, -1)));
    CHECK(camera_near(camera_dir(c, S(0.5), S(0)), Vec3<S>(0, 1, 0)));
    // 45 degrees up, then 90 degrees right: (0, sin 45, cos 45) turned about up onto +x.
    CHECK(camera_near(camera_dir(c, S(0.75), S(0.25)), Vec3<S>(std::sqrt(0.5), std::sqrt(0.5), 0)));
    const Camera<S> half(Projection::spherical, camera_frame<S>(S(180), S(90)));
    CHECK(camera_near(camera_dir(half, S(1), S(0.5)), Vec3<S>(1, 0, 0)));
    CHECK(camera_near(camera_dir(half, S(0.5), S(0)), Vec3<S>(0, std::sin(45 * deg), std::cos(45 * deg))));
}

TEMPLATE_TEST_CASE("the projections use the camera's own axes", "[camera]", float, double) {
    using S = TestType;
    // Looking along +x with right -z (POV-Ray's look_at from the origin to +x), up +y.
    const CameraFrame<S> f{{0, 0, 0}, {3, 0, 0}, {0, 0, -1}, {0, 1, 0}, S(180), S(180)};
    CHECK(camera_near(camera_dir(Camera<S>(Projection::fisheye, f), S(1), S(0.5)), Vec3<S>(0, 0, -1)));
    CHECK(camera_near(camera_dir(Camera<S>(Projection::panoramic, f), S(0), S(0.5)), Vec3<S>(0, 0, 1)));
    CHECK(camera_near(camera_dir(Camera<S>(Projection::spherical, f), S(1), S(0.5)), Vec3<S>(0, 0, -1)));
    CHECK(camera_near(Camera<S>(Projection::orthographic, f).ray(S(1), S(0))->origin, Vec3<S>(0, 0.5, -0.5)));
}

TEMPLATE_TEST_CASE("focal blur: every lens ray through one image position meets the others at the focal distance",
                   "[camera]", float, double) {
    using S = TestType;
    const S aperture = S(0.8), focal = S(5);
    for (const Projection p : {Projection::perspective, Projection::fisheye, Projection::orthographic}) {
        INFO(to_string(p));
        const Camera<S> pin(p, camera_frame<S>());
        const Camera<S> lens(p, camera_frame<S>(), FocalBlur<S>{aperture, focal});
        CHECK(lens.has_focal_blur());
        CHECK_FALSE(lens.eye());
        for (const Vec2<S> uv : {Vec2<S>(0.5, 0.5), Vec2<S>(0.7, 0.2), Vec2<S>(0.4, 0.6)}) {  // inside the fisheye's circle
            REQUIRE(pin.ray(uv.x, uv.y));
            const Ray<S> centre = *pin.ray(uv.x, uv.y);
            // POV-Ray: the sharp point is the unnormalised ray direction times focal / |direction|
            // (|direction| = 2 here) from the pinhole ray's origin.
            const std::optional<Ray<S>> raw = project(p, camera_frame<S>(), uv.x, uv.y);
            const Vec3<S> sharp = raw->origin + raw->direction * (focal / S(2));
            CHECK(camera_near(lens.ray(uv.x, uv.y)->direction, centre.direction));  // the lens's centre: no change
            double spread = 0;
            for (const Vec2<S> l : {Vec2<S>(0, 0), Vec2<S>(1, 0), Vec2<S>(0.3, 0.9), Vec2<S>(0.99, 0.99), Vec2<S>(0.6, 0.1)}) {
                const Ray<S> r = *lens.ray(uv.x, uv.y, l);
                const Vec3<S> to = sharp - r.origin;
                // The sharp point lies on the ray: no distance off it.
                CHECK(glm::length(to - glm::dot(to, r.direction) * r.direction) < S(1e-4) * glm::length(to));
                CHECK(glm::dot(to, r.direction) > S(0));
                // The lens: a disc of radius aperture / 4 across the view.
                const Vec3<S> off = r.origin - centre.origin;
                CHECK(glm::length(off) <= aperture / 4 + S(1e-5));
                CHECK(std::abs(glm::dot(off, Vec3<S>(0, 0, 1))) < S(1e-5));
                spread = std::max(spread, double(glm::length(off)));
            }
            CHECK(spread > 0.9 * double(aperture) / 4);
        }
    }
}

TEMPLATE_TEST_CASE("a camera rejects degenerate vectors, negative angles and apertures", "[camera]", float, double) {
    using S = TestType;
    CameraFrame<S> flat = camera_frame<S>();
    flat.up = {3, 0, 0};  // parallel to right
    CHECK_THROWS_AS(Camera<S>(Projection::fisheye, flat), std::invalid_argument);
    CHECK_THROWS_AS(Camera<S>(Projection::fisheye, camera_frame<S>(S(-1))), std::invalid_argument);
    CHECK_THROWS_AS(Camera<S>(Projection::perspective, camera_frame<S>(), FocalBlur<S>{S(-1), S(1)}), std::invalid_argument);
    CHECK_THROWS_AS(Camera<S>(Projection::perspective, camera_frame<S>(), FocalBlur<S>{S(1), S(0)}), std::invalid_argument);
}
