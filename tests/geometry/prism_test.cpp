// SPDX-License-Identifier: MIT
// Prism (geometry/prism.hpp) and its outline (geometry/outline.hpp): a square prism against a box
// (same hits and normals for many rays), curved outlines against densely sampled points of their
// curves, holes by the even-odd rule, conic sweeps, grazing rays, rays leaving the surface, tiny
// and huge scales, the inside test against the parity of hits, and a prism in CSG.

#include <catch2/catch.hpp>

#include <photon/geometry/box.hpp>
#include <photon/geometry/csg.hpp>
#include <photon/geometry/prism.hpp>
#include <photon/geometry/solid.hpp>
#include <photon/geometry/transformed.hpp>
#include <photon/math/rng.hpp>
#include <photon/math/sampling.hpp>

#include <cmath>
#include <stdexcept>
#include <vector>

using namespace photon;

namespace {

template <class S> double prism_tol() { return std::is_same_v<S, float> ? 2e-4 : 1e-9; }

/// The square [-a, a]^2 as four lines, counter-clockwise or clockwise.
std::vector<OutlineSegment> prism_square(double a, bool clockwise = false) {
    std::vector<glm::dvec2> p{{-a, -a}, {a, -a}, {a, a}, {-a, a}};
    if (clockwise) std::reverse(p.begin(), p.end());
    std::vector<OutlineSegment> out;
    for (std::size_t k = 0; k < 4; ++k) out.push_back(OutlineSegment::line(p[k], p[(k + 1) % 4]));
    return out;
}

/// A closed curve of two cubic and one quadratic Bezier segments, bulging outwards.
std::vector<OutlineSegment> prism_blob() {
    const glm::dvec2 a(-1, 0), b(1, 0), c(0, 1.5);
    return {OutlineSegment::cubic(a, {-0.5, -1.2}, {0.5, -1.2}, b), OutlineSegment::cubic(b, {1.4, 0.8}, {0.6, 1.6}, c),
            OutlineSegment::quadratic(c, {-1.3, 1.4}, a)};
}

template <class S> Vec3<S> prism_uniform3(Pcg32& rng) {
    const Vec2<S> a = rng.uniform2<S>();
    return {a.x, a.y, rng.uniform<S>()};
}

glm::dvec2 prism_bezier_at(const OutlineSegment& g, double s) {
    // de Casteljau, independent of the power form the outline keeps
    std::array<glm::dvec2, 4> p = g.control;
    for (int level = g.degree; level > 0; --level)
        for (int i = 0; i < level; ++i) p[std::size_t(i)] = (1 - s) * p[std::size_t(i)] + s * p[std::size_t(i + 1)];
    return p[0];
}

/// Every crossing of the ray with the shape, walking from hit to hit.
template <class Shape, class S> int prism_crossings(const Shape& shape, Ray<S> ray) {
    int n = 0;
    while (auto h = shape.intersect(ray)) {
        ++n;
        ray.origin = h->point + ray.direction * (S(1e-4) * std::max(S(1), max_component(glm::abs(h->point))));
        if (n > 50) break;
    }
    return n;
}

}  // namespace

static_assert(Primitive<Prism<float>> && Solid<Prism<double>> && Solid<Transformed<Prism<float>>>);

TEMPLATE_TEST_CASE("prism: a square prism is a box, same hits and normals for many rays, at several scales",
                   "[geometry][prism]", float, double) {
    using S = TestType;
    for (const double scale : {1e-4, 1.0, 1e4}) {
        const S a = S(scale), h1 = S(-0.5 * scale), h2 = S(1.5 * scale);
        const Prism<S> prism(Outline({prism_square(double(a))}), h1, h2);
        const Box<S> box({-a, h1, -a}, {a, h2, a});
        CHECK(prism.bounds().min.x <= box.bounds().min.x);
        CHECK(prism.bounds().max.y >= box.bounds().max.y);
        Pcg32 rng(7, 1);
        int hits = 0;
        for (int i = 0; i < 2000; ++i) {
            // From a point in a cube three times the box's size (often inside) in a random direction.
            const Vec3<S> o = (prism_uniform3<S>(rng) * S(6) - S(3)) * a;
            const Vec3<S> d = uniform_sphere<S>(rng.uniform2<S>());
            const Ray<S> ray{o, d};
            const auto p = prism.intersect(ray), b = box.intersect(ray);
            REQUIRE(p.has_value() == b.has_value());
            CHECK(prism.contains(o) == box.contains(o));
            if (!p) continue;
            ++hits;
            CHECK(p->t == Approx(b->t).epsilon(prism_tol<S>()).margin(prism_tol<S>() * scale));
            CHECK(glm::dot(p->normal, b->normal) == Approx(1).epsilon(prism_tol<S>()));
        }
        CHECK(hits > 150);
    }
}

TEST_CASE("outline: points of quadratic and cubic curves, sampled densely, are where the crossings are", "[geometry][prism]") {
    const auto blob = prism_blob();
    const Outline outline({blob});
    for (const auto& g : blob)
        for (int i = 0; i <= 200; ++i) {
            const glm::dvec2 q = prism_bezier_at(g, i / 200.0);
            // A line through q in a direction that varies with i must report a crossing at q.
            const double angle = 0.3 + i * 0.77;
            const glm::dvec2 dir(std::cos(angle), std::sin(angle)), n(-dir.y, dir.x);
            double nearest = 1e9;
            glm::dvec2 outward(0.0);
            outline.for_each_crossing({n, -glm::dot(n, q)}, [&](const OutlineCrossing& c) {
                if (glm::length(c.point - q) < nearest) nearest = glm::length(c.point - q), outward = c.outward;
            });
            CHECK(nearest < 1e-9);
            // Just outside along the outward normal is outside, just inside is inside.
            const glm::dvec2 u = glm::normalize(outward);
            if (i > 0 && i < 200) {
                CHECK_FALSE(outline.contains(q + 1e-6 * u));
                CHECK(outline.contains(q - 1e-6 * u));
            }
        }
}

TEST_CASE("outline: even-odd holes, either winding, joints on the counting line", "[geometry][prism]") {
    for (const bool clockwise : {false, true}) {
        const Outline ring({prism_square(2), prism_square(1, clockwise)});
        CHECK(ring.contains({1.5, 0}));
        CHECK_FALSE(ring.contains({0, 0}));
        CHECK_FALSE(ring.contains({3, 0}));
        CHECK(ring.contains({-1.5, 1}));  // on the height of the hole's corners
        CHECK(ring.contains({-1.5, -1}));
        CHECK_FALSE(ring.contains({-2.5, 2}));  // on the height of the outer corners, outside
        // The hole's wall faces into the hole whichever way it runs.
        glm::dvec2 out(0.0);
        ring.for_each_crossing({{0, 1}, 0}, [&](const OutlineCrossing& c) {
            if (std::abs(c.point.x - 1) < 1e-12) out = c.outward;
        });
        CHECK(out.x < 0);
    }
    // A diamond: the counting line through its left and right corners and through its top.
    const Outline diamond({{OutlineSegment::line({0, -1}, {1, 0}), OutlineSegment::line({1, 0}, {0, 1}),
                            OutlineSegment::line({0, 1}, {-1, 0}), OutlineSegment::line({-1, 0}, {0, -1})}});
    CHECK(diamond.contains({0, 0}));
    CHECK(diamond.contains({-0.5, 0}));
    CHECK_FALSE(diamond.contains({-2, 0}));
    CHECK_FALSE(diamond.contains({-2, 1}));
    CHECK_THROWS_AS(Outline({{OutlineSegment::line({0, 0}, {1, 0}), OutlineSegment::line({1, 0}, {1, 1})}}),
                    std::invalid_argument);
}

TEMPLATE_TEST_CASE("prism: curved sides, grazing rays, rays from the surface, open, conic sweep", "[geometry][prism]",
                   float, double) {
    using S = TestType;
    const Prism<S> blob(Outline({prism_blob()}), 0, 1);
    // Every sampled point of the curves, seen from outside along its outward normal, is hit there.
    const auto segments = prism_blob();
    for (const auto& g : segments)
        for (int i = 1; i < 40; ++i) {
            const double s = i / 40.0;
            const glm::dvec2 q = prism_bezier_at(g, s);
            const glm::dvec2 t = prism_bezier_at(g, std::min(1.0, s + 1e-6)) - prism_bezier_at(g, std::max(0.0, s - 1e-6));
            const glm::dvec2 out = glm::normalize(glm::dvec2(t.y, -t.x));  // counter-clockwise outline: right is out
            const Vec3<S> target(S(q.x), S(0.5), S(q.y));
            const Vec3<S> from = target + Vec3<S>(S(out.x), S(0.3), S(out.y)) * S(3);
            const auto h = blob.intersect({from, target - from});
            REQUIRE(h);
            CHECK(glm::length(glm::dvec3(h->point - target)) < 1e3 * prism_tol<S>());
            CHECK(double(h->normal.x) * out.x + double(h->normal.z) * out.y == Approx(1).epsilon(1e-3));
            // From the surface outwards nothing; inwards the far wall.
            CHECK_FALSE(blob.intersect({h->point + Vec3<S>(S(out.x), 0, S(out.y)) * S(1e-4), from - target}));
            const auto back = blob.intersect({h->point - Vec3<S>(S(out.x), 0, S(out.y)) * S(1e-4), target - from});
            REQUIRE(back);
            CHECK(glm::dot(back->normal, target - from) > 0);
        }
    // Grazing the flat bottom of a square prism: along a face is no hit, just inside hits the far wall.
    const Prism<S> square(Outline({prism_square(1)}), 0, 1);
    CHECK_FALSE(square.intersect({{-5, 0.5, S(1) + S(1e-3)}, {1, 0, 0}}));
    const auto inside = square.intersect({{-5, 0.5, S(1) - S(1e-3)}, {1, 0, 0}});
    REQUIRE(inside);
    CHECK(inside->t == Approx(4).epsilon(prism_tol<S>()));
    // Open: down the tube there is nothing; the inside is the closed solid's.
    const Prism<S> open(Outline({prism_square(1)}), 0, 1, PrismSweep::linear, true);
    CHECK_FALSE(open.intersect({{0.5, 5, 0}, {0, -1, 0}}));
    CHECK(open.contains({0.5, 0.5, 0}));
    // Conic: the unit square at height 1 shrinks to the origin; between heights 0.5 and 1 a
    // frustum whose wall x = y (for |z| <= y) has normal (1, -1, 0) / sqrt 2.
    const Prism<S> cone(Outline({prism_square(1)}), S(0.5), 1, PrismSweep::conic);
    auto h = cone.intersect({{5, 0.75, 0}, {-1, 0, 0}});
    REQUIRE(h);
    CHECK(h->t == Approx(4.25).epsilon(prism_tol<S>()));
    CHECK(h->normal.x == Approx(std::sqrt(0.5)).epsilon(prism_tol<S>()));
    CHECK(h->normal.y == Approx(-std::sqrt(0.5)).epsilon(prism_tol<S>()));
    h = cone.intersect({{0.2, 5, 0.3}, {0, -1, 0}});  // the top cap
    REQUIRE(h);
    CHECK(h->t == Approx(4).epsilon(prism_tol<S>()));
    h = cone.intersect({{0.7, 0, 0}, {0, 1, 0}});  // up, beside the bottom cap: the wall, at y = x, from below
    REQUIRE(h);
    CHECK(h->point.y == Approx(0.7).epsilon(prism_tol<S>()));
    CHECK(h->normal.y == Approx(-std::sqrt(0.5)).epsilon(prism_tol<S>()));
    CHECK(cone.contains({0.6, 0.7, 0}));
    CHECK_FALSE(cone.contains({0.6, 0.55, 0}));
    CHECK(cone.bounds().min.x <= S(-1));
    CHECK_THROWS_AS(Prism<S>(Outline({prism_square(1)}), 1, 1), std::invalid_argument);
}

TEMPLATE_TEST_CASE("prism: the inside test agrees with the parity of hits, linear and conic, with a hole",
                   "[geometry][prism]", float, double) {
    using S = TestType;
    std::vector<std::vector<OutlineSegment>> contours{prism_blob()};
    contours.push_back(prism_square(0.3));  // a hole in the blob
    for (const auto sweep : {PrismSweep::linear, PrismSweep::conic}) {
        const Prism<S> prism(Outline(contours), S(0.5), S(2), sweep);
        Pcg32 rng(11, 2);
        int mismatches = 0, inside = 0;
        for (int i = 0; i < 1500; ++i) {
            const Vec3<S> o = prism_uniform3<S>(rng) * S(6) - Vec3<S>(3, 1, 3);
            const Vec3<S> d = uniform_sphere<S>(rng.uniform2<S>());
            const bool odd = prism_crossings(prism, Ray<S>{o, d}) % 2 == 1;
            inside += prism.contains(o);
            mismatches += odd != prism.contains(o);
        }
        CHECK(inside > 20);
        CHECK(mismatches <= 2);  // a ray through an edge may count it once or twice
    }
}

TEMPLATE_TEST_CASE("prism in CSG: a box engraved with a prism", "[geometry][prism]", float, double) {
    using S = TestType;
    using Engraving = Csg<S, Box<S>, Prism<S>>;
    // A 4x4 slab minus a square prism that reaches 0.5 into it from the top.
    Engraving csg = Engraving::difference({Box<S>({-2, 0, -2}, {2, 1, 2}), Prism<S>(Outline({prism_square(1)}), S(0.5), 2)});
    auto h = csg.intersect({{0, 5, 0}, {0, -1, 0}});  // into the engraving: its floor
    REQUIRE(h);
    CHECK(h->t == Approx(4.5).epsilon(prism_tol<S>()));
    CHECK(h->normal.y == Approx(1).epsilon(prism_tol<S>()));
    h = csg.intersect({{1.5, 5, 0}, {0, -1, 0}});  // beside it: the slab's top
    REQUIRE(h);
    CHECK(h->t == Approx(4).epsilon(prism_tol<S>()));
    h = csg.intersect({{0, 0.75, 0}, {1, 0, 0}});  // in the engraving: its wall, facing in
    REQUIRE(h);
    CHECK(h->t == Approx(1).epsilon(prism_tol<S>()));
    CHECK(h->normal.x == Approx(-1).epsilon(prism_tol<S>()));
    CHECK_FALSE(csg.contains({0, 0.75, 0}));
    CHECK(csg.contains({0, 0.25, 0}));
}
