// SPDX-License-Identifier: MIT
// superellipsoid, lathe and sor in the scene language: POV-Ray 3.7's reading of their numbers,
// built as Transformed library shapes (also in CSG), located errors, written back by export-pov,
// and min_extent, max_extent and inside() against POV-Ray's numbers (povray 3.7 with #debug).

#include <catch2/catch.hpp>

#include "dsl_test_util.hpp"

using namespace dsl_test;
using namespace photon;
using Catch::Matchers::Contains;

namespace {

dsl::Vector3 revolved_query(const std::string& declare, const std::string& expression) {
    dsl::ParseOptions o;
    o.geometry = dsl::library_object_geometry();
    const auto p = parse(declare + "\nsphere { " + expression + ", 1 }", o);
    return std::get<dsl::SphereShape>(p.desc.objects.at(0).shape).center;
}

bool revolved_close(const dsl::Vector3& a, const dsl::Vector3& b, double eps = 1e-6) { return glm::length(a - b) <= eps; }

const std::string revolved_declarations =
    "#declare L = lathe { 4, <0,0>, <1,0>, <0.5,2>, <0,2> }\n"
    "#declare C = lathe { cubic_spline 6, <0,-1>, <0,0>, <1,0.5>, <0.8,1.5>, <0,2>, <0,3> }\n"
    "#declare R = sor { 6, <0,-0.5>, <0.6,0>, <1.1,0.5>, <0.4,1.2>, <0.7,1.8>, <0.9,2.2> }\n"
    "#declare E = superellipsoid { <0.3, 2.5> }\n";

}  // namespace

TEST_CASE("lathe, sor and superellipsoid: POV-Ray's extents and inside()", "[dsl][revolved]") {
    const std::string& d = revolved_declarations;
    // POV-Ray 3.7: L -1,0,-1 | 1,2,1; C -1.048452,0,-1.048452 | 1.048452,2,1.048452 (the cubic's
    // widest point, not its control points); R -1.101730,0,-1.101730 | 1.101730,1.8,1.101730;
    // E -1.0001 | 1.0001 (POV-Ray pads the superellipsoid's box by 1e-4).
    CHECK(revolved_close(revolved_query(d, "min_extent(L)"), {-1, 0, -1}));
    CHECK(revolved_close(revolved_query(d, "max_extent(L)"), {1, 2, 1}));
    CHECK(revolved_close(revolved_query(d, "min_extent(C)"), {-1.048452, 0, -1.048452}));
    CHECK(revolved_close(revolved_query(d, "max_extent(C)"), {1.048452, 2, 1.048452}));
    CHECK(revolved_close(revolved_query(d, "min_extent(R)"), {-1.101730, 0, -1.101730}));
    CHECK(revolved_close(revolved_query(d, "max_extent(R)"), {1.101730, 1.8, 1.101730}));
    CHECK(revolved_close(revolved_query(d, "max_extent(E)"), {1, 1, 1}, 2e-4));
    // POV-Ray: 1 0 1 0 1 0 0 0 for these eight points.
    CHECK(revolved_query(d, "<inside(L, <0.7,0.5,0>), inside(L, <0.7,1.5,0>), inside(C, <0.9,0.6,0>)>") == dsl::Vector3(1, 0, 1));
    CHECK(revolved_query(d, "<inside(C, <0.5,1.9,0>), inside(R, <0,1,0.55>), inside(R, <0.8,1,0>)>") == dsl::Vector3(0, 1, 0));
    CHECK(revolved_query(d, "<inside(E, <0.9,0.9,0.2>), inside(E, <0.9,0.9,0.9>), inside(E, <0.2,0.2,0.2>)>") ==
          dsl::Vector3(0, 0, 1));
}

TEST_CASE("lathe, sor and superellipsoid: built, hit, transformed and in CSG", "[dsl][revolved][csg]") {
    // A cylinder as a lathe, scaled: the wall at radius 2.
    const StagedScene l = build_staged("lathe { linear_spline 4, <0,0>, <1,0>, <1,1>, <0,1> sturm scale <2, 1, 2> }\n");
    CHECK(l.warnings.empty());
    only<Transformed<Lathe<double>>>(l);
    auto h = shoot(l, {-5, 0.5, 0}, {1, 0, 0});
    REQUIRE(h);
    CHECK(h->t == Approx(3));
    CHECK(h->normal.x == Approx(-1));
    // Each spline type builds: a quadratic vase and a Bezier one, hit on their sides.
    const StagedScene q = build_staged("lathe { quadratic_spline 5, <0,0>, <0.5,0>, <1,1>, <0.6,2>, <0.8,3> }\n"
                                       "lathe { bezier_spline 4, <0.5,0>, <1.5,0.5>, <1.5,1.5>, <0.5,2> translate 5*x }\n");
    CHECK(q.warnings.empty());
    REQUIRE(q.scene.objects().size() == 2);
    CHECK(shoot(q, {0, 1, -5}, {0, 0, 1}));
    h = shoot(q, {5, 1, -5}, {0, 0, 1});
    REQUIRE(h);
    CHECK(h->normal.z < -0.9);
    // A sor, open: down its axis nothing; closed: the cap.
    const StagedScene s = build_staged("sor { 4, <1,-1>, <1,0>, <1,1>, <1,2> open }\nsor { 4, <1,-1>, <1,0>, <1,1>, <1,2> translate 5*x }\n");
    CHECK(s.warnings.empty());
    CHECK_FALSE(shoot(s, {0, 5, 0}, {0, -1, 0}));
    h = shoot(s, {5, 5, 0}, {0, -1, 0});
    REQUIRE(h);
    CHECK(h->t == Approx(4));
    // A superellipsoid close to a box: its face at x = -1.
    const StagedScene e = build_staged("superellipsoid { <0.05, 0.05> translate y }\n");
    CHECK(e.warnings.empty());
    only<Transformed<Superellipsoid<double>>>(e);
    h = shoot(e, {-5, 1.2, 0.3}, {1, 0, 0});
    REQUIRE(h);
    CHECK(h->t == Approx(4).epsilon(1e-6));
    // A difference whose lathe decides its shape: a cup cut from a box, no longer skipped.
    const StagedScene c = build_staged("difference { box { <-2, 0, -2>, <2, 1, 2> }"
                                       " lathe { 4, <0,0.5>, <1,0.5>, <1,2>, <0,2> } pigment { rgb 1 } }\n");
    CHECK(c.warnings.empty());
    REQUIRE(c.scene.objects().size() == 1);
    h = shoot(c, {0, 5, 0}, {0, -1, 0});
    REQUIRE(h);
    CHECK(h->t == Approx(4.5));  // the cup's floor
    h = shoot(c, {1.5, 5, 0}, {0, -1, 0});
    REQUIRE(h);
    CHECK(h->t == Approx(4));  // the box's top beside it
}

TEST_CASE("lathe, sor and superellipsoid: errors and warnings as POV-Ray's", "[dsl][revolved][errors]") {
    CHECK_THAT(error_of("lathe { 1, <0,0> }"), Contains("1:9: a lathe with linear splines needs at least 2 points"));
    CHECK_THAT(error_of("lathe { cubic_spline 3, <0,0>, <1,0>, <1,1> }"),
               Contains("1:22: a lathe with cubic splines needs at least 4 points"));
    CHECK_THAT(error_of("lathe { bezier_spline 5, <0,0>, <1,0>, <1,1>, <0,1>, <0,2> }"),
               Contains("1:23: a lathe with Bezier splines needs 4 points per segment"));
    CHECK_THAT(error_of("lathe { 3, <0,0>, <-1,0>, <0,1> }"), Contains("1:19: point 2 of the lathe has a negative radius"));
    CHECK_THAT(error_of("sor { 3, <0,0>, <1,0>, <1,1> }"), Contains("1:7: a sor needs at least 4 points"));
    CHECK_THAT(error_of("sor { 5, <0,0>, <1,0>, <1,1>, <1,0.5>, <1,3> }"),
               Contains("1:31: point 4 of the sor must be higher than the point before it"));
    CHECK_THAT(error_of("sor { 4, <0,0>, <-1,0>, <1,1>, <1,2> }"), Contains("1:17: point 2 of the sor has a negative radius"));
    CHECK_THAT(error_of("superellipsoid { <0, 1> }"), Contains("1:18: the exponents of the superellipsoid must be positive"));
    // A negative radius at a linear lathe's end: accepted with POV-Ray 3.7's warning.
    const StagedScene b = build_staged("lathe { 3, <-0.5,0>, <1,0.5>, <0,1> }\n");
    CHECK(b.scene.objects().size() == 1);
    CHECK_THAT(all_messages(b.warnings), Contains("point 1 of the lathe has a negative radius"));
}

TEST_CASE("lathe, sor and superellipsoid: export-pov writes what reads back the same", "[dsl][revolved][export]") {
    const std::string text = std::string(stage) +
                             "lathe { quadratic_spline 5, <0,0>, <0.5,0>, <1,1>, <0.6,2>, <0.8,3> }\n"
                             "sor { 4, <1,-1>, <1,0>, <1,1>, <1,2> open }\nsuperellipsoid { <0.25, 1.5> }\n";
    const std::string exported = dsl::export_pov(dsl::parse_string(text, "r.pov"));
    CHECK_THAT(exported, Contains("lathe { bezier_spline 12, <0.5, 0>"));
    CHECK_THAT(exported, Contains("sor { 4, <1, -1>, <1, 0>, <1, 1>, <1, 2> open"));
    CHECK_THAT(exported, Contains("superellipsoid { <0.25, 1.5>"));
    const std::string twice = dsl::export_pov(dsl::parse_string(exported, "exported.pov"));
    CHECK(twice.substr(twice.find('\n')) == exported.substr(exported.find('\n')));
}

TEST_CASE("examples/scenes/revolved.pov reads and builds with no warning", "[dsl][revolved][scenes]") {
    std::vector<dsl::Diagnostic> warnings;
    dsl::ParseOptions po;
    po.diagnostics = collect(warnings);
    dsl::BuildOptions bo;
    bo.diagnostics = collect(warnings);
    const auto built = dsl::build<float>(dsl::parse_file(std::string(PHOTON_SCENES_DIR) + "/revolved.pov", po), bo);
    CHECK(all_messages(warnings).empty());
    int supers = 0, lathes = 0, sors = 0, csg = 0;
    for (const auto& o : built.scene.objects()) {
        supers += std::holds_alternative<Transformed<Superellipsoid<float>>>(o.shape);
        lathes += std::holds_alternative<Transformed<Lathe<float>>>(o.shape);
        sors += std::holds_alternative<Transformed<Sor<float>>>(o.shape);
        csg += std::holds_alternative<DefaultCsg<float>>(o.shape);
    }
    CHECK(supers == 3);
    CHECK(lathes == 2);
    CHECK(sors == 1);
    CHECK(csg == 1);  // the cup cut into the block
}
