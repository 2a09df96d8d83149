// SPDX-License-Identifier: MIT
// Lathe (geometry/lathe.hpp): line profiles of a cylinder and a cone against Cylinder and
// TruncatedCone (same hits and normals for many rays, float and double, scaled by 1e-3, 1 and
// 1e3), curved profiles hit at densely sampled points of their curves, level and grazing rays,
// rays from the surface, and the inside test against the parity of hits.

#include <catch2/catch.hpp>

#include <photon/geometry/cone.hpp>
#include <photon/geometry/cylinder.hpp>
#include <photon/geometry/lathe.hpp>
#include <photon/geometry/solid.hpp>
#include <photon/geometry/transformed.hpp>
#include <photon/math/rng.hpp>
#include <photon/math/sampling.hpp>

#include <cmath>
#include <numbers>
#include <stdexcept>
#include <vector>

using namespace photon;

namespace {

template <class S> double lathe_tol() { return std::is_same_v<S, float> ? 2e-4 : 1e-9; }

template <class S> Vec3<S> lathe_uniform3(Pcg32& rng) {
    const Vec2<S> a = rng.uniform2<S>();
    return {a.x, a.y, rng.uniform<S>()};
}

/// A closed line profile through the given (radius, height) points.
std::vector<OutlineSegment> lathe_polyline(const std::vector<glm::dvec2>& p) {
    std::vector<OutlineSegment> out;
    for (std::size_t i = 0; i + 1 < p.size(); ++i) out.push_back(OutlineSegment::line(p[i], p[i + 1]));
    return out;
}

/// A convex vase-like profile: the floor, a cubic side bulging out, a quadratic dome to the axis.
std::vector<OutlineSegment> lathe_bulb() {
    return {OutlineSegment::line({0, 0}, {1, 0}), OutlineSegment::cubic({1, 0}, {1.6, 0.6}, {1.3, 1.6}, {0.8, 2}),
            OutlineSegment::quadratic({0.8, 2}, {0.5, 2.4}, {0, 2.4})};
}

glm::dvec2 lathe_bezier_at(const OutlineSegment& g, double s) {
    std::array<glm::dvec2, 4> p = g.control;  // de Casteljau, independent of the power form
    for (int level = g.degree; level > 0; --level)
        for (int i = 0; i < level; ++i) p[std::size_t(i)] = (1 - s) * p[std::size_t(i)] + s * p[std::size_t(i + 1)];
    return p[0];
}

template <class Shape, class S> int lathe_crossings(const Shape& shape, Ray<S> ray) {
    int n = 0;
    while (auto h = shape.intersect(ray)) {
        ++n;
        ray.origin = h->point + ray.direction * (S(1e-4) * std::max(S(1), max_component(glm::abs(h->point))));
        if (n > 50) break;
    }
    return n;
}

/// Many random rays: the same hits and normals from both shapes (rays through an edge may differ).
template <class S, class A, class B> void lathe_agree(const A& a, const B& b, double scale) {
    Pcg32 rng(7, 1);
    int hits = 0, edge_disagreements = 0;
    for (int i = 0; i < 3000; ++i) {
        const Vec3<S> o = (lathe_uniform3<S>(rng) * S(6) - Vec3<S>(3, 2, 3)) * S(scale);
        const Vec3<S> d = uniform_sphere<S>(rng.uniform2<S>());
        const auto p = a.intersect({o, d}), q = b.intersect({o, d});
        CHECK(a.contains(o) == b.contains(o));
        if (p.has_value() != q.has_value()) {
            ++edge_disagreements;
            continue;
        }
        if (!p) continue;
        ++hits;
        CHECK(p->t == Approx(q->t).epsilon(lathe_tol<S>()).margin(lathe_tol<S>() * scale));
        CHECK(glm::dot(p->normal, q->normal) == Approx(1).epsilon(lathe_tol<S>()));
    }
    CHECK(edge_disagreements <= 1);
    CHECK(hits > 150);
}

}  // namespace

static_assert(Primitive<Lathe<float>> && Solid<Lathe<double>> && Solid<Transformed<Lathe<float>>>);

TEMPLATE_TEST_CASE("lathe: line profiles are a cylinder and a cone, at several scales", "[geometry][lathe]", float, double) {
    using S = TestType;
    for (const double scale : {1e-3, 1.0, 1e3}) {
        const Affine<S> to_world = Affine<S>::scale(Vec3<S>(S(scale)));
        const Transformed<Lathe<S>> tube(Lathe<S>(lathe_polyline({{0, 0}, {1, 0}, {1, 2}, {0, 2}})), to_world);
        const Cylinder<S> cylinder({0, 0, 0}, {0, S(2 * scale), 0}, S(scale));
        lathe_agree<S>(tube, cylinder, scale);
        // The profile drawn the other way round (clockwise) is the same solid.
        const Transformed<Lathe<S>> cone(Lathe<S>(lathe_polyline({{0, 2}, {0.5, 2}, {1, 0}, {0, 0}})), to_world);
        const TruncatedCone<S> frustum({0, 0, 0}, S(scale), {0, S(2 * scale), 0}, S(0.5 * scale));
        lathe_agree<S>(cone, frustum, scale);
    }
}

TEMPLATE_TEST_CASE("lathe: curved profiles are hit at sampled points of their curves, normals outward",
                   "[geometry][lathe]", float, double) {
    using S = TestType;
    const auto profile = lathe_bulb();
    const Lathe<S> bulb(profile);
    int checked = 0;
    for (const auto& g : profile)
        for (int i = 1; i < 60; ++i) {
            const double s = i / 60.0, angle = 0.7 + 2.1 * i;
            const glm::dvec2 q = lathe_bezier_at(g, s);
            const glm::dvec2 k = lathe_bezier_at(g, std::min(1.0, s + 1e-6)) - lathe_bezier_at(g, std::max(0.0, s - 1e-6));
            const glm::dvec2 out = glm::normalize(glm::dvec2(k.y, -k.x));  // counter-clockwise: right is out
            const glm::dvec3 radial(std::cos(angle), 0, std::sin(angle));
            const glm::dvec3 target = q.x * radial + glm::dvec3(0, q.y, 0);
            const glm::dvec3 normal = out.x * radial + glm::dvec3(0, out.y, 0);
            // From outside, along the normal tilted a little sideways.
            const glm::dvec3 from = target + 3.0 * normal + 0.4 * glm::cross(normal, radial);
            const auto h = bulb.intersect({Vec3<S>(from), Vec3<S>(target - from)});
            REQUIRE(h);
            ++checked;
            CHECK(glm::length(glm::dvec3(h->point) - target) < 1e2 * lathe_tol<S>());
            CHECK(glm::dot(glm::dvec3(h->normal), normal) == Approx(1).epsilon(1e-4));
            // From just outside the hit, outwards: nothing; from just inside, inwards: the far wall, seen from inside.
            CHECK_FALSE(bulb.intersect({h->point + Vec3<S>(normal) * S(1e-3), Vec3<S>(from - target)}));
            const auto back = bulb.intersect({h->point - Vec3<S>(normal) * S(1e-3), Vec3<S>(target - from)});
            REQUIRE(back);
            CHECK(glm::dot(back->normal, Vec3<S>(target - from)) > 0);
        }
    CHECK(checked > 150);
}

TEMPLATE_TEST_CASE("lathe: level rays, grazing rays, rays along the axis", "[geometry][lathe]", float, double) {
    using S = TestType;
    const Lathe<S> tube(lathe_polyline({{0, 0}, {1, 0}, {1, 2}, {0, 2}}));
    // Level, through the middle and off it: the wall at x = -sqrt(1 - z^2).
    for (const S z : {S(0), S(0.6), S(0.999)}) {
        const auto h = tube.intersect({{-5, S(0.7), z}, {1, 0, 0}});
        REQUIRE(h);
        CHECK(h->t == Approx(5 - std::sqrt(1 - double(z) * double(z))).epsilon(lathe_tol<S>() * 10));
        CHECK(h->normal.y == Approx(0).margin(1e-6));
    }
    // Nearly level (a slope below the switch to the level method and above it): the same as the cylinder.
    const Cylinder<S> cylinder({0, 0, 0}, {0, 2, 0}, 1);
    for (const double slope : {1e-7, 3e-6, 2e-5, 1e-3}) {
        const Ray<S> ray{{-5, S(0.7), S(0.3)}, {1, S(slope), 0}};
        const auto a = tube.intersect(ray), b = cylinder.intersect(ray);
        REQUIRE(a);
        REQUIRE(b);
        CHECK(a->t == Approx(b->t).epsilon(lathe_tol<S>()));
    }
    // Grazing the wall just outside, and the top face edge-on.
    CHECK_FALSE(tube.intersect({{-5, 1, S(1.001)}, {1, 0, 0}}));
    CHECK_FALSE(tube.intersect({{-5, S(2.001), 0}, {1, 0, 0}}));
    // Down the axis: the top, then from inside the bottom.
    auto h = tube.intersect({{0, 5, 0}, {0, -1, 0}});
    REQUIRE(h);
    CHECK(h->t == Approx(3).epsilon(lathe_tol<S>()));
    CHECK(h->normal.y == Approx(1).epsilon(lathe_tol<S>()));
    h = tube.intersect({{S(0.3), 1, 0}, {0, -1, 0}});
    REQUIRE(h);
    CHECK(h->t == Approx(1).epsilon(lathe_tol<S>()));
    CHECK(h->normal.y == Approx(-1).epsilon(lathe_tol<S>()));
    CHECK(tube.contains({S(0.3), 1, S(0.2)}));
    CHECK_FALSE(tube.contains({S(1.1), 1, 0}));
    CHECK_THROWS_AS(Lathe<S>(std::vector<OutlineSegment>{}), std::invalid_argument);
}

TEMPLATE_TEST_CASE("lathe: the inside test agrees with the parity of hits, an open profile and a hollow one",
                   "[geometry][lathe]", float, double) {
    using S = TestType;
    // The bulb, and a thick-walled cup (a closed profile not touching the axis: a ring).
    const std::vector<std::vector<OutlineSegment>> profiles{
        lathe_bulb(), lathe_polyline({{0.5, 0}, {1, 0}, {1.2, 1.5}, {0.9, 1.5}, {0.6, 0.3}, {0.5, 0}})};
    for (const auto& profile : profiles) {
        const Lathe<S> shape(profile);
        Pcg32 rng(11, 2);
        int mismatches = 0, inside = 0;
        for (int i = 0; i < 1500; ++i) {
            const Vec3<S> o = lathe_uniform3<S>(rng) * S(4) - Vec3<S>(2, 1, 2);
            const Vec3<S> d = uniform_sphere<S>(rng.uniform2<S>());
            const bool odd = lathe_crossings(shape, Ray<S>{o, d}) % 2 == 1;
            inside += shape.contains(o);
            mismatches += odd != shape.contains(o);
        }
        CHECK(inside > 20);
        CHECK(mismatches <= 2);
    }
}
