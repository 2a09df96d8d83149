// SPDX-License-Identifier: MIT
// cylinder, cone, disc and torus in the scene language: read with POV-Ray 3.7's syntax and
// values, placed as the library's shapes (Transformed where the map is not a similarity),
// located errors and warnings for bad values, written back by export-pov, and answered by
// inside(), trace(), min_extent() and max_extent().

#include <catch2/catch.hpp>

#include "dsl_test_util.hpp"

#include <fstream>
#include <map>
#include <iterator>

using namespace dsl_test;
using namespace photon;
using Catch::Matchers::Contains;

namespace {

bool near_point(const Vec3<double>& a, const Vec3<double>& b, double eps = 1e-9) { return glm::length(a - b) <= eps; }

}  // namespace

TEST_CASE("the round shapes are built as the library's shapes, placed by their transforms", "[dsl][quadrics]") {
    SECTION("cylinder: moved, rotated and uniformly scaled it stays a Cylinder") {
        const StagedScene b = build_staged("cylinder { <0, 0, 0>, <0, 2, 0>, 0.5 open scale 2 rotate 90*z translate x }\n");
        CHECK(places(b.warnings, "skipped object").empty());
        const auto& c = only<Cylinder<double>>(b);
        CHECK(c.radius() == Approx(1));
        CHECK(c.length() == Approx(4));
        CHECK(c.open());
        CHECK(near_point(c.base(), {1, 0, 0}));
        CHECK(near_point(c.cap(), {-3, 0, 0}, 1e-9));
    }
    SECTION("a non-uniform scale makes a cylinder a Transformed cone with equal radii, an ellipse in section") {
        const StagedScene b = build_staged("cylinder { -y, y, 1 scale <2, 1, 1> }\n");
        const auto& t = only<Transformed<TruncatedCone<double>>>(b);
        CHECK(t.shape().base_radius() == t.shape().cap_radius());
        const auto hit = shoot(b, {-5, 0, 0}, {1, 0, 0});
        REQUIRE(hit);
        CHECK(near_point(hit->point, {-2, 0, 0}));
        CHECK(near_point(hit->normal, {-1, 0, 0}));
        CHECK(shoot(b, {0, 0, -5}, {0, 0, 1})->point.z == Approx(-1));
        // Closed: the caps are hit from above.
        CHECK(shoot(b, {1.5, 5, 0}, {0, -1, 0})->point.y == Approx(1));
    }
    SECTION("cone: radii kept, a pointed one, and equal radii read as a cylinder (POV-Ray's rule)") {
        const StagedScene pointed = build_staged("cone { 0, 1, 2*y, 0 translate z }\n");
        const auto& k = only<TruncatedCone<double>>(pointed);
        CHECK(k.base_radius() == 1);
        CHECK(k.cap_radius() == 0);
        CHECK(near_point(k.base(), {0, 0, 1}));
        CHECK(only<Cylinder<double>>(build_staged("cone { 0, 0.5, y, 0.5 }\n")).radius() == 0.5);
        CHECK(only<Cylinder<double>>(build_staged("cone { 0, 0.5, y, 0.5 + 1e-12 }\n")).radius() == 0.5);
        const StagedScene open = build_staged("cone { 0, 1, y, 0.5 open }\n");
        CHECK(only<TruncatedCone<double>>(open).open());
        // Open: a ray down the axis passes through.
        CHECK_FALSE(shoot(open, {0, 5, 0}, {0, -1, 0}).has_value());
    }
    SECTION("disc: its hole, its normal turned with it, and a squashed disc Transformed") {
        const StagedScene ring = build_staged("disc { <0, 1, 0>, <0, 0, -3>, 2, 1 rotate 90*x }\n");
        const auto& d = only<Disc<double>>(ring);
        CHECK(d.radius() == 2);
        CHECK(d.hole_radius() == 1);
        CHECK(near_point(d.normal(), {0, 1, 0}, 1e-12));
        CHECK(near_point(d.center(), {0, 0, 1}, 1e-12));
        const StagedScene squashed = build_staged("disc { 0, y, 1, 0.5 scale <3, 1, 1> }\n");
        (void)only<Transformed<Disc<double>>>(squashed);
        CHECK(shoot(squashed, {2.5, 1, 0}, {0, -1, 0}).has_value());  // inside the ellipse
        CHECK_FALSE(shoot(squashed, {1.2, 1, 0}, {0, -1, 0}).has_value());  // in the hole
        CHECK_FALSE(shoot(squashed, {0, 1, 0.4}, {0, -1, 0}).has_value());  // in the hole along z
        CHECK(shoot(squashed, {0, 1, 0.9}, {0, -1, 0}).has_value());         // the ring along z is not widened
    }
    SECTION("torus: around y at the origin, placed by its transform; major radius 0 is a sphere") {
        const StagedScene b = build_staged("torus { 2, 0.5 sturm rotate 90*x translate <0, 0, 5> }\n");
        const auto& t = only<Transformed<Torus<double>>>(b);
        CHECK(t.shape().major_radius() == 2);
        CHECK(t.shape().minor_radius() == 0.5);
        const auto hit = shoot(b, {0, 10, 5}, {0, -1, 0});  // the ring now stands in the xy plane
        REQUIRE(hit);
        CHECK(hit->point.y == Approx(2.5));
        CHECK(near_point(hit->normal, {0, 1, 0}, 1e-9));
        CHECK_FALSE(shoot(b, {0, 0, 0}, {0, 0, 1}).has_value());  // through the hole
        CHECK(only<Sphere<double>>(build_staged("torus { 0, 0.5 translate x }\n")).radius() == 0.5);
    }
}

TEST_CASE("bad values of the round shapes: located errors, and warnings where POV-Ray draws nothing",
          "[dsl][quadrics][errors]") {
    CHECK_THAT(error_of("cone { 0, -1, y, 0.5 }"), Contains("1:11: a cone's radii must not be negative, found -1"));
    CHECK_THAT(error_of("cylinder { <-1e300, 0, 0>, <1e300, 0, 0>, 1 }"),
               Contains("1:28: the length of the cylinder must be finite, found inf"));
    CHECK_THAT(error_of("torus { 1 }"), Contains("1:11: expected the minor radius of the torus"));
    CHECK_THAT(error_of("cylinder { 0, y }"), Contains("1:17: expected the radius of the cylinder"));
    CHECK_THAT(error_of("cone { 0, 1, y }"), Contains("1:16: expected the cap radius of the cone"));
    CHECK_THAT(error_of("disc { 0, y }"), Contains("expected the radius of the disc"));
    CHECK_THAT(error_of("cylinder { 0, y, 1 pigment { rgb 1 } blah }"), Contains("1:38: expected an object modifier"));
    CHECK_THAT(error_of("cylinder { 0, y, 1 pigment { rgb 1 } open }"), Contains("1:38: expected an object modifier"));

    const StagedScene b = build_staged("cylinder { 0, y, 0 }\n"
                               "cone { 0, 0, y, 0 }\n"
                               "disc { 0, 0, 1 }\n"
                               "disc { 0, y, 1, 1 }\n"
                               "torus { 1, 0 }\n"
                               "#declare Post = cylinder { 0, y, 0 }\n"
                               "object { Post }\n"
                               "cylinder { <1, 2, 3>, <1, 2, 3>, 1 }\n"
                               "cone { 0, 1, <0, 1e-11, 0>, 0 }\n");
    CHECK(b.scene.objects().empty());
    CHECK(places(b.warnings, "skipped object") ==
          std::vector<std::string>{"3:18 cylinder", "4:11 cone", "5:11 disc", "6:17 disc", "7:12 torus",
                                   "8:34 cylinder", "9:10 cylinder", "10:12 cylinder", "11:8 cone"});
    // POV-Ray stops at a degenerate cylinder; photon skips it (a trace() that missed a skipped object
    // makes one in POV-Ray's own language/trace.pov).
    CHECK_THAT(all_messages(b.warnings), Contains("`cylinder` is skipped: its base and cap points are the same point "
                                                  "<1, 2, 3>; POV-Ray stops with \"Degenerate cylinder\" here"));
    CHECK_THAT(all_messages(b.warnings),
               Contains("`cylinder` is skipped: it has no surface (radius 0), POV-Ray renders nothing for it either"));
    CHECK_THAT(all_messages(b.warnings), Contains("its hole radius 1 is not below its radius 1"));
    CHECK_THAT(all_messages(b.warnings), Contains("`Post` is a `cylinder` (declared at 8:10): skipped, it has no surface"));

    // Negative radii that POV-Ray squares or mirrors: read as their absolute values, with a warning.
    const StagedScene negative = build_staged("cylinder { 0, y, -0.5 }\n");
    CHECK(only<Cylinder<double>>(negative).radius() == 0.5);
    CHECK_THAT(all_messages(negative.warnings),
               Contains("the radius of the cylinder is negative (-0.5): read as 0.5, as POV-Ray does"));
    CHECK(only<Disc<double>>(build_staged("disc { 0, y, -2, -1 }\n")).hole_radius() == 1);
    CHECK(only<Transformed<Torus<double>>>(build_staged("torus { -2, 0.5 }\n")).shape().major_radius() == 2);
}

TEST_CASE("export-pov writes the round shapes back: they read again as the same scene", "[dsl][quadrics][export]") {
    const std::string text = std::string(stage) +
                             "cylinder { <1, 0, 0>, <1, 2, 0>, 0.25 open scale <1, 2, 1> pigment { rgb 0.5 } }\n"
                             "cone { 0, 1, y, 0.125 rotate 30*z }\n"
                             "disc { <0, 1, 0>, <1, 1, 0>, 2, 0.5 }\n"
                             "disc { 0, z, 1 }\n"
                             "torus { 1.5, 0.25 rotate <10, 20, 30> translate y }\n";
    const auto desc = dsl::parse_string(text, "round.pov");
    const std::string exported = dsl::export_pov(desc);
    CHECK_THAT(exported, Contains("cylinder { <1, 0, 0>, <1, 2, 0>, 0.25 open"));
    CHECK_THAT(exported, Contains("disc { <0, 1, 0>, <1, 1, 0>, 2, 0.5"));
    CHECK_THAT(exported, Contains("torus { 1.5, 0.25"));
    const auto again = dsl::parse_string(exported, "exported.pov");
    const std::string twice = dsl::export_pov(again);
    CHECK(twice.substr(twice.find('\n')) == exported.substr(exported.find('\n')));
    const auto a = dsl::build<double>(desc), b = dsl::build<double>(again);
    REQUIRE(a.scene.objects().size() == 5);
    REQUIRE(b.scene.objects().size() == 5);
    for (std::uint32_t i = 0; i < 5; ++i) {
        INFO("object " << i);
        CHECK(a.scene.objects()[i].shape.index() == b.scene.objects()[i].shape.index());
        CHECK(near_point(a.scene.object_bounds(i).min, b.scene.object_bounds(i).min, 1e-12));
        CHECK(near_point(a.scene.object_bounds(i).max, b.scene.object_bounds(i).max, 1e-12));
    }
}

TEST_CASE("inside(), trace() and the extents answer for the round shapes", "[dsl][quadrics][geometry]") {
    dsl::ParseOptions o;
    o.geometry = dsl::library_object_geometry();
    const auto value = [&](const std::string& declare, const std::string& expression) {
        const auto p = parse(declare + "\nsphere { " + expression + ", 1 }", o);
        return std::get<dsl::SphereShape>(p.desc.objects.at(0).shape).center;
    };
    const std::string tube = "#declare T = cylinder { 0, 2*y, 1 open translate x }";
    CHECK(value(tube, "<inside(T, <1, 1, 0>), inside(T, <1, 3, 0>), inside(T, <2.5, 1, 0>)>") == dsl::Vector3(1, 0, 0));
    const std::string cone = "#declare K = cone { 0, 1, 2*y, 0 }";
    CHECK(value(cone, "<inside(K, <0, 1.9, 0>), inside(K, <0.6, 1, 0>), inside(K, <0.4, 1, 0>)>") ==
          dsl::Vector3(1, 0, 1));
    const std::string disc = "#declare D = disc { y, y, 1 }";  // POV-Ray: the half-space behind the normal
    CHECK(value(disc, "<inside(D, <5, 0, 0>), inside(D, <0, 2, 0>), 0>") == dsl::Vector3(1, 0, 0));
    const std::string ring = "#declare R = torus { 2, 0.5 }";
    CHECK(value(ring, "<inside(R, <2, 0.4, 0>), inside(R, <0, 0, 0>), inside(R, <0, 0, -2.3>)>") ==
          dsl::Vector3(1, 0, 1));

    CHECK(near_point(value(ring, "trace(R, <0, 5, 2>, -y)"), {0, 0.5, 2}));
    CHECK(near_point(value("#declare R = torus { 2, 0.5 rotate 90*x }", "trace(R, <-5, 0, 0>, x)"), {-2.5, 0, 0}));
    CHECK(near_point(value(ring, "min_extent(R)"), {-2.5, -0.5, -2.5}));
    CHECK(near_point(value(ring, "max_extent(R)"), {2.5, 0.5, 2.5}));
    CHECK(near_point(value(tube, "max_extent(T)"), {2, 2, 1}));
    CHECK(near_point(value(disc, "trace(D, <0.5, 3, 0>, -y)"), {0.5, 1, 0}));
    CHECK(near_point(value(cone, "trace(K, <-5, 1, 0>, x)"), {-0.5, 1, 0}));
}

TEST_CASE("the fuzz seed of the round shapes reads and builds, its values read as POV-Ray reads them",
          "[dsl][quadrics]") {
    std::ifstream in(std::string(PHOTON_SCENES_DIR) + "/../../fuzz/seeds/quadrics.pov", std::ios::binary);
    const std::string text((std::istreambuf_iterator<char>(in)), {});
    REQUIRE(!text.empty());
    dsl::ParseOptions o;
    o.geometry = dsl::library_object_geometry();
    const Parsed p = parse(text, o);
    // The only warnings: the negative disc radius and the cylinder of radius 0.
    CHECK(places(p.warnings, "skipped object") == std::vector<std::string>{"18:18 cylinder"});
    CHECK_THAT(all_messages(p.warnings), Contains("the radius of the disc is negative (-1)"));
    CHECK(p.warnings.size() == 2);
    const auto built = dsl::build<float>(p.desc);
    CHECK(built.scene.objects().size() == 13);
}

TEST_CASE("examples/scenes/shapes.pov builds without a warning into the library's round shapes, and renders",
          "[dsl][quadrics][scenes]") {
    std::vector<dsl::Diagnostic> warnings;
    dsl::ParseOptions po;
    po.diagnostics = collect(warnings);
    dsl::BuildOptions bo;
    bo.diagnostics = collect(warnings);
    bo.overrides = {{"width", 40u}, {"height", 30u}, {"global_photons", 4000u}, {"samples_per_pixel", 1u},
                    {"shadow_samples", 1u}, {"final_gather_rays", 4u}};
    const auto b = dsl::load_scene<float>(std::filesystem::path(PHOTON_SCENES_DIR) / "shapes.pov", po, bo);
    INFO(all_messages(warnings));
    CHECK(warnings.empty());
    std::map<std::string, int> kinds;
    for (const auto& o : b.scene.objects())
        ++kinds[std::visit([](const auto& s) { return plan::shape_name(s); }, o.shape)];
    CHECK(kinds == std::map<std::string, int>{{"box", 2}, {"cone", 1}, {"cylinder", 1}, {"disc", 1},
                                              {"transformed open cylinder", 1}, {"transformed torus", 1}});
    const RenderResult r = render(b.scene, b.camera, b.settings);
    CHECK(r.film.all_finite_nonnegative());
    CHECK(r.film.mean().x > 0.05);
}
