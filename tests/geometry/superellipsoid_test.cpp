// SPDX-License-Identifier: MIT
// Superellipsoid (geometry/superellipsoid.hpp): e = n = 1 is the unit sphere and small e, n the
// cube (same hits and normals for many rays, float and double, scaled by 1e-3, 1 and 1e3), star
// shapes (e, n > 2) with thin ridges hit where their implicit function says, grazing rays, rays
// from the surface, and the inside test against the parity of hits.

#include <catch2/catch.hpp>

#include <photon/geometry/box.hpp>
#include <photon/geometry/solid.hpp>
#include <photon/geometry/sphere.hpp>
#include <photon/geometry/superellipsoid.hpp>
#include <photon/geometry/transformed.hpp>
#include <photon/math/rng.hpp>
#include <photon/math/sampling.hpp>

#include <cmath>
#include <stdexcept>

using namespace photon;

namespace {

template <class S> double super_tol() { return std::is_same_v<S, float> ? 2e-4 : 1e-9; }

template <class S> Vec3<S> super_uniform3(Pcg32& rng) {
    const Vec2<S> a = rng.uniform2<S>();
    return {a.x, a.y, rng.uniform<S>()};
}

/// N(p) of POV-Ray's superellipsoid, written out directly (not through the class's scaled form).
double super_size(glm::dvec3 p, double e, double n) {
    p = glm::abs(p);
    return std::pow(std::pow(std::pow(p.x, 2 / e) + std::pow(p.y, 2 / e), e / n) + std::pow(p.z, 2 / n), n / 2);
}

template <class Shape, class S> int super_crossings(const Shape& shape, Ray<S> ray) {
    int n = 0;
    while (auto h = shape.intersect(ray)) {
        ++n;
        ray.origin = h->point + ray.direction * (S(1e-4) * std::max(S(1), max_component(glm::abs(h->point))));
        if (n > 50) break;
    }
    return n;
}

}  // namespace

static_assert(Primitive<Superellipsoid<float>> && Solid<Superellipsoid<double>> &&
              Solid<Transformed<Superellipsoid<float>>>);

TEMPLATE_TEST_CASE("superellipsoid: e = n = 1 is the unit sphere, at several scales", "[geometry][superellipsoid]",
                   float, double) {
    using S = TestType;
    for (const double scale : {1e-3, 1.0, 1e3}) {
        const Transformed<Superellipsoid<S>> super(Superellipsoid<S>(1, 1), Affine<S>::scale(Vec3<S>(S(scale))));
        const Sphere<S> sphere(Vec3<S>(0), S(scale));
        Pcg32 rng(3, 1);
        int hits = 0;
        for (int i = 0; i < 3000; ++i) {
            const Vec3<S> o = (super_uniform3<S>(rng) * S(6) - S(3)) * S(scale);
            const Vec3<S> d = uniform_sphere<S>(rng.uniform2<S>());
            const auto a = super.intersect({o, d}), b = sphere.intersect({o, d});
            CHECK(super.contains(o) == sphere.contains(o));
            // A ray within rounding of tangent may go either way.
            const S miss = glm::length(glm::cross(o, d)) / S(scale);
            if (std::abs(miss - S(1)) < S(1e-4)) continue;
            REQUIRE(a.has_value() == b.has_value());
            if (!a) continue;
            ++hits;
            CHECK(a->t == Approx(b->t).epsilon(super_tol<S>()).margin(super_tol<S>() * scale));
            CHECK(glm::dot(a->normal, b->normal) == Approx(1).epsilon(super_tol<S>()));
        }
        CHECK(hits > 150);
    }
}

TEMPLATE_TEST_CASE("superellipsoid: small e and n is the cube away from its rounded edges, at several scales",
                   "[geometry][superellipsoid]", float, double) {
    using S = TestType;
    for (const double scale : {1e-3, 1.0, 1e3}) {
        for (const double en : {0.02, 0.005}) {
            const Transformed<Superellipsoid<S>> super(Superellipsoid<S>{S(en), S(en)},
                                                       Affine<S>::scale(Vec3<S>(S(scale))));
            const Box<S> box(Vec3<S>(S(-scale)), Vec3<S>(S(scale)));
            Pcg32 rng(5, 2);
            int hits = 0;
            for (int i = 0; i < 3000; ++i) {
                const Vec3<S> o = (super_uniform3<S>(rng) * S(6) - S(3)) * S(scale);
                const Vec3<S> d = uniform_sphere<S>(rng.uniform2<S>());
                const auto a = super.intersect({o, d}), b = box.intersect({o, d});
                if (!b) {
                    // A miss of the box misses what it holds.
                    CHECK_FALSE(a);
                    continue;
                }
                // Away from the edges (where the corners are rounded by ~ e) the two agree.
                const glm::dvec3 q = glm::abs(glm::dvec3(b->point)) / scale;
                const double second = q.x + q.y + q.z - std::max({q.x, q.y, q.z}) - std::min({q.x, q.y, q.z});
                if (second > 0.8) continue;
                REQUIRE(a);
                ++hits;
                CHECK(a->t == Approx(b->t).epsilon(1e2 * super_tol<S>()).margin(1e2 * super_tol<S>() * scale));
                CHECK(glm::dot(a->normal, b->normal) == Approx(1).epsilon(1e-3));
            }
            CHECK(hits > 200);
        }
    }
}

TEMPLATE_TEST_CASE("superellipsoid: stars with thin ridges, grazing rays, rays from the surface",
                   "[geometry][superellipsoid]", float, double) {
    using S = TestType;
    for (const auto& [e, n] : {std::pair{3.0, 3.0}, std::pair{4.0, 0.5}, std::pair{0.5, 6.0}, std::pair{1.0, 2.5}}) {
        const Superellipsoid<S> star{S(e), S(n)};
        Pcg32 rng(9, 4);
        int hits = 0;
        for (int i = 0; i < 2000; ++i) {
            // Aimed at points near the shape, so that many rays pass close to its ridges.
            const Vec3<S> target = super_uniform3<S>(rng) * S(2) - S(1);
            const Vec3<S> o = uniform_sphere<S>(rng.uniform2<S>()) * S(4);
            const Ray<S> ray{o, target - o};
            const auto h = star.intersect(ray);
            if (!h) {
                // A miss: no sampled point of the ray inside.
                double least = 2;
                for (int k = 0; k <= 3000; ++k)
                    least = std::min(least, super_size(glm::dvec3(o) + (k / 1500.0) * glm::dvec3(target - o), e, n));
                CHECK(least >= 1 - 1e-9);
                continue;
            }
            ++hits;
            CHECK(super_size(glm::dvec3(h->point), e, n) == Approx(1).epsilon(1e2 * super_tol<S>()));
            // Nothing sampled between the origin and the hit is inside.
            double least = 2;
            for (int k = 1; k < 500; ++k)
                least = std::min(least, super_size(glm::dvec3(o) + (k / 500.0) * double(h->t) * glm::dvec3(ray.direction), e, n));
            CHECK(least >= 1 - 1e-9);
            // The normal is the implicit function's gradient (by central differences), where it is
            // smooth (away from the ridges on the coordinate planes).
            const glm::dvec3 p(h->point);
            if (min_component(glm::abs(p)) > 0.05) {
                glm::dvec3 g;
                for (int k = 0; k < 3; ++k) {
                    glm::dvec3 step(0.0);
                    step[k] = 1e-6;
                    g[k] = super_size(p + step, e, n) - super_size(p - step, e, n);
                }
                CHECK(glm::dot(glm::dvec3(h->normal), glm::normalize(g)) == Approx(1).epsilon(1e-3));
            }
            CHECK(glm::dot(h->normal, ray.direction) <= S(0));
        }
        CHECK(hits > 300);
    }
    // Grazing the unit sphere (e = n = 1) just outside and just inside its top.
    const Superellipsoid<S> sphere(1, 1);
    CHECK_FALSE(sphere.intersect({{-3, S(1) + S(1e-3), 0}, {1, 0, 0}}));
    const auto graze = sphere.intersect({{-3, S(0.999), 0}, {1, 0, 0}});
    REQUIRE(graze);
    CHECK(graze->t == Approx(3 - std::sqrt(1 - 0.999 * 0.999)).epsilon(super_tol<S>()));
    // From the surface: outwards nothing, inwards the far side.
    const Superellipsoid<S> cube(S(0.1), S(0.1));
    CHECK_FALSE(cube.intersect({{S(1) + S(1e-4), 0.2, 0.3}, {1, 0.1, 0}}));
    const auto across = cube.intersect({{S(1) - S(1e-4), 0.2, 0.3}, {-1, 0, 0}});
    REQUIRE(across);
    CHECK(across->t == Approx(2).epsilon(1e-3));
    CHECK(across->normal.x == Approx(-1).epsilon(1e-3));
    CHECK_THROWS_AS(Superellipsoid<S>(0, 1), std::invalid_argument);
    CHECK_THROWS_AS(Superellipsoid<S>(1, -1), std::invalid_argument);
}

TEMPLATE_TEST_CASE("superellipsoid: the inside test agrees with the parity of hits", "[geometry][superellipsoid]",
                   float, double) {
    using S = TestType;
    for (const auto& [e, n] : {std::pair{0.3, 0.3}, std::pair{1.0, 1.0}, std::pair{3.0, 2.5}}) {
        const Superellipsoid<S> shape{S(e), S(n)};
        Pcg32 rng(11, 2);
        int mismatches = 0, inside = 0;
        for (int i = 0; i < 1500; ++i) {
            const Vec3<S> o = super_uniform3<S>(rng) * S(3) - S(1.5);
            const Vec3<S> d = uniform_sphere<S>(rng.uniform2<S>());
            const bool odd = super_crossings(shape, Ray<S>{o, d}) % 2 == 1;
            inside += shape.contains(o);
            mismatches += odd != shape.contains(o);
        }
        CHECK(inside > 20);
        CHECK(mismatches <= 2);  // a ray through a ridge or corner may count it once or twice
    }
}
