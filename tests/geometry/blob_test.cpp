// SPDX-License-Identifier: MIT
// Blob (geometry/blob.hpp): one sphere component is a sphere and one cylinder component a capsule
// (radius R sqrt(1 - sqrt(threshold / strength))), at scales 1e-3, 1 and 1e3 and far from the
// origin, in float and double; a scaled sphere component is the scaled sphere; several components,
// a negative one among them, are hit where the field reaches the threshold, first along the ray,
// with the field's gradient as normal, and missed only where no sampled point is inside; rays from
// the surface and grazing rays; the inside test against the parity of hits; bad components throw.

#include <catch2/catch.hpp>

#include <photon/geometry/blob.hpp>
#include <photon/geometry/solid.hpp>
#include <photon/geometry/sphere.hpp>
#include <photon/geometry/transformed.hpp>
#include <photon/math/rng.hpp>
#include <photon/math/sampling.hpp>

#include <cmath>
#include <stdexcept>

using namespace photon;

namespace {

template <class S> double blob_tol() { return std::is_same_v<S, float> ? 2e-4 : 1e-9; }

template <class S> Vec3<S> blob_uniform3(Pcg32& rng) {
    const Vec2<S> a = rng.uniform2<S>();
    return {a.x, a.y, rng.uniform<S>()};
}

/// The radius where one component of this strength and radius meets the threshold.
double reach(double radius, double strength, double threshold) {
    return radius * std::sqrt(1.0 - std::sqrt(threshold / strength));
}

/// Distance from p to the segment [a, b].
double segment_distance(glm::dvec3 p, glm::dvec3 a, glm::dvec3 b) {
    const glm::dvec3 ab = b - a;
    const double s = std::clamp(glm::dot(p - a, ab) / glm::dot(ab, ab), 0.0, 1.0);
    return glm::length(p - (a + s * ab));
}

template <class S> int blob_crossings(const Blob<S>& shape, Ray<S> ray) {
    int n = 0;
    while (auto h = shape.intersect(ray)) {
        ++n;
        ray.origin = h->point + ray.direction * S(1e-4);
        if (n > 50) break;
    }
    return n;
}

}  // namespace

static_assert(Primitive<Blob<float>> && Solid<Blob<double>> && Solid<Transformed<Blob<float>>>);

TEMPLATE_TEST_CASE("blob: one sphere component is a sphere, at several scales and far away", "[geometry][blob]",
                   float, double) {
    using S = TestType;
    using C = typename Blob<S>::Component;
    for (const double scale : {1e-3, 1.0, 1e3}) {
        for (const double far : {0.0, 50.0}) {
            const Vec3<S> centre = Vec3<S>(S(far), S(-far), S(far / 2)) * S(scale);
            const Blob<S> blob({C::sphere(centre, S(2 * scale), S(2))}, S(0.5));
            const Sphere<S> sphere(centre, S(reach(2 * scale, 2, 0.5)));
            Pcg32 rng(3, 1);
            int hits = 0;
            for (int i = 0; i < 2000; ++i) {
                const Vec3<S> o = centre + (blob_uniform3<S>(rng) * S(6) - S(3)) * S(scale);
                const Vec3<S> d = uniform_sphere<S>(rng.uniform2<S>());
                const auto a = blob.intersect({o, d}), b = sphere.intersect({o, d});
                CHECK(blob.contains(o) == sphere.contains(o));
                // A ray within rounding of tangent may go either way.
                const double miss = glm::length(glm::cross(glm::dvec3(o - centre), glm::dvec3(d))) / scale;
                if (std::abs(miss - reach(2, 2, 0.5)) < 1e-3) continue;
                REQUIRE(a.has_value() == b.has_value());
                if (!a) continue;
                ++hits;
                const double tol = blob_tol<S>() * (1 + far);
                CHECK(a->t == Approx(b->t).epsilon(tol).margin(tol * scale));
                CHECK(glm::dot(a->normal, b->normal) == Approx(1).epsilon(tol));
                CHECK(blob.bounds().contains(a->point));
            }
            CHECK(hits > 200);
        }
    }
}

TEMPLATE_TEST_CASE("blob: one cylinder component is a capsule, at several scales", "[geometry][blob]", float,
                   double) {
    using S = TestType;
    using C = typename Blob<S>::Component;
    for (const double scale : {1e-3, 1.0, 1e3}) {
        const glm::dvec3 a = glm::dvec3(-1, 0.5, 0.2) * scale, b = glm::dvec3(1.2, -0.3, 0.4) * scale;
        const Blob<S> blob({C::cylinder(Vec3<S>(a), Vec3<S>(b), S(scale), S(1))}, S(0.25));
        const double rho = reach(1, 1, 0.25) * scale;
        Pcg32 rng(7, 3);
        int hits = 0;
        for (int i = 0; i < 1500; ++i) {
            const Vec3<S> o = (blob_uniform3<S>(rng) * S(6) - S(3)) * S(scale);
            const Vec3<S> d = uniform_sphere<S>(rng.uniform2<S>());
            const auto h = blob.intersect({o, d});
            // The first t where the distance to the segment falls to rho, by sampling then bisection.
            auto excess = [&](double t) { return segment_distance(glm::dvec3(o) + t * glm::dvec3(d), a, b) - rho; };
            std::optional<double> expected;
            const double step = 0.004 * scale;
            for (int k = 1; k <= 2500 && !expected; ++k) {
                double lo = (k - 1) * step, hi = k * step;
                if (excess(lo) <= 0 || excess(hi) > 0) continue;
                for (int it = 0; it < 80; ++it) (excess(0.5 * (lo + hi)) > 0 ? lo : hi) = 0.5 * (lo + hi);
                expected = 0.5 * (lo + hi);
            }
            CHECK(blob.contains(o) == (excess(0) < 0));
            if (excess(0) < 0) continue;  // from inside: the exit, not what this sampling finds
            if (expected.has_value() != h.has_value()) {
                // Only a ray within rounding of tangent may disagree: its closest approach is rho.
                double least = 1e30;
                for (int k = 0; k <= 20000; ++k) least = std::min(least, excess(k * 1e-3 * scale));
                CHECK(std::abs(least) < 1e-3 * scale);
                continue;
            }
            if (!h) continue;
            ++hits;
            const double tol = blob_tol<S>();
            CHECK(double(h->t) == Approx(*expected).epsilon(1e2 * tol).margin(1e2 * tol * scale));
            // The normal points away from the segment.
            const glm::dvec3 p(h->point);
            const double s = std::clamp(glm::dot(p - a, b - a) / glm::dot(b - a, b - a), 0.0, 1.0);
            const glm::dvec3 away = glm::normalize(p - (a + s * (b - a)));
            CHECK(glm::dot(glm::dvec3(h->normal), away) == Approx(1).epsilon(1e2 * tol));
        }
        CHECK(hits > 50);
    }
}

TEMPLATE_TEST_CASE("blob: a scaled sphere component is the scaled sphere", "[geometry][blob]", float, double) {
    using S = TestType;
    using C = typename Blob<S>::Component;
    C component = C::sphere({S(0.5), 0, 0}, S(1.5), S(1));
    component.placement = Affine<S>::scale({1, 2, S(0.5)}).then(Affine<S>::rotate_xyz({30, 10, 0}));
    const Blob<S> blob({component}, S(0.3));
    const Transformed<Sphere<S>> ellipsoid(Sphere<S>({S(0.5), 0, 0}, S(reach(1.5, 1, 0.3))), component.placement);
    Pcg32 rng(5, 9);
    int hits = 0, disagreements = 0;
    for (int i = 0; i < 4000; ++i) {
        const Vec3<S> o = blob_uniform3<S>(rng) * S(6) - S(3);
        const Vec3<S> d = uniform_sphere<S>(rng.uniform2<S>());
        const auto a = blob.intersect({o, d}), b = ellipsoid.intersect({o, d});
        if (a.has_value() != b.has_value()) {
            // Only within rounding of tangent: the ellipsoid's own hit (if any) is a graze.
            const auto inward = ellipsoid.intersect({o, d});
            CHECK((!inward || std::abs(double(glm::dot(inward->normal, d))) < 1e-2));
            ++disagreements;
            continue;
        }
        if (!a) continue;
        ++hits;
        CHECK(a->t == Approx(b->t).epsilon(1e2 * blob_tol<S>()).margin(1e2 * blob_tol<S>()));
        CHECK(glm::dot(a->normal, b->normal) == Approx(1).epsilon(1e2 * blob_tol<S>()));
        CHECK(blob.bounds().contains(a->point));
    }
    CHECK(hits > 200);
    CHECK(disagreements <= 2);
}

TEMPLATE_TEST_CASE("blob: several components, one carving, hit where the field reaches the threshold",
                   "[geometry][blob]", float, double) {
    using S = TestType;
    // POV-Ray's blob1a (two crossed cylinders and a carving sphere), with a ball and an ellipsoid;
    // the field is checked in double whatever S.
    auto make = [](auto zero) {
        using T = decltype(zero);
        using C = typename Blob<T>::Component;
        C scaled = C::sphere({0, T(-0.8), 0}, T(1.2), T(1.5));
        scaled.placement = Affine<T>::scale({2, 1, 1});
        return Blob<T>({C::cylinder({-3, 0, 0}, {3, 0, 0}, 2, 2), C::cylinder({0, 0, -3}, {0, 0, 3}, 2, 2),
                        C::sphere({0, T(1.2), 0}, T(1.2), -4), C::sphere({2, 1, 1}, 1, T(1.5)), scaled},
                       T(0.5));
    };
    const Blob<S> blob = make(S(0));
    const Blob<double> exact = make(0.0);
    const double threshold = 0.5;
    auto field = [&](const glm::dvec3& p) { return exact.field(p); };
    Pcg32 rng(9, 4);
    int hits = 0, misses = 0;
    for (int i = 0; i < 1500; ++i) {
        const Vec3<S> target = blob_uniform3<S>(rng) * S(8) - S(4);
        const Vec3<S> o = uniform_sphere<S>(rng.uniform2<S>()) * S(9);
        const Ray<S> ray{o, glm::normalize(target - o)};
        const auto h = blob.intersect(ray);
        const glm::dvec3 od(o), dd(ray.direction);
        if (!h) {
            ++misses;
            double most = 0;
            for (int k = 0; k <= 4000; ++k) most = std::max(most, field(od + (k * 0.005) * dd));
            CHECK(most <= threshold + 1e-6);
            continue;
        }
        ++hits;
        CHECK(field(glm::dvec3(h->point)) == Approx(threshold).margin(1e2 * blob_tol<S>()));
        double most = 0;
        for (int k = 1; k < 1000; ++k) most = std::max(most, field(od + (k / 1000.0) * double(h->t) * dd));
        CHECK(most <= threshold + 1e-6);
        // The normal against the field's gradient, by central differences.
        const glm::dvec3 p(h->point);
        glm::dvec3 g;
        for (int k = 0; k < 3; ++k) {
            glm::dvec3 step(0.0);
            step[k] = 1e-6;
            g[k] = field(p + step) - field(p - step);
        }
        if (glm::length(g) > 1e-9) CHECK(glm::dot(glm::dvec3(h->normal), -glm::normalize(g)) == Approx(1).epsilon(1e-4));
        CHECK(glm::dot(h->normal, ray.direction) <= S(1e-6));
        CHECK(blob.bounds().contains(h->point));
    }
    CHECK(hits > 300);
    CHECK(misses > 100);
    // The carving sphere leaves a dip: straight down onto the crossing, the hit is below where
    // the cylinders alone would put it (their surface at y = reach(2, 4, 0.5), both adding there).
    const auto top = blob.intersect({{0, 5, 0}, {0, -1, 0}});
    REQUIRE(top);
    CHECK(double(top->point.y) < reach(2, 4, 0.5) - 0.05);
}

TEMPLATE_TEST_CASE("blob: rays from the surface, grazing rays, the inside test against the parity of hits",
                   "[geometry][blob]", float, double) {
    using S = TestType;
    using C = typename Blob<S>::Component;
    const double rho = reach(1, 1, 0.5);
    const Blob<S> ball({C::sphere({0, 0, 0}, 1, 1)}, S(0.5));
    // Tangent just outside misses; just inside hits at the expected t.
    CHECK_FALSE(ball.intersect({{-3, S(rho + 1e-3), 0}, {1, 0, 0}}));
    const auto graze = ball.intersect({{-3, S(rho - 1e-3), 0}, {1, 0, 0}});
    REQUIRE(graze);
    CHECK(double(graze->t) == Approx(3 - std::sqrt(rho * rho - (rho - 1e-3) * (rho - 1e-3))).epsilon(1e2 * blob_tol<S>()));
    // From just outside the surface outward: nothing; from just inside inward: the far side.
    CHECK_FALSE(ball.intersect({{S(rho + 1e-4), 0, 0}, {1, 0, 0}}));
    const auto across = ball.intersect({{S(rho - 1e-4), 0, 0}, {-1, 0, 0}});
    REQUIRE(across);
    CHECK(double(across->t) == Approx(2 * rho).epsilon(1e-3));
    CHECK(across->normal.x == Approx(-1).epsilon(1e-3));
    // A ray along a cylinder component's axis (its body's distance does not vary along it).
    const Blob<S> rod({C::cylinder({0, 0, -1}, {0, 0, 1}, 1, 1)}, S(0.5));
    const auto end = rod.intersect({{0, 0, -5}, {0, 0, 1}});
    REQUIRE(end);
    CHECK(double(end->t) == Approx(4 - rho).epsilon(1e2 * blob_tol<S>()));
    CHECK(end->normal.z == Approx(-1).epsilon(1e-4));

    const Blob<S> shape({C::sphere({-0.6, 0, 0}, 1, 1), C::sphere({0.6, 0, 0}, 1, 1), C::sphere({0, 0.5, 0}, S(0.7), -1)},
                        S(0.4));
    Pcg32 rng(11, 2);
    int mismatches = 0, inside = 0;
    for (int i = 0; i < 1500; ++i) {
        const Vec3<S> o = blob_uniform3<S>(rng) * S(3) - S(1.5);
        const Vec3<S> d = uniform_sphere<S>(rng.uniform2<S>());
        const bool odd = blob_crossings(shape, Ray<S>{o, d}) % 2 == 1;
        inside += shape.contains(o);
        mismatches += odd != shape.contains(o);
    }
    CHECK(inside > 50);
    CHECK(mismatches <= 2);  // a ray through a near-tangent may count a crossing once or twice

    CHECK_THROWS_AS(Blob<S>({C::sphere({0, 0, 0}, 1, 1)}, S(0)), std::invalid_argument);
    CHECK_THROWS_AS(Blob<S>({C::sphere({0, 0, 0}, 0, 1)}, S(1)), std::invalid_argument);
    CHECK_THROWS_AS(Blob<S>({C::cylinder({1, 2, 3}, {1, 2, 3}, 1, 1)}, S(1)), std::invalid_argument);
    // A blob of carving components only is empty: no bounds, no hits.
    const Blob<S> hole({C::sphere({0, 0, 0}, 1, -1)}, S(0.5));
    CHECK(hole.bounds().is_empty());
    CHECK_FALSE(hole.intersect({{0, 0, -3}, {0, 0, 1}}));
}
