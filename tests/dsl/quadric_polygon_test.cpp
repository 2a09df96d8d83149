// SPDX-License-Identifier: MIT
// quadric and polygon in the scene language: read with POV-Ray 3.7's syntax, built as the
// library's Quadric (its transformation folded into its numbers; a quadric with no quadratic term
// is the plane it is) and Polygon (loops split where a first point repeats), in CSG, located
// errors for bad values, skipped with a warning where POV-Ray draws nothing, written back by
// export-pov, answered by inside() and trace(); and shapes.inc's quadrics read with no warning.

#include <catch2/catch.hpp>

#include "dsl_test_util.hpp"

#include <map>

using namespace dsl_test;
using namespace photon;
using Catch::Matchers::Contains;

TEST_CASE("quadric: POV-Ray's coefficients, placed by the transformation, in CSG", "[dsl][quadric]") {
    // shapes.inc's Cylinder_X, scaled and moved: radius 0.5 around the line y = 1, z = 0.
    const StagedScene b = build_staged("quadric { <0, 1, 1>, <0, 0, 0>, <0, 0, 0>, -1 scale 0.5 translate y }\n");
    const auto& q = only<Quadric<double>>(b);
    CHECK(std::isinf(q.bounds().max.x));
    CHECK(q.bounds().max.y == Approx(1.5).epsilon(1e-8));
    auto h = shoot(b, {7, 1, -5}, {0, 0, 1});
    REQUIRE(h);
    CHECK(h->t == Approx(4.5));
    CHECK(h->normal.z == Approx(-1));
    // Mixed and linear terms: x^2 + y^2 + z^2 + xy - 1 (an ellipsoid), and (x - 1)^2 + y^2 + z^2 - 1 written out.
    CHECK(only<Quadric<double>>(build_staged("quadric { <1, 1, 1>, <1, 0, 0>, 0, -1 }\n")).bounds().is_finite());
    const StagedScene moved = build_staged("quadric { <1, 1, 1>, <0, 0, 0>, <-2, 0, 0>, 0 }\n");
    h = shoot(moved, {5, 0, 0}, {-1, 0, 0});
    REQUIRE(h);
    CHECK(h->t == Approx(3));
    // No quadratic term: the half-space G x + H y + I z + J <= 0, built as a plane.
    const StagedScene half = build_staged("quadric { 0, 0, <0, 2, 0>, -1 }\n");
    const auto& plane = only<Plane<double>>(half);
    CHECK(plane.normal().y == Approx(1));
    CHECK(plane.offset() == Approx(0.5));
    // An infinite cylinder cut by a box: one CSG object, bounded.
    const StagedScene cut = build_staged("intersection { quadric { <1, 0, 1>, 0, 0, -1 } box { -2, 2 } }\n");
    REQUIRE(cut.scene.objects().size() == 1);
    CHECK(cut.scene.object_bounds(0).is_finite());
    CHECK_THAT(all_messages(cut.warnings), !Contains("skipped") && !Contains("quadric"));
    // `inverse` on its own: the outside of the cylinder (a CSG of one leaf).
    const StagedScene inverted = build_staged("quadric { <1, 0, 1>, 0, 0, -1 inverse }\n");
    h = shoot(inverted, {0, 0, 0}, {1, 0, 0});
    REQUIRE(h);
    CHECK(h->normal.x == Approx(-1));
}

TEST_CASE("quadric and polygon: located errors, and warnings where POV-Ray draws nothing", "[dsl][quadric][polygon][errors]") {
    CHECK_THAT(error_of("quadric { <1, 1, 1>, 0, 0 }"), Contains("1:27: expected the constant of the quadric"));
    CHECK_THAT(error_of("quadric { <1, 1, 1>, <0, 0, 1e300 * 1e300>, 0, -1 }"),
               Contains("1:35: the result of `*` is not a finite number"));
    CHECK_THAT(error_of("polygon { 2, <0, 0>, <1, 0> }"), Contains("1:11: a polygon needs at least 3 points, found 2"));
    CHECK_THAT(error_of("polygon { 4, <0, 0>, <1, 0>, <1, 1> }"), Contains("1:37: expected point 4 of the polygon"));
    CHECK_THAT(error_of("polygon { 3, <0, 0>, <1, 0>, <1, 1> blah }"), Contains("1:37: expected an object modifier"));
    CHECK_THAT(error_of("polygon { 1e12, <0, 0>, <1, 0>, <1, 1> }"), Contains("1:11: the polygon has too many points"));

    const StagedScene b = build_staged("quadric { 0, 0, 0, 1 }\n"
                               "polygon { 3, <0, 0>, <1, 1>, <2, 2> }\n"
                               "polygon { 4, <0, 0, 0>, <1, 0, 0>, <1, 1, 0>, <0, 1, 1> }\n");
    CHECK(b.scene.objects().empty());
    CHECK(places(b.warnings, "skipped object") == std::vector<std::string>{"3:11 quadric", "4:11 polygon", "5:11 polygon"});
    CHECK_THAT(all_messages(b.warnings), Contains("`quadric` is skipped: it has no surface (its coefficients of x, y "
                                                  "and z are all 0), POV-Ray renders nothing for it either"));
    CHECK_THAT(all_messages(b.warnings), Contains("its points are all on one line or not in one plane"));
}

TEST_CASE("polygon: loops closed by their first point, 2D and 3D points, transformed", "[dsl][polygon]") {
    // POV-Ray's objects/polygon.pov style: an outer square and an inner one, each closed.
    const StagedScene b = build_staged("polygon { 10, <-2, -2>, <2, -2>, <2, 2>, <-2, 2>, <-2, -2>,"
                               " <-1, -1>, <1, -1>, <1, 1>, <-1, 1>, <-1, -1> rotate -90*x translate y }\n");
    const auto& p = only<Polygon<double>>(b);
    CHECK(std::abs(p.normal().y) == Approx(1));
    CHECK(shoot(b, {1.5, 5, 0}, {0, -1, 0}));         // on the frame
    CHECK_FALSE(shoot(b, {0, 5, 0}, {0, -1, 0}));     // in the hole
    CHECK_FALSE(shoot(b, {2.5, 5, 0}, {0, -1, 0}));   // outside
    const auto h = shoot(b, {1.5, 5, 0}, {0, -1, 0});
    REQUIRE(h);
    CHECK(h->t == Approx(4));
    // The last loop left open is closed, as POV-Ray closes it.
    const StagedScene open = build_staged("polygon { 3, <0, 0, 1>, <1, 0, 1>, <0, 1, 1> }\n");
    CHECK(shoot(open, {0.2, 0.2, 5}, {0, 0, -1}));
    CHECK(dsl::polygon_loops({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 0}, {5, 5, 0}, {6, 5, 0}, {5, 6, 0}}).size() == 2);
    // A polygon has no inside: `inverse` says so, and it is not a CSG child that decides.
    const StagedScene inv = build_staged("polygon { 3, 0, x, y inverse }\n");
    CHECK_THAT(all_messages(inv.warnings), Contains("`inverse` on a `polygon` is ignored: it has no inside"));
}

TEST_CASE("quadric and polygon: export-pov writes them back, inside() and trace() answer", "[dsl][quadric][polygon][export]") {
    const std::string text = std::string(stage) +
                             "quadric { <1, 0, 1>, <0, 0.5, 0>, <0, -1, 0>, -2 rotate 30*z pigment { rgb 0.5 } }\n"
                             "polygon { 5, <0, 0>, <1, 0>, <1, 1>, <0, 1>, <0, 0> translate z }\n";
    const auto desc = dsl::parse_string(text, "q.pov");
    const std::string exported = dsl::export_pov(desc);
    CHECK_THAT(exported, Contains("quadric { <1, 0, 1>, <0, 0.5, 0>, <0, -1, 0>, -2"));
    CHECK_THAT(exported, Contains("polygon { 5, <0, 0, 0>, <1, 0, 0>, <1, 1, 0>, <0, 1, 0>, <0, 0, 0>"));
    const auto again = dsl::parse_string(exported, "exported.pov");
    const std::string twice = dsl::export_pov(again);
    CHECK(twice.substr(twice.find('\n')) == exported.substr(exported.find('\n')));

    dsl::ParseOptions o;
    o.geometry = dsl::library_object_geometry();
    const auto value = [&](const std::string& declare, const std::string& expression) {
        const auto p = parse(declare + "\nsphere { " + expression + ", 1 }", o);
        return std::get<dsl::SphereShape>(p.desc.objects.at(0).shape).center;
    };
    const std::string q = "#declare Q = quadric { <1, 0, 1>, 0, 0, -1 translate x }";
    CHECK(value(q, "<inside(Q, <1.5, 100, 0>), inside(Q, <2.5, 0, 0>), inside(Q, <2, 0, 0>)>") == dsl::Vector3(1, 0, 1));
    CHECK(glm::length(value(q, "trace(Q, <-5, 3, 0>, x)") - dsl::Vector3(0, 3, 0)) < 1e-9);
    const std::string g = "#declare G = polygon { 4, <0, 0>, <1, 0>, <1, 1>, <0, 1> }";
    CHECK(value(g, "<inside(G, <0.5, 0.5, 0>), 0, 0>") == dsl::Vector3(0, 0, 0));  // POV-Ray: no inside
    CHECK(glm::length(value(g, "trace(G, <0.5, 0.5, -5>, z)") - dsl::Vector3(0.5, 0.5, 0)) < 1e-9);
    CHECK(glm::length(value(g, "max_extent(G)") - dsl::Vector3(1, 1, 0)) < 1e-9);
}

TEST_CASE("shapes.inc's quadrics read and build with no warning", "[dsl][quadric][includes]") {
    dsl::ParseOptions o;
    o.include_paths = {"/usr/share/povray-3.7/include"};
    if (!std::filesystem::exists("/usr/share/povray-3.7/include/shapes.inc")) {
        WARN("POV-Ray's includes are not installed: not tested");
        return;
    }
    const StagedScene b = build_staged("#include \"shapes.inc\"\n"
                               "intersection { object { Cylinder_X } object { QCone_Y } box { -2, 2 } }\n"
                               "object { Paraboloid_Y scale 0.5 clipped_by { box { -1, 1 } } }\n"
                               "intersection { object { Hyperboloid_Y } sphere { 0, 3 } }\n",
                               o);
    for (const auto& w : b.warnings) CHECK_THAT(w.message, !Contains("quadric"));
    CHECK(b.scene.objects().size() == 3);
}

TEST_CASE("examples/scenes/quadric.pov builds without a warning into quadrics, CSG and a polygon", "[dsl][quadric][scenes]") {
    std::vector<dsl::Diagnostic> warnings;
    dsl::ParseOptions po;
    po.diagnostics = collect(warnings);
    dsl::BuildOptions bo;
    bo.diagnostics = collect(warnings);
    const auto desc = dsl::parse_file(std::string(PHOTON_SCENES_DIR) + "/quadric.pov", po);
    const auto built = dsl::build<float>(desc, bo);
    CHECK(all_messages(warnings).empty());
    std::map<std::size_t, int> kinds;
    for (const auto& o : built.scene.objects()) ++kinds[o.shape.index()];
    using Shape = DefaultScene<float>::Shape;
    CHECK(kinds[Shape(Quadric<float>(QuadricCoefficients<float>{{1, 1, 1}, {}, {}, -1})).index()] == 1);
    CHECK(kinds[Shape(Polygon<float>({{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}})).index()] == 1);
    CHECK(kinds[Shape(DefaultCsg<float>(Box<float>({0, 0, 0}, {1, 1, 1}))).index()] == 3);
    // Bounded but the dome: a paraboloid's box is infinite (its solid reaches every x and z), and so
    // is a plane's, so the box of their intersection is too (tested outside the BVH, as planes are).
    int finite = 0;
    for (std::uint32_t i = 0; i < built.scene.objects().size(); ++i) finite += built.scene.object_bounds(i).is_finite();
    CHECK(built.scene.objects().size() == 7);
    CHECK(finite == 6);
}
