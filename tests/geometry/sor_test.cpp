// SPDX-License-Identifier: MIT
// Sor (geometry/sor.hpp): point lists whose Hermite cubics are exactly a cylinder and a cone
// against Cylinder and TruncatedCone (many rays, float and double, scales 1e-3, 1, 1e3), a curved
// sor whose hits lie on the cubic written out independently, open and closed, rays from the
// surface, and the inside test against the parity of hits.

#include <catch2/catch.hpp>

#include <photon/geometry/cone.hpp>
#include <photon/geometry/cylinder.hpp>
#include <photon/geometry/solid.hpp>
#include <photon/geometry/sor.hpp>
#include <photon/geometry/transformed.hpp>
#include <photon/math/rng.hpp>
#include <photon/math/sampling.hpp>

#include <cmath>
#include <stdexcept>
#include <vector>

using namespace photon;

namespace {

template <class S> double sor_tol() { return std::is_same_v<S, float> ? 2e-4 : 1e-9; }

template <class S> Vec3<S> sor_uniform3(Pcg32& rng) {
    const Vec2<S> a = rng.uniform2<S>();
    return {a.x, a.y, rng.uniform<S>()};
}

template <class Shape, class S> int sor_crossings(const Shape& shape, Ray<S> ray) {
    int n = 0;
    while (auto h = shape.intersect(ray)) {
        ++n;
        ray.origin = h->point + ray.direction * (S(1e-4) * std::max(S(1), max_component(glm::abs(h->point))));
        if (n > 50) break;
    }
    return n;
}

template <class S, class A, class B> void sor_agree(const A& a, const B& b, double scale) {
    Pcg32 rng(7, 3);
    int hits = 0, edge_disagreements = 0;
    for (int i = 0; i < 3000; ++i) {
        const Vec3<S> o = (sor_uniform3<S>(rng) * S(6) - Vec3<S>(3, 1.5, 3)) * S(scale);
        const Vec3<S> d = uniform_sphere<S>(rng.uniform2<S>());
        const auto p = a.intersect({o, d}), q = b.intersect({o, d});
        CHECK(a.contains(o) == b.contains(o));
        if (p.has_value() != q.has_value()) {
            ++edge_disagreements;
            continue;
        }
        if (!p) continue;
        ++hits;
        CHECK(p->t == Approx(q->t).epsilon(sor_tol<S>()).margin(sor_tol<S>() * scale));
        CHECK(glm::dot(p->normal, q->normal) == Approx(1).epsilon(sor_tol<S>()));
    }
    CHECK(edge_disagreements <= 1);
    CHECK(hits > 100);
}

/// r^2 at height y on the segment from (x1, y1) to (x2, y2), by the Hermite basis in y, slopes as
/// POV-Ray's Compute_Sor takes them from the neighbours p0 and p3.
double sor_radius2(glm::dvec2 p0, glm::dvec2 p1, glm::dvec2 p2, glm::dvec2 p3, double y) {
    const double h = p2.y - p1.y, u = (y - p1.y) / h;
    const double k0 = 2 * p1.x * (p2.x - p0.x) / (p2.y - p0.y), k1 = 2 * p2.x * (p3.x - p1.x) / (p3.y - p1.y);
    const double h00 = 2 * u * u * u - 3 * u * u + 1, h10 = u * u * u - 2 * u * u + u, h01 = -2 * u * u * u + 3 * u * u,
                 h11 = u * u * u - u * u;
    return h00 * p1.x * p1.x + h10 * h * k0 + h01 * p2.x * p2.x + h11 * h * k1;
}

}  // namespace

static_assert(Primitive<Sor<float>> && Solid<Sor<double>> && Solid<Transformed<Sor<float>>>);

TEMPLATE_TEST_CASE("sor: a cylinder and a cone from their points, at several scales", "[geometry][sor]", float, double) {
    using S = TestType;
    for (const double scale : {1e-3, 1.0, 1e3}) {
        const Affine<S> to_world = Affine<S>::scale(Vec3<S>(S(scale)));
        const Transformed<Sor<S>> tube(Sor<S>({{1, -1}, {1, 0}, {1, 1}, {1, 2}}), to_world);
        sor_agree<S>(tube, Cylinder<S>({0, 0, 0}, {0, S(scale), 0}, S(scale)), scale);
        // r = y / 2 through the apex: r^2 = y^2 / 4 is a cubic the Hermite slopes reproduce.
        const Transformed<Sor<S>> cone(Sor<S>({{0.25, 0.5}, {0.5, 1}, {1, 2}, {1.5, 3}}), to_world);
        sor_agree<S>(cone, TruncatedCone<S>({0, S(scale), 0}, S(0.5 * scale), {0, S(2 * scale), 0}, S(scale)), scale);
    }
}

TEMPLATE_TEST_CASE("sor: a curved sor's hits lie on its cubics, open and closed, rays from the surface",
                   "[geometry][sor]", float, double) {
    using S = TestType;
    const std::vector<glm::dvec2> points{{0, -0.5}, {0.6, 0}, {1.1, 0.5}, {0.4, 1.2}, {0.7, 1.8}, {0.9, 2.2}};
    const Sor<S> vase(points), open(points, true);
    Pcg32 rng(5, 9);
    int side_hits = 0;
    for (int i = 0; i < 2000; ++i) {
        const Vec3<S> target = sor_uniform3<S>(rng) * Vec3<S>(2, S(1.8), 2) - Vec3<S>(1, 0, 1);
        const Vec3<S> o = uniform_sphere<S>(rng.uniform2<S>()) * S(5) + Vec3<S>(0, 1, 0);
        const auto h = vase.intersect({o, target - o});
        if (!h) continue;
        const glm::dvec3 p(h->point);
        if (std::abs(std::abs(h->normal.y) - S(1)) < S(1e-6)) {
            CHECK((std::abs(p.y) < 1e-4 || std::abs(p.y - 1.8) < 1e-4));  // a cap
            continue;
        }
        ++side_hits;
        const std::size_t k = p.y < 0.5 ? 0 : p.y < 1.2 ? 1 : 2;
        const double r2 = sor_radius2(points[k], points[k + 1], points[k + 2], points[k + 3], p.y);
        CHECK(p.x * p.x + p.z * p.z == Approx(r2).epsilon(1e2 * sor_tol<S>()).margin(1e2 * sor_tol<S>()));
        CHECK(glm::dot(h->normal, o - h->point) > S(0));  // seen from outside: facing the ray's origin
        // Just outside along the normal: the ray on from there outwards misses.
        CHECK_FALSE(vase.intersect({h->point + h->normal * S(1e-3), h->normal}));
    }
    CHECK(side_hits > 200);
    // Down the axis: the closed one's cap, the open one's floor... none: open has no floor either.
    auto h = vase.intersect({{0, 5, 0}, {0, -1, 0}});
    REQUIRE(h);
    CHECK(h->t == Approx(5 - 1.8).epsilon(sor_tol<S>()));
    CHECK(h->normal.y == Approx(1).epsilon(sor_tol<S>()));
    CHECK_FALSE(open.intersect({{0, 5, 0}, {0, -1, 0}}));
    CHECK(open.contains({0, 1, 0}));
    // From inside, level: the wall at the radius of that height.
    h = vase.intersect({{0, S(0.5), 0}, {1, 0, 0}});
    REQUIRE(h);
    CHECK(h->t == Approx(1.1).epsilon(sor_tol<S>()));
    CHECK_THROWS_AS(Sor<S>({{1, 0}, {1, 1}, {1, 2}}), std::invalid_argument);
    CHECK_THROWS_AS(Sor<S>({{1, 0}, {1, 1}, {1, 1}, {1, 2}, {1, 3}}), std::invalid_argument);
    CHECK_THROWS_AS(Sor<S>({{1, 0}, {-1, 1}, {1, 2}, {1, 3}}), std::invalid_argument);
}

TEMPLATE_TEST_CASE("sor: the inside test agrees with the parity of hits", "[geometry][sor]", float, double) {
    using S = TestType;
    const Sor<S> vase({{0, -0.5}, {0.6, 0}, {1.1, 0.5}, {0.4, 1.2}, {0.7, 1.8}, {0.9, 2.2}});
    Pcg32 rng(11, 2);
    int mismatches = 0, inside = 0;
    for (int i = 0; i < 1500; ++i) {
        const Vec3<S> o = sor_uniform3<S>(rng) * S(3) - Vec3<S>(1.5, 0.5, 1.5);
        const Vec3<S> d = uniform_sphere<S>(rng.uniform2<S>());
        const bool odd = sor_crossings(vase, Ray<S>{o, d}) % 2 == 1;
        inside += vase.contains(o);
        mismatches += odd != vase.contains(o);
    }
    CHECK(inside > 20);
    CHECK(mismatches <= 2);
}
