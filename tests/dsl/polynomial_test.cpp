// SPDX-License-Identifier: MIT
// quartic, cubic, poly and polynomial in the scene language: POV-Ray 3.7's term order (shapesq.inc's
// torus lands where the Torus shape is), each way of writing the coefficients, the order limits
// and coefficient counts as located errors, a surface with no terms skipped, the bounded_by gate
// (and where it stays an ignored bound with its warning), CSG, inside(), and export-pov.

#include <catch2/catch.hpp>

#include "dsl_test_util.hpp"

#include <cmath>
#include <cstring>
#include <string>
#include <vector>

using namespace dsl_test;
using namespace photon;
using Catch::Matchers::Contains;

namespace {

/// shapesq.inc's Torus_40_12: major radius sqrt(40), minor sqrt(12), around y.
const char* const poly_torus_40_12 =
    "quartic { < 1, 0, 0, 0, 2, 0, 0, 2, 0, -104,  0, 0, 0, 0, 0, 0, 0, 0, 0, 0,"
    "  1, 0, 0, 2, 0, 56, 0, 0, 0, 0,  1, 0, -104, 0, 784> sturm }\n";

/// `poly { N, <...> }` for (x^2 + y^2 + z^2)^(N/2) - 1 (N even): the unit sphere.
std::string poly_sphere_text(int order) {
    std::vector<double> c(polynomial_term_count(order), 0.0);
    const int half = order / 2;
    // Multinomial expansion of (x^2 + y^2 + z^2)^half.
    std::vector<double> factorial(20, 1.0);
    for (int n = 1; n < 20; ++n) factorial[std::size_t(n)] = factorial[std::size_t(n - 1)] * n;
    for (int a = 0; a <= half; ++a)
        for (int b = 0; a + b <= half; ++b) {
            const int e = half - a - b;
            c[polynomial_term_index(order, 2 * a, 2 * b, 2 * e)] +=
                factorial[std::size_t(half)] / (factorial[std::size_t(a)] * factorial[std::size_t(b)] * factorial[std::size_t(e)]);
        }
    c.back() = -1;
    std::string s = "poly { " + std::to_string(order) + ", <";
    for (std::size_t n = 0; n < c.size(); ++n) s += (n ? ", " : "") + std::to_string(c[n]);
    return s + "> }\n";
}

}  // namespace

TEST_CASE("polynomial: POV-Ray's term order, the index the parser writes `xyz` terms to", "[dsl][polynomial]") {
    for (int order = 2; order <= 7; ++order)
        for (std::size_t n = 0; n < polynomial_term_count(order); ++n) {
            const auto m = polynomial_term_powers(order, n);
            CHECK(polynomial_term_index(order, m[0], m[1], m[2]) == n);
        }
}

TEST_CASE("polynomial: quartic, cubic, poly and polynomial build exact surfaces", "[dsl][polynomial]") {
    // shapesq.inc's torus, hit where the Torus shape is hit.
    const StagedScene t = build_staged(poly_torus_40_12);
    CHECK(t.warnings.empty());
    only<Transformed<PolynomialSurface<double>>>(t);
    const Torus<double> torus(std::sqrt(40.0), std::sqrt(12.0));
    for (const Vec3<double> dir : {Vec3<double>(0, -1, 0), Vec3<double>(0.3, -1, 0.2), Vec3<double>(-1, -0.1, 0.05)}) {
        const Vec3<double> from(0.5, 10, std::sqrt(40.0));
        const auto h = shoot(t, from, dir);
        const auto e = torus.intersect({from, dir});
        REQUIRE(h.has_value() == e.has_value());
        if (h) {
            CHECK(h->t == Approx(e->t));
            CHECK(glm::dot(h->normal, e->normal) == Approx(1));
        }
    }
    // A cubic y = x^3 (x^3 is the first of its 20 terms, y the 16th), moved up by 1.
    const StagedScene c = build_staged("cubic { <1, 0,0,0, 0,0,0,0,0,0, 0,0,0,0,0, -1, 0,0,0,0> translate y }\n");
    CHECK(c.warnings.empty());
    auto h = shoot(c, {0.5, 5, 0}, {0, -1, 0});
    REQUIRE(h);
    CHECK(h->t == Approx(5 - 1.125));
    // x^4 + y^4 + z^4 = 1 by `polynomial`, and the unit sphere as poly of order 2, 4 and 6.
    const StagedScene q = build_staged("polynomial { 4, xyz(4,0,0):1, xyz(0,4,0):1, xyz(0,0,4):1, xyz(0,0,0):-1 }\n");
    CHECK(q.warnings.empty());
    h = shoot(q, {0, 0, 0}, {1, 1, 1});
    REQUIRE(h);
    CHECK(h->t == Approx(std::pow(3.0, -0.25)));
    for (const int order : {2, 4, 6}) {
        const StagedScene s = build_staged(poly_sphere_text(order));
        CHECK(s.warnings.empty());
        h = shoot(s, {0.3, 0.2, -5}, {0, 0, 1});
        REQUIRE(h);
        CHECK(h->t == Approx(5 - std::sqrt(1 - 0.13)));
    }
    // Rotated and scaled like any object; in CSG, a box minus the quartic torus.
    const StagedScene r = build_staged(std::string(poly_torus_40_12).insert(std::strlen(poly_torus_40_12) - 2, " rotate 90*x scale 0.1"));
    h = shoot(r, {0, std::sqrt(0.4), -5}, {0, 0, 1});
    REQUIRE(h);
    CHECK(h->t == Approx(5 - std::sqrt(0.12)));
    const StagedScene d = build_staged(std::string("difference { box { <-8, -1, -8>, <8, 1, 8> } ") + poly_torus_40_12 + " }\n");
    CHECK(d.warnings.empty());
    CHECK_FALSE(shoot(d, {std::sqrt(40.0), 5, 0}, {0, -1, 0}));  // the tube is thicker than the box: cut through
    h = shoot(d, {0, 5, 0}, {0, -1, 0});
    REQUIRE(h);
    CHECK(h->t == Approx(4));  // the box's top in the torus's hole
    h = shoot(d, {0, 0, 0}, {1, 0, 0});
    REQUIRE(h);
    CHECK(h->t == Approx(std::sqrt(40.0) - std::sqrt(12.0)));  // the hole's wall, facing out of what is left
    CHECK(h->normal.x == Approx(1));
}

TEST_CASE("polynomial: orders, counts and powers as located errors, and no terms skipped", "[dsl][polynomial][errors]") {
    CHECK_THAT(error_of("quartic { <1, 2, 3> }"), Contains("1:19: the quartic of order 4 needs 35 coefficients, found 3"));
    CHECK_THAT(error_of("poly { 36, <1> }"), Contains("1:8: the order of `poly` must be 2 to 35"));
    CHECK_THAT(error_of("poly { 1, <1, 2, 3, 4> }"), Contains("1:8: the order of `poly` must be 2 to 35"));
    CHECK_THAT(error_of("polynomial { 4, xyz(3,2,0):1 }"), Contains("1:21: the term x^3 y^2 z^0 is above the polynomial's order 4"));
    CHECK_THAT(error_of("cubic { <1,0,0,0, 0,0,0,0,0,0, 0,0,0,0,0, 0,0,0,0,0, 7> }"), Contains("after the 20 coefficients of the cubic"));
    const StagedScene b = build_staged("polynomial { 3, xyz(0,0,0):1 }\n");
    CHECK(b.scene.objects().empty());
    CHECK(places(b.warnings, "skipped object") == std::vector<std::string>{"3:17 polynomial"});
}

TEST_CASE("polynomial: bounded_by as POV-Ray's gate, inside() and export-pov", "[dsl][polynomial][export]") {
    // The paraboloid y = x^2 + z^2 (poly order 2: x^2, xy, xz, x, y^2, yz, y, z^2, z, 1).
    const std::string para = "poly { 2, <1, 0, 0, 0, 0, 0, -1, 1, 0, 0> ";
    const StagedScene open = build_staged(para + "}\n");
    REQUIRE(shoot(open, {-10, 4, 0}, {1, 0, 0}));
    // A box bound: rays that miss it miss the surface; no warning, it renders as POV-Ray's.
    const StagedScene gated = build_staged(para + "bounded_by { box { -1, 1 } } translate 10*x }\n");
    CHECK(all_messages(gated.warnings).empty());
    CHECK_FALSE(shoot(gated, {0, 4, 0}, {1, 0, 0}));
    auto h = shoot(gated, {10.5, -5, 0}, {0, 1, 0});  // through the box, to y = 0.25
    REQUIRE(h);
    CHECK(h->t == Approx(5.25));
    // A sphere bound written after a move is taken back into the polynomial's coordinates.
    const StagedScene moved = build_staged(para + "translate 3*y bounded_by { sphere { 3*y, 1 } } }\n");
    CHECK(all_messages(moved.warnings).empty());
    CHECK_FALSE(shoot(moved, {-10, 7, 0}, {1, 0, 0}));
    REQUIRE(shoot(moved, {0, 3.5, -10}, {0, 0, 1}));
    // A bound squashed into an ellipsoid is not a gate photon has: ignored, with the warning.
    const StagedScene squashed = build_staged(para + "bounded_by { sphere { 0, 1 scale <1, 2, 1> } } }\n");
    CHECK_THAT(all_messages(squashed.warnings), Contains("`bounded_by` is ignored"));
    // inside() with POV-Ray's tolerance: p < 1e-4.
    dsl::ParseOptions o;
    o.geometry = dsl::library_object_geometry();
    const auto p = parse(std::string("#declare T = ") + poly_torus_40_12 +
                             "sphere { <inside(T, <6.3, 0, 0>), inside(T, <0, 0, 0>), inside(T, <6.3, 3.5, 0>)>, 1 }",
                         o);
    CHECK(std::get<dsl::SphereShape>(p.desc.objects.at(0).shape).center == dsl::Vector3(1, 0, 0));
    // export-pov writes poly with the gate before the transformations, and reads back the same.
    const std::string text = std::string(stage) + para + "bounded_by { box { -1, 1 } } translate 10*x }\n" +
                             "cubic { <1, 0,0,0, 0,0,0,0,0,0, 0,0,0,0,0, -1, 0,0,0,0> }\n";
    const std::string exported = dsl::export_pov(dsl::parse_string(text, "p.pov"));
    CHECK_THAT(exported, Contains("poly { 2, <1, 0, 0, 0, 0, 0, -1, 1, 0, 0> bounded_by { box { <-1, -1, -1>, <1, 1, 1> } }"));
    CHECK_THAT(exported, Contains("poly { 3, <1, 0,"));
    const std::string twice = dsl::export_pov(dsl::parse_string(exported, "exported.pov"));
    CHECK(twice.substr(twice.find('\n')) == exported.substr(exported.find('\n')));
}

TEST_CASE("examples/scenes/polynomials.pov reads and builds with no warning", "[dsl][polynomial][scenes]") {
    std::vector<dsl::Diagnostic> warnings;
    dsl::ParseOptions po;
    po.diagnostics = collect(warnings);
    po.include_paths = dsl::standard_include_paths();
    dsl::BuildOptions bo;
    bo.diagnostics = collect(warnings);
    const auto built = dsl::build<float>(dsl::parse_file(std::string(PHOTON_SCENES_DIR) + "/polynomials.pov", po), bo);
    CHECK(all_messages(warnings).empty());
    int surfaces = 0, gated = 0, csg = 0;
    for (const auto& o : built.scene.objects()) {
        if (const auto* p = std::get_if<Transformed<PolynomialSurface<float>>>(&o.shape)) {
            ++surfaces;
            gated += p->shape().gate().has_value();
        }
        csg += std::holds_alternative<DefaultCsg<float>>(o.shape);
    }
    CHECK(surfaces == 3);  // the torus, the piriform and the rounded cube
    CHECK(gated == 1);     // the piriform's bounded_by sphere
    CHECK(csg == 1);       // the saddle cut by a box
}
