// SPDX-License-Identifier: MIT
// CSG (geometry/csg.hpp): analytic hits and outward normals of each operation, rays starting
// inside, inverse, coincident faces, grazing rays, tiny and huge scales; Crofton's formula
// (isotropic uniform lines through a ball of radius B cross a surface of area A on average
// A / (2 pi B^2) times) for a lens, a merge, a box with a corner cut away and a clipped sphere;
// clipping (POV-Ray's clipped_by: an open surface); and, for a tree with
// more leaves than the walk keeps on the stack, that between successive hits the inside test
// agrees with the side the hits say.

#include <catch2/catch.hpp>

#include <photon/geometry/box.hpp>
#include <photon/geometry/csg.hpp>
#include <photon/geometry/cylinder.hpp>
#include <photon/geometry/offset.hpp>
#include <photon/geometry/plane.hpp>
#include <photon/geometry/sphere.hpp>
#include <photon/geometry/torus.hpp>
#include <photon/geometry/transformed.hpp>
#include <photon/geometry/triangle.hpp>
#include <photon/math/frame.hpp>
#include <photon/math/rng.hpp>
#include <photon/math/sampling.hpp>
#include <photon/plan/shape_facts.hpp>
#include <photon/scene/scene.hpp>

#include "geometry/crofton.hpp"

#include <cmath>
#include <stdexcept>
#include <vector>

using namespace photon;

template <class S> double tol() { return std::is_same_v<S, float> ? 2e-4 : 1e-9; }

template <class S>
using TestCsg = Csg<S, Sphere<S>, Box<S>, Plane<S>, Cylinder<S>, Torus<S>, Transformed<Sphere<S>>, Transformed<Torus<S>>>;

static_assert(Solid<Sphere<double>> && Solid<Box<float>> && Solid<Plane<double>> && Solid<Cylinder<double>> &&
              Solid<Torus<float>> && Solid<Transformed<Torus<double>>> && Solid<TestCsg<double>>);
static_assert(!Solid<Transformed<Triangle<double>>>);

/// The next hit after `h` along `ray`, from an origin pushed past it by the offset rules.
template <class Shape, class S = scalar_of<Shape>>
std::optional<Hit<S>> next_hit(const Shape& shape, Ray<S>& ray, const Hit<S>& h) {
    const Vec3<S> side = glm::dot(h.normal, ray.direction) > 0 ? h.normal : -h.normal;
    ray.origin = offset_origin(h.point, side, intersection_error(h.point, ray.origin));
    return shape.intersect(ray);
}

TEMPLATE_TEST_CASE("csg lens: intersection of two spheres, from outside, inside, off axis, at tiny and huge scales",
                   "[geometry][csg]", float, double) {
    using S = TestType;
    for (const double scale : {1e-4, 1.0, 1e5}) {
        const S k = S(scale);
        const auto lens = TestCsg<S>::intersection({Sphere<S>({0, 0, S(0.5) * k}, k), Sphere<S>({0, 0, S(-0.5) * k}, k)});
        const BBox<S> b = lens.bounds();  // the overlap of the two spheres' boxes
        CHECK(double(b.min.z) == Approx(-0.5 * scale).epsilon(tol<S>()));
        CHECK(double(b.max.z) == Approx(0.5 * scale).epsilon(tol<S>()));
        CHECK(double(b.max.x) == Approx(scale).epsilon(tol<S>()));
        Ray<S> ray{{0, 0, S(-5) * k}, {0, 0, 1}};
        auto h = lens.intersect(ray);
        REQUIRE(h);
        CHECK(double(h->point.z) == Approx(-0.5 * scale).margin(tol<S>() * scale));
        CHECK(double(h->normal.z) == Approx(-1).epsilon(tol<S>()));
        CHECK(h->part == 0);  // on the sphere centred at +0.5
        h = next_hit(lens, ray, *h);  // from just inside: the far face, normal along the ray
        REQUIRE(h);
        CHECK(double(h->point.z) == Approx(0.5 * scale).margin(tol<S>() * scale));
        CHECK(double(h->normal.z) == Approx(1).epsilon(tol<S>()));
        CHECK(h->part == 1);
        CHECK_FALSE(next_hit(lens, ray, *h));
        // Off axis at z = 0.2: the lens is sqrt(1 - 0.7^2) wide there, bounded by the sphere at -0.5.
        h = lens.intersect({{S(-5) * k, 0, S(0.2) * k}, {1, 0, 0}});
        REQUIRE(h);
        CHECK(double(h->point.x) == Approx(-std::sqrt(0.51) * scale).margin(tol<S>() * scale));
        CHECK(h->part == 1);
        CHECK(double(glm::dot(h->normal, Vec3<S>(-std::sqrt(S(0.51)), 0, S(0.7)))) == Approx(1).epsilon(tol<S>()));
        CHECK(lens.contains({0, 0, S(0.4) * k}));
        CHECK_FALSE(lens.contains({0, 0, S(0.6) * k}));
        CHECK_FALSE(lens.contains({S(0.9) * k, 0, 0}));
    }
}

TEMPLATE_TEST_CASE("csg difference: a box with a spherical hole, normals flip on the subtracted part",
                   "[geometry][csg]", float, double) {
    using S = TestType;
    const auto holed = TestCsg<S>::difference({Box<S>({-1, -1, -1}, {1, 1, 1}), Sphere<S>({0, 0, 0}, S(0.5))});
    CHECK(holed.bounds().max.x == S(1));  // the first child's box
    CHECK(holed.op() == CsgOp::difference);
    Ray<S> ray{{-5, 0, 0}, {1, 0, 0}};
    const double expect[] = {-1, -0.5, 0.5, 1}, normal[] = {-1, 1, -1, 1};
    std::optional<Hit<S>> h = holed.intersect(ray);
    for (int i = 0; i < 4; ++i) {
        REQUIRE(h);
        CHECK(double(h->point.x) == Approx(expect[i]).margin(tol<S>()));
        CHECK(double(h->normal.x) == Approx(normal[i]).epsilon(tol<S>()));
        CHECK(h->part == (i == 0 || i == 3 ? 0u : 1u));
        h = next_hit(holed, ray, *h);
    }
    CHECK_FALSE(h);
    // Starting in the hole (outside the solid): the hole's wall, normal into the hole.
    h = holed.intersect({{0, 0, 0}, {0, 2, 0}});
    REQUIRE(h);
    CHECK(double(h->t) == Approx(0.25).epsilon(tol<S>()));
    CHECK(double(h->normal.y) == Approx(-1).epsilon(tol<S>()));
    // A difference of several: the first minus the union of the rest.
    const auto two_holes = TestCsg<S>::difference(
        {Box<S>({-2, -1, -1}, {2, 1, 1}), Sphere<S>({-1, 0, 0}, S(0.5)), Sphere<S>({1, 0, 0}, S(0.5))});
    CHECK_FALSE(two_holes.contains({1, 0, 0}));
    CHECK_FALSE(two_holes.contains({-1, 0, 0}));
    CHECK(two_holes.contains({0, 0, 0}));
}

TEMPLATE_TEST_CASE("csg merge has no inner surfaces, inverse swaps inside and outside", "[geometry][csg]", float,
                   double) {
    using S = TestType;
    const auto merged = TestCsg<S>::merge({Sphere<S>({S(-0.5), 0, 0}, 1), Sphere<S>({S(0.5), 0, 0}, 1)});
    Ray<S> ray{{-5, 0, 0}, {1, 0, 0}};
    auto h = merged.intersect(ray);
    REQUIRE(h);
    CHECK(double(h->point.x) == Approx(-1.5).margin(tol<S>()));
    h = next_hit(merged, ray, *h);  // not the inner surfaces at -0.5 + 1 and 0.5 - 1
    REQUIRE(h);
    CHECK(double(h->point.x) == Approx(1.5).margin(tol<S>()));
    CHECK(merged.bounds().min.x == S(-1.5));

    auto inside_out = TestCsg<S>(Sphere<S>({0, 0, 0}, 1));
    inside_out.invert();
    CHECK(inside_out.inverted());
    CHECK_FALSE(inside_out.bounds().is_finite());
    CHECK(inside_out.contains({2, 0, 0}));
    h = inside_out.intersect({{0, 0, 0}, {1, 0, 0}});  // from outside the complement: enters it
    REQUIRE(h);
    CHECK(double(h->normal.x) == Approx(-1).epsilon(tol<S>()));  // out of the complement: inward
    // Intersection with an inverse = difference.
    auto hole = TestCsg<S>(Sphere<S>({0, 0, 0}, S(0.5)));
    hole.invert();
    const auto same = TestCsg<S>::intersection({Box<S>({-1, -1, -1}, {1, 1, 1}), hole});
    h = same.intersect({{0, 0, 0}, {1, 0, 0}});
    REQUIRE(h);
    CHECK(double(h->t) == Approx(0.5).epsilon(tol<S>()));
    CHECK(double(h->normal.x) == Approx(-1).epsilon(tol<S>()));
    CHECK(same.bounds().max.x == S(1));  // finite: the box bounds it
}

TEMPLATE_TEST_CASE("csg: half-space clipping, coincident faces, grazing rays, empty intersections", "[geometry][csg]",
                   float, double) {
    using S = TestType;
    const auto dome = TestCsg<S>::intersection({Sphere<S>({0, 0, 0}, 1), Plane<S>({0, 1, 0}, 0)});
    CHECK(dome.bounds().is_finite());
    auto h = dome.intersect({{S(0.3), 5, 0}, {0, -1, 0}});  // the flat face
    REQUIRE(h);
    CHECK(double(h->t) == Approx(5).epsilon(tol<S>()));
    CHECK(double(h->normal.y) == Approx(1).epsilon(tol<S>()));
    h = dome.intersect({{S(0.3), -5, 0}, {0, 1, 0}});
    REQUIRE(h);
    CHECK(double(h->point.y) == Approx(-std::sqrt(1 - 0.09)).margin(tol<S>()));
    CHECK_FALSE(dome.intersect({{S(0.3), S(0.5), 0}, {0, 1, 0}}));  // above it, going up
    CHECK_FALSE(dome.intersect({{-5, S(1e-3), 0}, {1, 0, 0}}));  // just above the clipping plane
    CHECK(dome.intersect({{-5, S(-1e-3), 0}, {1, 0, 0}}));

    // The half cut away shares three faces with the box: rays along them see only the remaining half.
    const auto half = TestCsg<S>::difference({Box<S>({0, 0, 0}, {1, 1, 1}), Box<S>({S(0.5), 0, 0}, {1, 1, 1})});
    CHECK_FALSE(half.intersect({{S(0.7), -1, S(0.5)}, {0, 1, 0}}));
    CHECK_FALSE(half.intersect({{2, S(0.5), S(0.5)}, {-1, 0, 0}}) == std::nullopt);  // the cut face at 0.5
    h = half.intersect({{2, S(0.5), S(0.5)}, {-1, 0, 0}});
    CHECK(double(h->point.x) == Approx(0.5).margin(tol<S>()));
    CHECK(double(h->normal.x) == Approx(1).epsilon(tol<S>()));
    h = half.intersect({{S(0.25), -1, S(0.5)}, {0, 1, 0}});
    REQUIRE(h);
    CHECK(double(h->point.y) == Approx(0).margin(tol<S>()));

    // Disjoint intersection: empty bounds, never hit.
    const auto none = TestCsg<S>::intersection({Sphere<S>({-3, 0, 0}, 1), Sphere<S>({3, 0, 0}, 1)});
    CHECK(none.bounds().is_empty());
    CHECK_FALSE(none.intersect({{-10, 0, 0}, {1, 0, 0}}));

    // Grazing the lens rim (where the two spheres meet) and tangent to one sphere: finite or a miss.
    const auto lens = TestCsg<S>::intersection({Sphere<S>({0, 0, S(0.5)}, 1), Sphere<S>({0, 0, S(-0.5)}, 1)});
    const S rim = std::sqrt(S(0.75));
    for (const Ray<S>& r : {Ray<S>{{-5, rim, 0}, {1, 0, 0}}, Ray<S>{{-5, 0, 0}, {1, 0, 0}},
                            Ray<S>{{rim, -5, 0}, {0, 1, 0}}, Ray<S>{{0, -5, S(-0.5) + S(1)}, {0, 1, 0}}}) {
        if (const auto g = lens.intersect(r)) {
            CHECK(std::isfinite(double(g->t)));
            CHECK(is_finite(g->normal));
            CHECK(double(glm::length(g->normal)) == Approx(1).epsilon(tol<S>()));
        }
    }
    CHECK_THROWS_AS(TestCsg<S>::merge({}), std::invalid_argument);
}

TEMPLATE_TEST_CASE("csg clip: the lower half of a sphere's surface, open where the plane cut it, at tiny and huge scales",
                   "[geometry][csg]", float, double) {
    using S = TestType;
    for (const double scale : {1e-4, 1.0, 1e5}) {
        const S k = S(scale);
        // POV-Ray's `sphere { 0, 1 clipped_by { plane { y, 0 } } }`: the plane keeps y < 0.
        const auto bowl = TestCsg<S>::clipped(Sphere<S>({0, 0, 0}, k), {Plane<S>({0, 1, 0}, 0)});
        CHECK(bowl.op() == CsgOp::clip);
        CHECK(double(bowl.bounds().min.y) == Approx(-scale).epsilon(tol<S>()));  // a plane's box is all space
        // Down through the cut: the plane shows nothing, the bowl's inside does, its normal out of
        // the result (down, along the ray).
        Ray<S> down{{0, S(5) * k, 0}, {0, -1, 0}};
        auto h = bowl.intersect(down);
        REQUIRE(h);
        CHECK(double(h->point.y) == Approx(-scale).margin(tol<S>() * scale));
        CHECK(double(h->normal.y) == Approx(-1).epsilon(tol<S>()));
        CHECK(h->part == 0);
        CHECK_FALSE(next_hit(bowl, down, *h));
        // Up from below: the bowl's outside, then nothing (the upper half is clipped away).
        Ray<S> up{{0, S(-5) * k, 0}, {0, 1, 0}};
        h = bowl.intersect(up);
        REQUIRE(h);
        CHECK(double(h->point.y) == Approx(-scale).margin(tol<S>() * scale));
        CHECK(double(h->normal.y) == Approx(-1).epsilon(tol<S>()));
        CHECK_FALSE(next_hit(bowl, up, *h));
        // Across above the cut: nothing; across below it: the side of the bowl, twice.
        CHECK_FALSE(bowl.intersect({{S(-5) * k, S(0.5) * k, 0}, {1, 0, 0}}));
        Ray<S> across{{S(-5) * k, S(-0.5) * k, 0}, {1, 0, 0}};
        h = bowl.intersect(across);
        REQUIRE(h);
        CHECK(double(h->point.x) == Approx(-std::sqrt(0.75) * scale).margin(tol<S>() * scale));
        h = next_hit(bowl, across, *h);
        REQUIRE(h);
        CHECK(double(h->point.x) == Approx(std::sqrt(0.75) * scale).margin(tol<S>() * scale));
        CHECK(bowl.contains({0, S(-0.5) * k, 0}));
        CHECK_FALSE(bowl.contains({0, S(0.5) * k, 0}));
        // Clipped twice (each clip must hold the point): a quarter of the sphere's surface.
        const auto quarter = TestCsg<S>::clipped(Sphere<S>({0, 0, 0}, k), {Plane<S>({0, 1, 0}, 0), Plane<S>({1, 0, 0}, 0)});
        CHECK_FALSE(quarter.intersect({{S(0.5) * k, S(-5) * k, 0}, {0, 1, 0}}));
        CHECK(quarter.intersect({{S(-0.5) * k, S(-5) * k, 0}, {0, 1, 0}}));
    }
    CHECK_THROWS_AS(TestCsg<S>::clipped(Sphere<S>({0, 0, 0}, 1), {}), std::invalid_argument);
}

TEMPLATE_TEST_CASE("csg trees: nested operations, transformed leaves, children", "[geometry][csg]", float, double) {
    using S = TestType;
    // A ring: a torus minus a slab, intersected with an ellipsoid, all merged with a cylinder.
    const Transformed<Sphere<S>> ellipsoid(Sphere<S>({0, 0, 0}, 1), Affine<S>::scale({3, 1, 1}));
    const auto ring = TestCsg<S>::intersection(
        {TestCsg<S>::difference({Torus<S>(2, S(0.5)), Box<S>({-4, -1, -S(0.2)}, {4, 1, S(0.2)})}), ellipsoid});
    const auto tree = TestCsg<S>::merge({ring, Cylinder<S>({0, -1, 0}, {0, 1, 0}, S(0.3))});
    CHECK(tree.leaves().size() == 4);
    CHECK(tree.children().size() == 2);
    CHECK(tree.children()[0].op() == CsgOp::intersection);
    // Along x at z = 0: the slab removes the torus there; the cylinder remains.
    auto h = tree.intersect({{-5, 0, 0}, {1, 0, 0}});
    REQUIRE(h);
    CHECK(double(h->point.x) == Approx(-0.3).margin(tol<S>()));
    CHECK(h->part == 3);
    // Along x at z = 0.5 (above the slab): the torus tube from x = -2.5 would be at
    // |x| in [sqrt(1.5^2 - ...)], clipped by the ellipsoid |x| < 3 sqrt(1 - 0.25).
    const S z = S(0.5);
    h = tree.intersect({{-5, 0, z}, {1, 0, 0}});
    REQUIRE(h);
    // The torus at y = 0, z = 0.5: (sqrt(x^2 + z^2) - 2)^2 < 0.25, so sqrt(x^2 + 0.25) < 2.5.
    const double torus_x = std::sqrt(2.5 * 2.5 - 0.25), ellipsoid_x = 3 * std::sqrt(1 - 0.25);
    CHECK(double(h->point.x) == Approx(-std::min(torus_x, ellipsoid_x)).margin(10 * tol<S>()));
    CHECK(tree.contains({0, 0, 0}));
    CHECK_FALSE(tree.contains({2, 0, 0}));  // in the slab
    CHECK(tree.contains({2, 0, S(0.5)}));
}

/// Mean crossings of random lines through the ball (centre, radius) and its standard error; each
/// line's walk continues from past each hit by the offset rules.
template <class Shape, class S = scalar_of<Shape>>
std::pair<double, double> mean_crossings(const Shape& shape, const Vec3<S>& center, S radius, int lines) {
    return testing::mean_crossings<S>(center, radius, lines, 11, [&](Ray<S> ray) {
        long k = 0;
        for (auto h = shape.intersect(ray); h && k < 16; h = next_hit(shape, ray, *h)) ++k;
        return k;
    });
}

TEMPLATE_TEST_CASE("csg Crofton: mean crossings of random lines match the surface areas", "[geometry][csg]", float,
                   double) {
    using S = TestType;
    const int n = 100000;
    const double pi = 3.14159265358979323846;
    const auto check = [&](const auto& shape, double area, S radius) {
        const double expected = area / (2 * pi * double(radius) * double(radius));
        const auto [got, sigma] = mean_crossings(shape, Vec3<S>(0), radius, n);
        CHECK(got == Approx(expected).margin(4 * sigma));
    };
    // Lens of two unit spheres 1 apart: two caps of height 1/2, each 2 pi R h.
    check(TestCsg<S>::intersection({Sphere<S>({0, 0, S(0.5)}, 1), Sphere<S>({0, 0, S(-0.5)}, 1)}), 2 * pi, S(1.2));
    // Merge of the same spheres: both spheres less those caps.
    check(TestCsg<S>::merge({Sphere<S>({0, 0, S(0.5)}, 1), Sphere<S>({0, 0, S(-0.5)}, 1)}), 2 * (4 * pi - pi), S(1.8));
    // The lower half of a unit sphere's surface, clipped by a plane: the cut shows no surface.
    check(TestCsg<S>::clipped(Sphere<S>({0, 0, 0}, 1), {Plane<S>({0, 1, 0}, 0)}), 2 * pi, S(1.2));
    // A 2-cube minus the ball of radius 1 at a corner: 24 - 3 quarter discs + an eighth of the sphere.
    check(TestCsg<S>::difference({Box<S>({-1, -1, -1}, {1, 1, 1}), Sphere<S>({1, 1, 1}, 1)}),
          24 - 3 * pi / 4 + pi / 2, S(1.8));
}

TEMPLATE_TEST_CASE("csg with many leaves: between successive hits the inside test agrees with the hits",
                   "[geometry][csg]", float, double) {
    using S = TestType;
    std::vector<TestCsg<S>> holes{Box<S>({-2, -2, -2}, {2, 2, 2})};
    Pcg32 rng(3, 0);
    for (int i = 0; i < 20; ++i) {  // more leaves than the walk keeps on the stack
        const Vec2<S> a = rng.uniform2<S>(), b = rng.uniform2<S>();
        holes.emplace_back(Sphere<S>({S(4) * a.x - 2, S(4) * a.y - 2, S(4) * b.x - 2}, S(0.2) + S(0.5) * b.y));
    }
    const auto cheese = TestCsg<S>::difference(holes);
    REQUIRE(cheese.leaves().size() == 21);
    int hits = 0, disagreements = 0;
    for (int i = 0; i < 2000; ++i) {
        const Vec3<S> u = uniform_sphere<S>(rng.uniform2<S>());
        const Vec2<S> p = concentric_disc<S>(rng.uniform2<S>()) * S(3);
        const Frame<S> f = Frame<S>::from_normal(u);
        Ray<S> ray{f.tangent * p.x + f.bitangent * p.y - u * S(5), u};
        std::optional<Hit<S>> h = cheese.intersect(ray);
        while (h && hits < 1000000) {
            ++hits;
            REQUIRE(std::isfinite(double(h->t)));
            const Hit<S> last = *h;
            h = next_hit(cheese, ray, last);
            const bool entering = glm::dot(last.normal, u) < 0;
            const Vec3<S> mid = h ? (last.point + h->point) * S(0.5) : last.point + u * S(0.01);
            if (glm::length(mid - last.point) > S(1e-3) && cheese.contains(mid) != entering) ++disagreements;
        }
    }
    CHECK(hits > 2000);
    CHECK(disagreements == 0);
}

TEST_CASE("csg in a scene: each leaf's own material, whole-object questions ask every part, plan facts",
          "[geometry][csg]") {
    DefaultScene<double> scene;
    const MaterialId white = scene.add_material(Material<double>::lambertian(Rgb<double>(0.8)));
    const MaterialId glass = scene.add_material(Material<double>::glass(1.5));
    // A white box with a glass ball set into its top face: leaf 0 the box, leaf 1 the ball.
    scene.add(DefaultCsg<double>::merge({Box<double>({-1, -1, -1}, {1, 1, 1}), Sphere<double>({0, 1, 0}, 0.5)}),
              white, {}, {white, glass});
    scene.commit();
    auto hit = scene.intersect({{0, 5, 0}, {0, -1, 0}});
    REQUIRE(hit);
    CHECK(hit->hit.point.y == Approx(1.5));
    CHECK(hit->material == &scene.materials()[glass]);
    hit = scene.intersect({{0.8, 5, 0}, {0, -1, 0}});
    REQUIRE(hit);
    CHECK(hit->material == &scene.materials()[white]);
    CHECK(scene.any_material_of(0, is_specular_material));
    CHECK(scene.is_caustic_target(0));  // glass somewhere on it
    CHECK_FALSE(scene.material_of(0).is_specular());
    CHECK_THROWS_AS(scene.add(Sphere<double>({0, 0, 0}, 1), white, {}, {7}), std::invalid_argument);

    using C = DefaultCsg<double>;
    const C lens = C::intersection({Sphere<double>({0, 0, 0.5}, 1), Sphere<double>({0, 0, -0.5}, 1)});
    CHECK(plan::is_convex_solid(lens));
    CHECK(plan::shape_name(lens) == "intersection");
    CHECK(plan::contains_ball(lens, Vec3<double>(0, 0, 0), 0.2));
    CHECK_FALSE(plan::contains_ball(lens, Vec3<double>(0, 0, 0), 0.6));
    CHECK(plan::is_convex_solid(C::intersection({Sphere<double>({0, 0, 0}, 1), Plane<double>({0, 1, 0}, 0)})));
    const Transformed<Torus<double>> ring(Torus<double>(2, 1), Affine<double>::identity());
    CHECK_FALSE(plan::is_convex_solid(C::intersection({ring, Sphere<double>({0, 0, 0}, 3)})));
    const C holed = C::difference({Box<double>({-1, -1, -1}, {1, 1, 1}), Sphere<double>({0, 0, 0}, 0.5)});
    CHECK_FALSE(plan::is_convex_solid(holed));
    CHECK_FALSE(plan::contains_ball(holed, Vec3<double>(0, 0, 0), 0.1));
    CHECK(plan::shape_name(holed) == "difference");
    C inverse_lens = lens;
    inverse_lens.invert();
    CHECK_FALSE(plan::is_convex_solid(inverse_lens));
    CHECK(plan::shape_name(inverse_lens) == "inverse intersection");
    CHECK_FALSE(plan::is_flat(lens));
}

TEMPLATE_TEST_CASE("csg: an intersection of planes is bounded by its vertices, an open one only where it closes",
                   "[geometry][csg]", float, double) {
    using S = TestType;
    // An octahedron |x| + |y| + |z| <= 1 from eight planes (shapes2.inc's Octahedron), tilted.
    const Affine<S> tilt = Affine<S>::rotate_axis(Vec3<S>(S(0.3), S(0.5), S(0.1)), S(40));
    std::vector<TestCsg<S>> faces;
    for (int sx : {-1, 1})
        for (int sy : {-1, 1})
            for (int sz : {-1, 1}) {
                const Vec3<S> n = glm::normalize(tilt.vector(Vec3<S>(S(sx), S(sy), S(sz))));
                faces.push_back(TestCsg<S>(Plane<S>(n, S(1) / std::sqrt(S(3)))));
            }
    const auto octahedron = TestCsg<S>::intersection(faces);
    const BBox<S> b = octahedron.bounds();
    REQUIRE(b.is_finite());
    // The box holds every vertex (tilt of the six unit points) and is no larger than they need.
    Vec3<S> lo(S(10)), hi(S(-10));
    for (int a = 0; a < 3; ++a)
        for (S s : {S(-1), S(1)}) {
            Vec3<S> v(S(0));
            v[a] = s;
            const Vec3<S> p = tilt.vector(v);
            lo = glm::min(lo, p), hi = glm::max(hi, p);
            CHECK(b.contains(p));
        }
    for (int a = 0; a < 3; ++a) {
        CHECK(double(b.min[a]) == Approx(double(lo[a])).margin(1e-5));
        CHECK(double(b.max[a]) == Approx(double(hi[a])).margin(1e-5));
    }
    // Every hit of random rays lies in the box.
    Pcg32 rng(11, 3);
    int hits = 0;
    for (int i = 0; i < 2000; ++i) {
        const Vec3<S> origin = S(3) * uniform_sphere(rng.uniform2<S>());
        const Vec3<S> target = S(0.8) * (rng.uniform2<S>().x - S(0.5)) * uniform_sphere(rng.uniform2<S>());
        const auto h = octahedron.intersect({origin, glm::normalize(target - origin)});
        if (!h) continue;
        ++hits;
        CHECK(b.contains(h->point));
    }
    CHECK(hits > 1000);

    // Two planes, a slab: bounded along its normal only. A plane with an inverse side: the same.
    const auto slab = TestCsg<S>::intersection({Plane<S>({0, 1, 0}, S(1)), Plane<S>({0, -1, 0}, S(1))});
    CHECK(slab.bounds().max.y == Approx(1).margin(1e-5));
    CHECK(slab.bounds().min.y == Approx(-1).margin(1e-5));
    CHECK_FALSE(std::isfinite(slab.bounds().max.x));
    auto under = TestCsg<S>(Plane<S>({0, -1, 0}, S(1)));  // y >= -1, inverted: y < -1
    under.invert();
    const auto open_below = TestCsg<S>::intersection({Plane<S>({0, 1, 0}, S(1)), under});
    CHECK(open_below.bounds().max.y == Approx(-1).margin(1e-5));
    CHECK_FALSE(std::isfinite(open_below.bounds().min.y));
    // A box closes planes that do not close themselves.
    const auto cut = TestCsg<S>::intersection({Plane<S>({1, 1, 0}, S(0)), Box<S>({-1, -1, -1}, {1, 1, 1})});
    CHECK(cut.bounds().max.x == Approx(1).margin(1e-5));
    CHECK(cut.bounds().min.x == Approx(-1).margin(1e-5));
}
