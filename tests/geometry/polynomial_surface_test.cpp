// SPDX-License-Identifier: MIT
// PolynomialSurface (geometry/polynomial_surface.hpp): a sphere and a torus written as quartics
// (and the sphere as a quadratic poly) against the Sphere and Torus shapes for many rays at scales
// 1e-3, 1 and 1e3; a cubic and surfaces of order 5 and 6 against roots found by sampling the
// polynomial along the ray; POV-Ray's term order; grazing rays; rays leaving the surface; the
// inside test against the parity of hits; POV-Ray's bounded_by gate.

#include <catch2/catch.hpp>

#include <photon/geometry/csg.hpp>
#include <photon/geometry/polynomial_surface.hpp>
#include <photon/geometry/solid.hpp>
#include <photon/geometry/sphere.hpp>
#include <photon/geometry/torus.hpp>
#include <photon/geometry/transformed.hpp>
#include <photon/math/rng.hpp>
#include <photon/math/sampling.hpp>

#include <array>
#include <cmath>
#include <map>
#include <stdexcept>
#include <vector>

using namespace photon;

namespace {

/// A polynomial in x, y, z as monomial -> coefficient, with its own arithmetic and evaluation,
/// independent of the shape's expansion along rays.
using PolyTerms = std::map<std::array<int, 3>, double>;

PolyTerms poly_mul(const PolyTerms& a, const PolyTerms& b) {
    PolyTerms out;
    for (const auto& [ma, ca] : a)
        for (const auto& [mb, cb] : b) out[{ma[0] + mb[0], ma[1] + mb[1], ma[2] + mb[2]}] += ca * cb;
    return out;
}
PolyTerms poly_add(PolyTerms a, const PolyTerms& b, double scale = 1.0) {
    for (const auto& [m, c] : b) a[m] += scale * c;
    return a;
}
int poly_order(const PolyTerms& p) {
    int n = 0;
    for (const auto& [m, c] : p)
        if (c != 0.0) n = std::max(n, m[0] + m[1] + m[2]);
    return n;
}
double poly_eval(const PolyTerms& p, const glm::dvec3& q) {
    double v = 0.0;
    for (const auto& [m, c] : p) v += c * std::pow(q.x, m[0]) * std::pow(q.y, m[1]) * std::pow(q.z, m[2]);
    return v;
}
/// The coefficients in POV-Ray's order, looked up by polynomial_term_powers.
std::vector<double> poly_coefficients(const PolyTerms& p, int order) {
    std::vector<double> c(polynomial_term_count(order), 0.0);
    for (std::size_t index = 0; index < c.size(); ++index) {
        const auto m = polynomial_term_powers(order, index);
        if (const auto it = p.find(m); it != p.end()) c[index] = it->second;
    }
    return c;
}
template <class S> PolynomialSurface<S> poly_surface(const PolyTerms& p, int order = 0) {
    return PolynomialSurface<S>(order ? order : poly_order(p), poly_coefficients(p, order ? order : poly_order(p)));
}

const PolyTerms poly_x{{{1, 0, 0}, 1.0}}, poly_y{{{0, 1, 0}, 1.0}}, poly_z{{{0, 0, 1}, 1.0}};
PolyTerms poly_constant(double c) { return {{{0, 0, 0}, c}}; }
PolyTerms poly_shifted(const PolyTerms& axis, double by) { return poly_add(axis, poly_constant(-by)); }

/// |q - c|^2 - r^2.
PolyTerms poly_sphere(glm::dvec3 c, double r) {
    const PolyTerms dx = poly_shifted(poly_x, c.x), dy = poly_shifted(poly_y, c.y), dz = poly_shifted(poly_z, c.z);
    return poly_add(poly_add(poly_add(poly_mul(dx, dx), poly_mul(dy, dy)), poly_mul(dz, dz)), poly_constant(-r * r));
}
/// (|q|^2 + R^2 - r^2)^2 - 4 R^2 (x^2 + z^2): the torus around y.
PolyTerms poly_torus(double major, double minor) {
    const PolyTerms rho2 = poly_add(poly_add(poly_mul(poly_x, poly_x), poly_mul(poly_y, poly_y)), poly_mul(poly_z, poly_z));
    const PolyTerms m = poly_add(rho2, poly_constant(major * major - minor * minor));
    return poly_add(poly_mul(m, m), poly_add(poly_mul(poly_x, poly_x), poly_mul(poly_z, poly_z)), -4 * major * major);
}

template <class S> double poly_tol() { return std::is_same_v<S, float> ? 2e-4 : 1e-8; }

template <class S> Vec3<S> poly_uniform3(Pcg32& rng) {
    const Vec2<S> a = rng.uniform2<S>();
    return {a.x, a.y, rng.uniform<S>()};
}

/// The first sign change of p along the ray in (0, t_end], by 4000 samples refined by bisection
/// (the samples' spacing hides roots closer together than it: callers skip such rays).
std::optional<double> poly_sampled_root(const PolyTerms& p, glm::dvec3 o, glm::dvec3 d, double t_end,
                                        bool* close_pair = nullptr) {
    constexpr int n = 4000;
    double prev_t = 1e-9 * t_end, prev = poly_eval(p, o + prev_t * d);
    std::optional<double> found;
    for (int i = 1; i <= n; ++i) {
        const double t = t_end * i / n, v = poly_eval(p, o + t * d);
        if ((v < 0) != (prev < 0)) {
            if (found) {  // a second sign change within a few samples of the first: too close to judge
                if (close_pair) *close_pair = t - *found < 4.0 * t_end / n;
                return found;
            }
            double a = prev_t, b = t, fa = prev;
            for (int k = 0; k < 100; ++k) {
                const double m = 0.5 * (a + b), fm = poly_eval(p, o + m * d);
                if ((fm < 0) == (fa < 0)) a = m, fa = fm; else b = m;
            }
            found = 0.5 * (a + b);
        }
        prev_t = t, prev = v;
    }
    if (close_pair) *close_pair = false;
    return found;
}

}  // namespace

static_assert(Primitive<PolynomialSurface<float>> && Solid<PolynomialSurface<double>> &&
              Solid<Transformed<PolynomialSurface<float>>>);

TEST_CASE("polynomial: POV-Ray's term order, the counts, and what the constructor refuses", "[geometry][polynomial]") {
    CHECK(polynomial_term_count(2) == 10);
    CHECK(polynomial_term_count(3) == 20);
    CHECK(polynomial_term_count(4) == 35);
    CHECK(polynomial_term_count(35) == 8436);
    // A quartic's terms, as POV-Ray's polynomial.cpp lists them: a00 x^4, a01 x^3 y, a02 x^3 z,
    // a03 x^3, a04 x^2 y^2, a05 x^2 y z, ..., a19 x, a20 y^4, ..., a33 z, a34.
    CHECK(polynomial_term_powers(4, 0) == std::array<int, 3>{4, 0, 0});
    CHECK(polynomial_term_powers(4, 2) == std::array<int, 3>{3, 0, 1});
    CHECK(polynomial_term_powers(4, 5) == std::array<int, 3>{2, 1, 1});
    CHECK(polynomial_term_powers(4, 19) == std::array<int, 3>{1, 0, 0});
    CHECK(polynomial_term_powers(4, 20) == std::array<int, 3>{0, 4, 0});
    CHECK(polynomial_term_powers(4, 26) == std::array<int, 3>{0, 1, 3});
    CHECK(polynomial_term_powers(4, 34) == std::array<int, 3>{0, 0, 0});
    // A quadric's ten in the same order: x^2, xy, xz, x, y^2, yz, y, z^2, z, 1.
    CHECK(polynomial_term_powers(2, 3) == std::array<int, 3>{1, 0, 0});
    CHECK(polynomial_term_powers(2, 7) == std::array<int, 3>{0, 0, 2});
    CHECK_THROWS_AS(PolynomialSurface<double>(4, std::vector<double>(34, 1.0)), std::invalid_argument);
    CHECK_THROWS_AS(PolynomialSurface<double>(36, std::vector<double>(polynomial_term_count(36), 1.0)),
                    std::invalid_argument);
    std::vector<double> constant(35, 0.0);
    constant.back() = 1.0;
    CHECK_THROWS_AS(PolynomialSurface<double>(4, constant), std::invalid_argument);
    constant[0] = std::nan("");
    CHECK_THROWS_AS(PolynomialSurface<double>(4, constant), std::invalid_argument);
    const auto s = poly_surface<double>(poly_sphere({1, 2, 3}, 2));
    CHECK(s.value({1, 2, 3}) == Approx(-4));
    CHECK(s.gradient({3, 2, 3}).x == Approx(4));
}

TEMPLATE_TEST_CASE("polynomial: a sphere as a quadratic and as a quartic is the Sphere, for many rays at 1e-3, 1, 1e3",
                   "[geometry][polynomial]", float, double) {
    using S = TestType;
    for (const double scale : {1e-3, 1.0, 1e3}) {
        const glm::dvec3 c = glm::dvec3(0.3, -0.2, 0.1) * scale;
        const double r = scale;
        const PolyTerms quadratic = poly_sphere(c, r);
        // |q - c|^4 - r^4: the same zero set and inside.
        const PolyTerms quartic = poly_add(poly_mul(poly_add(quadratic, poly_constant(r * r)),
                                                    poly_add(quadratic, poly_constant(r * r))),
                                           poly_constant(-r * r * r * r));
        const Sphere<S> sphere{Vec3<S>(c), S(r)};
        for (const PolyTerms& terms : {quadratic, quartic}) {
            const auto surface = poly_surface<S>(terms);
            Pcg32 rng(11, 3);
            int hits = 0;
            for (int i = 0; i < 2000; ++i) {
                const Vec3<S> o = Vec3<S>(c) + (poly_uniform3<S>(rng) * S(6) - S(3)) * S(scale);
                const Vec3<S> d = uniform_sphere<S>(rng.uniform2<S>()) * S(i % 3 == 0 ? 1e-2 : 1.0);
                const Ray<S> ray{o, d};
                const auto p = surface.intersect(ray), b = sphere.intersect(ray);
                const glm::dvec3 od(o), dd = glm::normalize(glm::dvec3(d));
                const double miss_by = glm::length(od - c - glm::dot(od - c, dd) * dd) - r;
                if (std::abs(miss_by) < 1e-4 * r) continue;  // grazing: judged below
                const double off_surface = std::abs(glm::length(od - c) - r);
                if (off_surface < 1e-4 * r) continue;  // on the surface: judged below
                REQUIRE(p.has_value() == b.has_value());
                CHECK(surface.contains(o) == sphere.contains(o));
                if (!p) continue;
                ++hits;
                CHECK(p->t == Approx(b->t).epsilon(poly_tol<S>()).margin(poly_tol<S>() * scale / glm::length(glm::dvec3(d))));
                CHECK(glm::dot(p->normal, b->normal) == Approx(1).epsilon(poly_tol<S>()));
            }
            CHECK(hits > 80);
        }
    }
}

TEMPLATE_TEST_CASE("polynomial: a torus as a quartic is the Torus, for many rays at 1e-3, 1, 1e3", "[geometry][polynomial][heavy]",
                   float, double) {
    using S = TestType;
    for (const double scale : {1e-3, 1.0, 1e3}) {
        const double major = scale, minor = 0.35 * scale;
        const auto surface = poly_surface<S>(poly_torus(major, minor));
        const Torus<S> torus{S(major), S(minor)};
        Pcg32 rng(5, 9);
        int hits = 0, compared = 0;
        for (int i = 0; i < 2000; ++i) {
            const Vec3<S> o = (poly_uniform3<S>(rng) * S(6) - S(3)) * S(scale);
            const Vec3<S> d = uniform_sphere<S>(rng.uniform2<S>());
            const Ray<S> ray{o, d};
            const auto p = surface.intersect(ray), t = torus.intersect(ray);
            // Skip rays that graze (the two shapes may disagree on a double root) or start on it.
            bool close = false;
            (void)poly_sampled_root(poly_torus(major, minor), glm::dvec3(o), glm::dvec3(d), 8 * scale, &close);
            if (close) continue;
            const double ring = std::sqrt(double(o.x) * o.x + double(o.z) * o.z) - major;
            if (std::abs(std::sqrt(ring * ring + double(o.y) * o.y) - minor) < 1e-4 * scale) continue;
            ++compared;
            REQUIRE(p.has_value() == t.has_value());
            CHECK(surface.contains(o) == torus.contains(o));
            if (!p) continue;
            ++hits;
            CHECK(p->t == Approx(t->t).epsilon(poly_tol<S>()).margin(poly_tol<S>() * scale));
            CHECK(glm::dot(p->normal, t->normal) == Approx(1).epsilon(poly_tol<S>()));
        }
        CHECK(compared > 1800);
        CHECK(hits > 80);
    }
}

TEST_CASE("polynomial: a cubic and surfaces of order 5 and 6 agree with roots found by sampling", "[geometry][polynomial][heavy]") {
    // Monkey saddle z = x^3 - 3 x y^2, a cubic; a sphere times a torus (order 6, a sphere in the
    // torus's hole); an order-5 surface: the cubic times a sphere.
    const PolyTerms saddle = poly_add(poly_add(poly_mul(poly_mul(poly_x, poly_x), poly_x),
                                               poly_mul(poly_mul(poly_x, poly_y), poly_y), -3.0),
                                      poly_z, -1.0);
    const PolyTerms sextic = poly_mul(poly_sphere({0, 0, 0}, 0.4), poly_torus(1.2, 0.3));
    const PolyTerms quintic = poly_mul(saddle, poly_sphere({0.2, 0.1, 0}, 0.8));
    const Sphere<double> inner({0, 0, 0}, 0.4);
    const Torus<double> ring(1.2, 0.3);
    for (const PolyTerms* p : {&saddle, &sextic, &quintic}) {
        const auto surface = poly_surface<double>(*p);
        CHECK(surface.order() == poly_order(*p));
        Pcg32 rng(3, 17);
        int compared = 0, hits = 0;
        for (int i = 0; i < 400; ++i) {
            const glm::dvec3 o = poly_uniform3<double>(rng) * 5.0 - 2.5;
            const glm::dvec3 d = uniform_sphere<double>(rng.uniform2<double>());
            bool close = false;
            const auto sampled = poly_sampled_root(*p, o, d, 10.0, &close);
            if (close || std::abs(poly_eval(*p, o)) < 1e-6) continue;
            const auto h = surface.intersect(Ray<double>{o, d, 10.0});
            ++compared;
            REQUIRE(h.has_value() == sampled.has_value());
            CHECK(surface.contains(o) == (poly_eval(*p, o) < 0));
            if (!h) continue;
            ++hits;
            CHECK(h->t == Approx(*sampled).margin(1e-8));
            // The normal is the gradient, along which p grows.
            CHECK(poly_eval(*p, glm::dvec3(h->point) + 1e-5 * glm::dvec3(h->normal)) > 0);
            if (p == &sextic) {  // the nearer of the sphere's and the torus's hits
                const auto a = inner.intersect(Ray<double>{o, d, 10.0}), b = ring.intersect(Ray<double>{o, d, 10.0});
                REQUIRE((a || b));
                CHECK(h->t == Approx(std::min(a ? a->t : 1e9, b ? b->t : 1e9)).margin(1e-9));
            }
        }
        CHECK(compared > 300);
        CHECK(hits > 30);
    }
}

TEMPLATE_TEST_CASE("polynomial: grazing rays, rays from the surface, far origins, inside against hit parity",
                   "[geometry][polynomial]", float, double) {
    using S = TestType;
    const PolyTerms torus_terms = poly_torus(1.0, 0.4);
    const auto torus = poly_surface<S>(torus_terms);
    // Rays tangent to the outer equator (y = 0.4 top, a double root): a miss or a hit on the surface.
    for (int i = 0; i < 50; ++i) {
        const double phi = 0.1 * i;
        const Vec3<S> o(S(3 * std::cos(phi)), S(0.4), S(3 * std::sin(phi)));
        const Vec3<S> d(S(-std::cos(phi)), 0, S(-std::sin(phi)));
        if (const auto h = torus.intersect({o, d}))
            CHECK(std::abs(poly_eval(torus_terms, glm::dvec3(h->point))) < 1e3 * poly_tol<S>());
    }
    // From points on the surface, along the normal: outwards nothing near (the torus's other side
    // is 0.4 away or more), inwards the tube's far wall, 0.8 away at most.
    Pcg32 rng(21, 4);
    for (int i = 0; i < 300; ++i) {
        const Vec3<S> from = (poly_uniform3<S>(rng) * S(6) - S(3));
        const Vec3<S> d = uniform_sphere<S>(rng.uniform2<S>());
        const auto h = torus.intersect({from, d});
        if (!h) continue;
        const Vec3<S> n = h->normal;
        const auto out = torus.intersect({h->point + n * S(1e-3), n});
        if (out) CHECK(out->t > S(0.3));
        const auto in = torus.intersect({h->point - n * S(1e-3), -n});
        REQUIRE(in);
        CHECK(glm::dot(in->normal, -n) > 0);  // leaving the solid
        CHECK(in->t > S(0.3));
        CHECK(in->t < S(0.8));
        // Parity: a point is inside when a ray from it crosses the surface an odd number of times.
        int crossings = 0;
        Ray<S> walk{from, d};
        while (const auto c = torus.intersect(walk)) {
            ++crossings;
            walk.origin = c->point + d * S(1e-3);
            if (crossings > 8) break;
        }
        CHECK(torus.contains(from) == (crossings % 2 == 1));
    }
    // A camera a million units away sees the unit torus where the Torus shape sees it.
    const Torus<S> exact{S(1), S(0.4)};
    for (int i = 0; i < 40; ++i) {
        const Vec3<S> o(S(1e6), S(0.3 + 0.01 * i), S(0.2));
        const Vec3<S> d(S(-1), S(0), S(0.0001 * i));
        const auto p = torus.intersect({o, d}), t = exact.intersect({o, d});
        REQUIRE(p.has_value() == t.has_value());
        if (p) CHECK(double(p->t) == Approx(double(t->t)).margin(std::is_same_v<S, float> ? 0.5 : 1e-6));
    }
}

TEST_CASE("polynomial: POV-Ray's bounded_by gate, and the surface in CSG", "[geometry][polynomial]") {
    // A paraboloid y = x^2 + z^2 (unbounded) gated by the unit sphere at the origin.
    const PolyTerms para = poly_add(poly_add(poly_mul(poly_x, poly_x), poly_mul(poly_z, poly_z)), poly_y, -1.0);
    const auto open = poly_surface<double>(para, 2);
    const auto gated = open.gated({PolynomialGate::Kind::sphere, glm::dvec3(0.0), 1.0});
    // A ray that misses the gate misses the surface; one through the gate meets it also outside.
    const Ray<double> far{{-10, 4, 0}, {1, 0, 0}};
    REQUIRE(open.intersect(far));
    CHECK_FALSE(gated.intersect(far));
    const Ray<double> through{{0, 10, 0.5}, {0, -1, 0}};  // enters the sphere, hits at y = 0.25
    REQUIRE(gated.intersect(through));
    CHECK(gated.intersect(through)->t == Approx(9.75));
    const Ray<double> beyond{{0.5, -10, 0}, {0, 1, 0}};  // passes the gate first, meets y = 0.25 inside it
    CHECK(gated.intersect(beyond)->t == Approx(10.25));
    const auto box_gated = open.gated({PolynomialGate::Kind::box, {}, 0, glm::dvec3(-1, -1, -1), glm::dvec3(1, 0, 1)});
    const Ray<double> over_box{{2, 5, 0}, {-1, 0, 0}};  // above the box: meets the paraboloid at x = sqrt 5 only ungated
    CHECK(open.intersect(over_box));
    CHECK_FALSE(box_gated.intersect(over_box));
    const Ray<double> via_box{{0.5, -0.5, 0}, {0, 1, 0}};  // from in the box up to y = 0.25, above it
    REQUIRE(box_gated.intersect(via_box));
    CHECK(box_gated.intersect(via_box)->t == Approx(0.75));
    CHECK(gated.contains({0, 5, 0}));  // the inside ignores the gate, as POV-Ray's
    // The gate's box is the surface's bounds (the scene then keeps it in its BVH); ungated, infinite.
    CHECK_FALSE(open.bounds().is_finite());
    CHECK(gated.bounds().min == glm::dvec3(-1.0));
    CHECK(gated.bounds().max == glm::dvec3(1.0));
    CHECK(box_gated.bounds().max == glm::dvec3(1, 0, 1));
    CHECK_THROWS_AS(open.gated({PolynomialGate::Kind::sphere, glm::dvec3(0.0), 0.0}), std::invalid_argument);

    // In CSG: the torus quartic minus a slab, crossed along x.
    using C = Csg<double, PolynomialSurface<double>, Sphere<double>>;
    const C cut = C::difference({C(poly_surface<double>(poly_torus(1.0, 0.4))), C(Sphere<double>({1, 0, 0}, 0.3))});
    const auto h = cut.intersect({{-3, 0, 0}, {1, 0, 0}});
    REQUIRE(h);
    CHECK(h->t == Approx(1.6));
    const auto h2 = cut.intersect({{0, 0, 0}, {1, 0, 0}});
    REQUIRE(h2);
    CHECK(h2->t == Approx(0.6));  // the torus's inner wall
    const auto h3 = cut.intersect({{0.75, 0, 0}, {1, 0, 0}});
    REQUIRE(h3);
    CHECK(h3->t == Approx(1.3 - 0.75));  // the sphere's far side: the hollow the difference leaves
}
