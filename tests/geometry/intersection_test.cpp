// SPDX-License-Identifier: MIT
// Ray/primitive intersections: hits, misses, grazing rays, rays from inside and from the surface,
// transformed shapes, and the mesh BVH against brute force.

#include <catch2/catch.hpp>

#include <photon/geometry/box.hpp>
#include <photon/geometry/plane.hpp>
#include <photon/geometry/sphere.hpp>
#include <photon/geometry/transformed.hpp>
#include <photon/geometry/triangle.hpp>
#include <photon/geometry/triangle_mesh.hpp>
#include <photon/math/rng.hpp>
#include <photon/math/sampling.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

using namespace photon;

template <class S> S tol() { return std::is_same_v<S, float> ? S(1e-5) : S(1e-12); }

TEMPLATE_TEST_CASE("sphere: outside, inside, on the surface, grazing, behind", "[geometry]", float, double) {
    using S = TestType;
    const Sphere<S> s({1, 2, 3}, 2);
    SECTION("hit from outside returns the near root and an outward normal") {
        const auto h = s.intersect({{1, 2, -7}, {0, 0, 1}});
        REQUIRE(h);
        CHECK(h->t == Approx(8).epsilon(tol<S>()));
        CHECK(h->normal.z == Approx(-1).epsilon(tol<S>()));
    }
    SECTION("ray from the centre hits the far side with the outward normal") {
        const auto h = s.intersect({{1, 2, 3}, {1, 0, 0}});
        REQUIRE(h);
        CHECK(h->t == Approx(2).epsilon(tol<S>()));
        CHECK(h->normal.x == Approx(1).epsilon(tol<S>()));
    }
    SECTION("ray starting on the surface going in hits the far side, going out misses") {
        const auto in = s.intersect({{1, 2, 1}, {0, 0, 1}});
        REQUIRE(in);
        CHECK(in->t == Approx(4).epsilon(S(100) * tol<S>()));
        CHECK_FALSE(s.intersect({{1, 2, 1}, {0, 0, -1}}));
    }
    SECTION("grazing ray tangent to the sphere hits at most at the tangent point, never NaN") {
        const auto h = s.intersect({{3, 2, -10}, {0, 0, 1}});
        if (h) {
            CHECK(h->t == Approx(13).epsilon(S(1e-3)));
            CHECK(is_finite(h->normal));
        }
        CHECK_FALSE(s.intersect({{3 + S(1e-3), 2, -10}, {0, 0, 1}}));
    }
    SECTION("sphere behind the ray is missed; t_max bounds the hit") {
        CHECK_FALSE(s.intersect({{1, 2, 10}, {0, 0, 1}}));
        CHECK_FALSE(s.intersect({{1, 2, -7}, {0, 0, 1}, S(7.9)}));
    }
    SECTION("far away sphere: the stable quadratic keeps the hit on the surface") {
        const Sphere<S> far({0, 0, S(1e4)}, S(1));
        const auto h = far.intersect({{0, S(0.5), 0}, {0, 0, 1}});
        REQUIRE(h);
        const S expected = S(1e4) - std::sqrt(S(0.75));
        CHECK(std::abs(h->t - expected) < S(1e4) * S(64) * std::numeric_limits<S>::epsilon());
    }
    SECTION("invalid radius is rejected") {
        CHECK_THROWS_AS(Sphere<S>({0, 0, 0}, 0), std::invalid_argument);
        CHECK_THROWS_AS(Sphere<S>({0, 0, 0}, -1), std::invalid_argument);
        CHECK_THROWS_AS(Sphere<S>({0, 0, 0}, std::numeric_limits<S>::quiet_NaN()), std::invalid_argument);
    }
}

TEMPLATE_TEST_CASE("plane: both sides, parallel rays, rays on the plane", "[geometry]", float, double) {
    using S = TestType;
    const Plane<S> p({0, 2, 0}, 1);  // y = 1, normal normalised
    const auto h = p.intersect({{0, 3, 0}, {0, -1, 0}});
    REQUIRE(h);
    CHECK(h->t == Approx(2));
    CHECK(h->normal.y == Approx(1));
    const auto below = p.intersect({{0, -1, 0}, {0, 1, 0}});
    REQUIRE(below);
    CHECK(below->normal.y == Approx(1));  // the normal is not flipped towards the ray
    CHECK_FALSE(p.intersect({{0, 3, 0}, {1, 0, 0}}));  // parallel
    CHECK_FALSE(p.intersect({{0, 1, 0}, {1, 0, 0}}));  // in the plane
    CHECK_FALSE(p.intersect({{0, 3, 0}, {0, 1, 0}}));  // pointing away
    CHECK_THROWS_AS(Plane<S>({0, 0, 0}, 1), std::invalid_argument);
}

TEMPLATE_TEST_CASE("box: faces, inside, edges, zero thickness", "[geometry]", float, double) {
    using S = TestType;
    const Box<S> b({1, 1, 1}, {-1, -1, -1});  // corners in any order
    const auto h = b.intersect({{-5, 0, 0}, {1, 0, 0}});
    REQUIRE(h);
    CHECK(h->t == Approx(4));
    CHECK(h->normal.x == Approx(-1));
    const auto inside = b.intersect({{0, 0, 0}, {0, 0, -1}});
    REQUIRE(inside);
    CHECK(inside->t == Approx(1));
    CHECK(inside->normal.z == Approx(-1));  // outward
    // Along an edge and in a face's plane: no NaN, either a clean hit or a clean miss.
    const auto edge = b.intersect({{-5, 1, 1}, {1, 0, 0}});
    if (edge) CHECK(is_finite(edge->normal));
    CHECK_FALSE(b.intersect({{-5, 2, 0}, {1, 0, 0}}));
    const Box<S> sheet({-1, 0, -1}, {1, 0, 1});
    const auto s = sheet.intersect({{0, 1, 0}, {0, -1, 0}});
    REQUIRE(s);
    CHECK(s->t == Approx(1));
    CHECK(s->normal.y == Approx(1));
}

TEMPLATE_TEST_CASE("triangle: inside, outside, degenerate", "[geometry]", float, double) {
    using S = TestType;
    const Triangle<S> t({0, 0, 0}, {1, 0, 0}, {0, 1, 0});
    const auto h = t.intersect({{S(0.25), S(0.25), 1}, {0, 0, -1}});
    REQUIRE(h);
    CHECK(h->t == Approx(1));
    CHECK(h->normal.z == Approx(1));  // counter-clockwise seen from +z
    CHECK_FALSE(t.intersect({{1, 1, 1}, {0, 0, -1}}));
    CHECK_FALSE(t.intersect({{S(0.25), S(0.25), 1}, {1, 0, 0}}));
    const Triangle<S> collinear({0, 0, 0}, {1, 1, 1}, {2, 2, 2});
    const Triangle<S> point({1, 1, 1}, {1, 1, 1}, {1, 1, 1});
    CHECK(collinear.is_degenerate());
    CHECK(point.is_degenerate());
    CHECK_FALSE(collinear.intersect({{1, 1, 0}, {0, 0, 1}}));
    CHECK_FALSE(point.intersect({{1, 1, 0}, {0, 0, 1}}));
}

TEMPLATE_TEST_CASE("transformed primitives: ellipsoid and rotated box", "[geometry]", float, double) {
    using S = TestType;
    const Transformed<Sphere<S>> ellipsoid(Sphere<S>({0, 0, 0}, 1),
                                           Affine<S>::scale({2, 1, 1}).then(Affine<S>::translate({0, 0, 5})));
    const auto h = ellipsoid.intersect({{-10, 0, 5}, {1, 0, 0}});
    REQUIRE(h);
    CHECK(h->t == Approx(8));
    CHECK(h->normal.x == Approx(-1));
    // The ellipsoid (x/2)^2 + y^2 + (z-5)^2 = 1 is met at z = 5 - sqrt(0.5) by the ray through
    // (1, 0.5); its normal is along the gradient (x/2, 2y, 2(z-5)).
    const auto g = ellipsoid.intersect({{1, S(0.5), 0}, {0, 0, 1}});
    REQUIRE(g);
    CHECK(g->t == Approx(5 - std::sqrt(S(0.5))));
    const Vec3<S> expected = glm::normalize(Vec3<S>(S(0.5), 1, -2 * std::sqrt(S(0.5))));
    CHECK(glm::dot(g->normal, expected) == Approx(1).epsilon(S(1e-4)));
    const Transformed<Box<S>> rotated(Box<S>({-1, -1, -1}, {1, 1, 1}),
                                      Affine<S>::rotate_xyz({0, 45, 0}).then(Affine<S>::translate({0, 0, 5})));
    const auto r = rotated.intersect({{0, 0, 0}, {0, 0, 1}});
    REQUIRE(r);
    CHECK(r->t == Approx(5 - std::sqrt(S(2))));
    CHECK(rotated.bounds().max.x == Approx(std::sqrt(S(2))));
    CHECK_THROWS_AS(Transformed<Sphere<S>>(Sphere<S>({0, 0, 0}, 1), Affine<S>::scale({1, 0, 1})), std::invalid_argument);
}

TEMPLATE_TEST_CASE("rotation follows POV-Ray: rotate <0,90,0> takes +x to -z", "[geometry]", float, double) {
    using S = TestType;
    const Vec3<S> v = Affine<S>::rotate_xyz({0, 90, 0}).vector({1, 0, 0});
    CHECK(v.x == Approx(0).margin(1e-6));
    CHECK(v.z == Approx(-1));
}

TEMPLATE_TEST_CASE("mesh BVH finds the same nearest hit as testing every triangle", "[geometry]", float, double) {
    using S = TestType;
    Pcg32 rng(42, 0);
    std::vector<Vec3<S>> positions;
    std::vector<typename TriangleMesh<S>::Index> tris;
    for (std::uint32_t i = 0; i < 2000; ++i) {
        const Vec3<S> c{rng.uniform<S>() * 10, rng.uniform<S>() * 10, rng.uniform<S>() * 10};
        for (int k = 0; k < 3; ++k)
            positions.push_back(c + Vec3<S>{rng.uniform<S>(), rng.uniform<S>(), rng.uniform<S>()} - S(0.5));
        tris.push_back({3 * i, 3 * i + 1, 3 * i + 2});
    }
    const TriangleMesh<S> mesh(positions, tris);
    for (int r = 0; r < 500; ++r) {
        const Ray<S> ray{{rng.uniform<S>() * 10, rng.uniform<S>() * 10, S(-1)},
                         glm::normalize(Vec3<S>{rng.uniform<S>() - S(0.5), rng.uniform<S>() - S(0.5), 1})};
        S best = std::numeric_limits<S>::infinity();
        for (const auto& t : tris) {
            const Triangle<S> tri(positions[t[0]], positions[t[1]], positions[t[2]]);
            if (const auto h = tri.intersect(ray)) best = std::min(best, h->t);
        }
        const auto h = mesh.intersect(ray);
        if (best == std::numeric_limits<S>::infinity()) {
            CHECK_FALSE(h);
            CHECK_FALSE(mesh.occluded(ray));
        } else {
            REQUIRE(h);
            CHECK(h->t == Approx(best));
            CHECK(mesh.occluded(ray));
        }
    }
    CHECK_THROWS_AS(TriangleMesh<S>(positions, {{0, 1, 99999}}), std::invalid_argument);
}

TEST_CASE("BVH of coincident boxes stays shallow", "[geometry]") {
    std::vector<BBox<float>> boxes(100000, BBox<float>{{0, 0, 0}, {1, 1, 1}});
    std::vector<Vec3<float>> centers(boxes.size(), Vec3<float>(0.5f));
    const Bvh<float> bvh(boxes, centers);
    CHECK(bvh.depth() <= 20);
    Ray<float> ray{{0.5f, 0.5f, -1}, {0, 0, 1}};
    std::size_t tested = 0;
    bvh.intersect(ray, [&](std::uint32_t, Ray<float>&) { ++tested; return false; });
    CHECK(tested == boxes.size());
}

// The float build runs in SSE (geometry/bvh_build_sse.hpp) and loads representative points only when
// they are not the boxes' centres; double runs the scalar build. Both must index every box:
// overlap queries against brute force, over nodes large enough for the build's two sets of bins.
TEMPLATE_TEST_CASE("BVH with representative points other than box centres finds every overlapping box",
                   "[geometry]", float, double) {
    using S = TestType;
    Pcg32 rng(7, 0);
    std::vector<BBox<S>> boxes;
    std::vector<Vec3<S>> points;
    for (int i = 0; i < 3000; ++i) {
        const Vec3<S> lo{rng.uniform<S>() * 20, rng.uniform<S>() * 20, rng.uniform<S>() * 20};
        // Every fourth box flat on one axis, as walls and triangles are.
        const Vec3<S> size{rng.uniform<S>(), i % 4 == 0 ? S(0) : rng.uniform<S>(), rng.uniform<S>() * 3};
        boxes.push_back({lo, lo + size});
        points.push_back(lo + size * Vec3<S>{rng.uniform<S>(), rng.uniform<S>(), rng.uniform<S>()});
    }
    for (const unsigned block : {1u, 4u}) {
        BvhConfig config;
        config.leaf_block = block;
        const Bvh<S> bvh(boxes, points, config);
        for (int q = 0; q < 200; ++q) {
            const Vec3<S> lo{rng.uniform<S>() * 20, rng.uniform<S>() * 20, rng.uniform<S>() * 20};
            const BBox<S> query{lo, lo + Vec3<S>(rng.uniform<S>() * 4)};
            std::vector<std::uint32_t> found, expected;
            bvh.for_each_overlapping(query, [&](std::uint32_t position) {
                const std::uint32_t id = bvh.primitive_indices()[position];
                if (id != Bvh<S>::padding) found.push_back(id);
            });
            for (std::uint32_t i = 0; i < boxes.size(); ++i)
                if (boxes[i].overlaps(query)) expected.push_back(i);
            std::sort(found.begin(), found.end());
            found.erase(std::unique(found.begin(), found.end()), found.end());
            // A leaf may hand over boxes that miss the query; it must not leave one out.
            CHECK(std::includes(found.begin(), found.end(), expected.begin(), expected.end()));
        }
    }
}
