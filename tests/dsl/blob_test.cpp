// SPDX-License-Identifier: MIT
// blob in the scene language: POV-Ray 3.7's syntax (both component syntaxes, `strength` optional,
// the threshold 1 unless given, each component's own transformations, sturm and hierarchy),
// inside() and the extents against POV-Ray's answers (povray 3.7 with #debug), built as a
// Transformed library Blob (also in CSG), located errors, a component's texture reported as
// approximated, and export-pov's round trip.

#include <catch2/catch.hpp>

#include <cmath>

#include "dsl_test_util.hpp"

using namespace dsl_test;
using namespace photon;
using Catch::Matchers::Contains;

namespace {

const std::string blob_declaration =
    "#declare B = blob { threshold 0.5 sphere { <0,0,0>, 1, 1 }\n"
    "  cylinder { <-1,0,0>, <1,0,0>, 0.5, 2 scale <1,2,1> } sphere { <0.5,0.5,0>, 0.6, strength -1 }\n"
    "  component 1, 0.8, <0,1,0> rotate 20*z }\n";

}  // namespace

TEST_CASE("blob: inside() and the extents as POV-Ray answers them", "[dsl][blob]") {
    // POV-Ray 3.7: inside(B, <I*0.2, J*0.2, 0.1>) for I (rows) and J (columns) from -8 to 8.
    const char* const povray[17] = {"00000000000000000", "00000000000000000", "00000011110000000", "00001111110000000",
                                    "00001111111000000", "00001111111111100", "00001111111111100", "00001111111111100",
                                    "00000111111111000", "00000111111100000", "00000111111100000", "00000011111100000",
                                    "00000011111110000", "00000001111110000", "00000001111000000", "00000000000000000",
                                    "00000000000000000"};
    std::string loop = blob_declaration +
                       "#for (I, -8, 8) #declare Row = \"\";\n"
                       "  #for (J, -8, 8) #declare Row = concat(Row, str(inside(B, <I*0.2, J*0.2, 0.1>), 0, 0)); #end\n"
                       "  #warning concat(str(I + 8, 0, 0), \":\", Row)\n"
                       "#end\nsphere { 0, 1 }\n";
    const Parsed p = parse(loop);
    const std::string messages = all_messages(p.warnings);
    for (int row = 0; row < 17; ++row)
        CHECK_THAT(messages, Contains("#warning: " + std::to_string(row) + ":" + povray[row]));
    // POV-Ray: min_extent -1, 0, 1 and max_extent 3, 4, 5 (a carving component bounds nothing).
    dsl::ParseOptions o;
    o.geometry = dsl::library_object_geometry();
    const auto q = parse("#declare S = blob { sphere { <1,2,3>, 2, 3 } sphere { <0,0,0>, 1, -1 } }\n"
                         "sphere { min_extent(S), 1 } sphere { max_extent(S), 1 }\n",
                         o);
    CHECK(glm::length(std::get<dsl::SphereShape>(q.desc.objects.at(0).shape).center - dsl::Vector3(-1, 0, 1)) < 1e-5);
    CHECK(glm::length(std::get<dsl::SphereShape>(q.desc.objects.at(1).shape).center - dsl::Vector3(3, 4, 5)) < 1e-5);
}

TEST_CASE("blob: built as the library's Blob, hit where the field meets the threshold, in CSG", "[dsl][blob][csg]") {
    // The threshold 1 unless given: one component of strength 4 and radius 2 reaches 2 sqrt(1/2).
    const StagedScene b = build_staged("blob { sphere { 0, 2, 4 } sturm hierarchy off translate x }\n");
    CHECK(b.warnings.empty());
    only<Transformed<Blob<double>>>(b);
    auto h = shoot(b, {-5, 0, 0}, {1, 0, 0});
    REQUIRE(h);
    CHECK(h->t == Approx(6 - 2 * std::sqrt(0.5)));
    CHECK(h->normal.x == Approx(-1));
    // The old syntax (strength, radius, centre) and a cylinder component turned by its own rotate.
    const StagedScene c = build_staged("blob { threshold 0.25 component 1, 1, <0, 0, 3>\n"
                                       "  cylinder { <-1, 0, 0>, <1, 0, 0>, 1, 1 rotate 90*z } }\n");
    CHECK(c.warnings.empty());
    const double rho = std::sqrt(1 - std::sqrt(0.25));
    h = shoot(c, {0, 5, 0}, {0, -1, 0});  // the cylinder now runs along y: its end cap at y = 1 + rho
    REQUIRE(h);
    CHECK(h->t == Approx(4 - rho));
    h = shoot(c, {0, 0, 10}, {0, 0, -1});  // the ball at z = 3
    REQUIRE(h);
    CHECK(h->t == Approx(7 - rho));
    // A blob cut from a box: a CSG leaf, no warning.
    const StagedScene d = build_staged("difference { box { -2, 2 } blob { threshold 0.5 sphere { <0, 2, 0>, 2, 2 } } }\n");
    CHECK(d.warnings.empty());
    only<DefaultCsg<double>>(d);
    h = shoot(d, {0, 5, 0}, {0, -1, 0});
    REQUIRE(h);
    CHECK(h->t == Approx(3 + 2 * std::sqrt(1 - std::sqrt(0.25))));  // the blob's hollow in the box's top
}

TEST_CASE("blob: POV-Ray's errors at their place, a component's texture reported", "[dsl][blob]") {
    CHECK_THAT(error_of("blob { threshold 0.5 }"), Contains("1:1: a blob needs at least one component"));
    CHECK_THAT(error_of("blob { threshold 0 sphere { 0, 1, 1 } }"),
               Contains("1:18: the threshold of the blob must be positive, found 0"));
    CHECK_THAT(error_of("blob { cylinder { <1,2,3>, <1,2,3>, 1, 1 } }"),
               Contains("1:28: degenerate cylindrical component in blob"));
    CHECK_THAT(error_of("blob { sphere { 0, 1, 1 open } }"), Contains("1:25: expected a component modifier"));
    CHECK_THAT(error_of("blob { sphere { 0, 1 } }"), Contains("the strength of the sphere component"));
    const StagedScene b =
        build_staged("blob { sphere { 0, 1, 2 pigment { rgb x } } sphere { x, 1, 2 texture { pigment { rgb y } } } }\n");
    CHECK(places(b.warnings, "approximated texture") == std::vector<std::string>{"3:25 blob"});
    CHECK_THAT(all_messages(b.warnings), Contains("a blob component's own `pigment` is ignored"));
    // Radius 0 adds nothing (POV-Ray divides by it): a warning, and the other component stays.
    const StagedScene z = build_staged("blob { sphere { 0, 0, 1 } sphere { 0, 1, 2 } }\n");
    CHECK_THAT(all_messages(z.warnings), Contains("a blob sphere component of radius 0 adds nothing"));
    CHECK(z.scene.objects().size() == 1);
}

TEST_CASE("blob: export-pov writes what reads back the same", "[dsl][blob][export]") {
    const std::string text = std::string(stage) + blob_declaration + "object { B pigment { rgb 1 } }\n";
    const std::string exported = dsl::export_pov(dsl::parse_string(text, "b.pov"));
    CHECK_THAT(exported, Contains("blob { threshold 0.5 sphere { <0, 0, 0>, 1, 1 } cylinder { <-1, 0, 0>, <1, 0, 0>, 0.5, 2 matrix <"));
    const std::string twice = dsl::export_pov(dsl::parse_string(exported, "exported.pov"));
    CHECK(twice.substr(twice.find('\n')) == exported.substr(exported.find('\n')));
}

TEST_CASE("examples/scenes/blobs.pov reads and builds with no warning, and exports back the same", "[dsl][blob][scenes]") {
    std::vector<dsl::Diagnostic> warnings;
    dsl::ParseOptions po;
    po.diagnostics = collect(warnings);
    dsl::BuildOptions bo;
    bo.diagnostics = collect(warnings);
    const auto desc = dsl::parse_file(std::string(PHOTON_SCENES_DIR) + "/blobs.pov", po);
    const auto built = dsl::build<float>(desc, bo);
    CHECK(all_messages(warnings).empty());
    int blobs = 0;
    for (const auto& o : built.scene.objects()) blobs += std::holds_alternative<Transformed<Blob<float>>>(o.shape);
    CHECK(blobs == 4);
    const std::string exported = dsl::export_pov(desc);
    const std::string twice = dsl::export_pov(dsl::parse_string(exported, "exported.pov"));
    CHECK(twice.substr(twice.find('\n')) == exported.substr(exported.find('\n')));
}
