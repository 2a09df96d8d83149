// SPDX-License-Identifier: MIT
// What POV-Ray's sample scenes need and POV-Ray accepts: the animation identifiers of a frame
// (animation.hpp), light groups, empty unions, nested `object`s, looks_like by name, POV-Ray's
// optional commas, `.gray`, a stray `#`, weightless average maps, and values photon's physical
// materials and lights cannot take, replaced with a located warning (physical_ranges.hpp).

#include <catch2/catch.hpp>

#include "dsl_test_util.hpp"

using namespace dsl_test;
using Catch::Matchers::Contains;

namespace {

struct CorpusScene {
    dsl::SceneDescription desc;
    std::vector<dsl::Diagnostic> warnings;
    photon::dsl::BuiltScene<double> scene;
};

CorpusScene build_corpus(const std::string& text, dsl::ParseOptions po = {}) {
    std::vector<dsl::Diagnostic> w;
    po.diagnostics = collect(w);
    auto desc = dsl::parse_string(text, "test.pov", po);
    dsl::BuildOptions bo;
    bo.diagnostics = collect(w);
    auto scene = dsl::build<double>(desc, bo);
    return {std::move(desc), std::move(w), std::move(scene)};
}

/// The value of `expression` after the declarations in `prelude`.
double number(const std::string& expression, dsl::ParseOptions po = {}, const std::string& prelude = "") {
    const Parsed p = parse(prelude + "#declare R = " + expression + ";\nsphere { 0, R }", po);
    return std::get<dsl::SphereShape>(p.desc.objects.at(0).shape).radius;
}

}  // namespace

TEST_CASE("animation options give POV-Ray's identifiers for one frame", "[dsl][animation]") {
    using photon::dsl::AnimationRequest;
    using photon::dsl::animation_clock;
    SECTION("a still image: all 0, clock_on only with a clock") {
        const auto a = animation_clock({});
        CHECK(a.clock == 0);
        CHECK_FALSE(a.clock_on);
        CHECK(a.frame_number == 0);
        CHECK(a.initial_frame == 0);
        CHECK(a.final_frame == 0);
        CHECK(a.final_clock == 0);
        AnimationRequest r;
        r.clock = 0.25;
        const auto k = animation_clock(r);
        CHECK(k.clock == 0.25);
        CHECK(k.clock_on);
        CHECK(k.frame_number == 0);
    }
    SECTION("POV-Ray's still ranges 1:1 and 0:0") {
        AnimationRequest r;
        r.initial_frame = 1, r.final_frame = 1;
        CHECK(animation_clock(r).frame_number == 0);
        CHECK_FALSE(animation_clock(r).clock_on);
    }
    SECTION("the frames of a range") {
        AnimationRequest r;
        r.initial_frame = 1, r.final_frame = 5;
        r.initial_clock = 0, r.final_clock = 2;
        const auto first = animation_clock(r);
        CHECK(first.frame_number == 1);
        CHECK(first.clock == 0);
        CHECK(first.clock_delta == Approx(0.5));
        CHECK(first.initial_frame == 1);
        CHECK(first.final_frame == 5);
        CHECK(first.final_clock == 2);
        CHECK(first.clock_on);
        r.frame = 4;
        CHECK(animation_clock(r).clock == Approx(1.5));
        CHECK(animation_clock(r).frame_number == 4);
    }
    SECTION("a frame alone is the one frame of N:N") {
        AnimationRequest r;
        r.frame = 7;
        const auto a = animation_clock(r);
        CHECK(a.frame_number == 7);
        CHECK(a.initial_frame == 7);
        CHECK(a.final_frame == 7);
        CHECK(a.clock_delta == 0);
        CHECK(a.clock == 0);
    }
    SECTION("bad requests") {
        AnimationRequest r;
        r.initial_frame = 1, r.final_frame = 5, r.frame = 6;
        CHECK_THROWS_WITH(animation_clock(r), Contains("frame 6 is outside the frames 1 to 5"));
        r.frame = 2.5;
        CHECK_THROWS_WITH(animation_clock(r), Contains("must be a whole number"));
        r.frame.reset();
        r.clock = 1;
        CHECK_THROWS_WITH(animation_clock(r), Contains("not --clock"));
    }
    SECTION("the scene reads them") {
        dsl::ParseOptions po;
        AnimationRequest r;
        r.initial_frame = 1, r.final_frame = 3, r.frame = 2;
        po.animation = animation_clock(r);
        CHECK(number("frame_number", po) == 2);
        CHECK(number("clock + 1", po) == Approx(1.5));
        CHECK(number("clock_on + 1", po) == 2);
        const std::string scene = "#declare A = array[3] { 1, 2, 3 }\nsphere { 0, A[frame_number - 1] }";
        CHECK(error_of(scene) == "2:15: index -1 is out of the bounds of `A` (indices 0 to 2 in dimension 1, "
                                 "declared at 1:10)");
        const Parsed p = parse(scene, po);
        CHECK(std::get<dsl::SphereShape>(p.desc.objects.at(0).shape).radius == 2);
    }
}

TEST_CASE("light_group is read as a union of its lights and objects, with a warning", "[dsl][corpus]") {
    const CorpusScene b = build_corpus(std::string(stage) +
                               "light_group {\n"
                               "  light_source { <0, 9, 0>, rgb 1 }\n"
                               "  sphere { 0, 1 }\n"
                               "  global_lights on\n"
                               "  translate x\n"
                               "}\n");
    CHECK(places(b.warnings, "approximated light") == std::vector<std::string>{"3:1 light_group"});
    CHECK(b.scene.scene.lights().size() == 2);
    CHECK(b.scene.scene.objects().size() == 1);
    CHECK(error_of("light_group { sphere { 0, 1 } global_lights }") == "");
}

TEST_CASE("an empty union warns and adds nothing, as in POV-Ray", "[dsl][corpus]") {
    const CorpusScene b = build_corpus(std::string(stage) + "union { }\nsphere { 0, 1 }\n");
    CHECK_THAT(all_messages(b.warnings), Contains("`union` without objects adds nothing to the scene"));
    CHECK(b.scene.scene.objects().size() == 1);
    const Parsed p = parse("#declare U = union { #if (0) sphere { 0, 1 } #end }\nobject { U } sphere { 0, 1 }");
    CHECK(p.desc.objects.size() == 2);
}

TEST_CASE("object { object { ... } } and looks_like { IDENTIFIER }", "[dsl][corpus]") {
    const Parsed p = parse("object { object { sphere { 0, 2 } translate x } translate y }");
    REQUIRE(p.desc.objects.size() == 1);
    CHECK(std::get<dsl::SphereShape>(p.desc.objects[0].shape).radius == 2);
    CHECK(p.desc.objects[0].transform.point(dsl::Vector3(0.0)) == dsl::Vector3(1, 1, 0));
    const Parsed l = parse("#declare Bulb = sphere { 0, 0.1 }\n"
                           "light_source { 0, 1 looks_like { Bulb pigment { rgb 1 } } }\n"
                           "sphere { 0, 1 }");
    const auto& light = std::get<dsl::LightSource>(l.desc.objects.at(0).shape);
    CHECK(light.looks_like);
    CHECK(error_of("#declare V = 1;\nlight_source { 0, 1 looks_like { V } }") ==
          "2:34: expected an object or an object identifier in `looks_like`, found `V`");
}

TEST_CASE("POV-Ray's optional commas: between macro arguments, after a vector's components", "[dsl][corpus]") {
    // An argument ends where its value does: a string, a block, or a sum (`5 -3` is one sum).
    const std::string macro = "#macro Sub(A, B) (A - B) #end\n#macro Len(S, V) (strlen(S) + V.y) #end\n";
    CHECK(number("Len(\"abc\" <0, 2, 0>)", {}, macro) == 5);
    CHECK(number("Sub(5, 3)", {}, macro) == 2);
    CHECK_THAT(error_of(macro + "sphere { 0, Sub(5 -3) }"), Contains("expected `,` and argument 2 (`B`)"));
    const Parsed objects = parse("#macro Place(O, V) object { O translate V } #end\n"
                                 "Place(sphere { 0, 1 } -y)");
    REQUIRE(objects.desc.objects.size() == 1);
    CHECK(objects.desc.objects[0].transform.point(dsl::Vector3(0.0)) == dsl::Vector3(0, -1, 0));
    CHECK(number("vlength(<0, 3, 4,>)") == 5);
    CHECK(number("vlength(<3, 4,>)") == 5);
    CHECK(error_of("#macro Sub(A, B) (A - B) #end\nsphere { 0, Sub(5) }") != "");
}

TEST_CASE("`.gray` is POV-Ray's grey value of a colour", "[dsl][corpus]") {
    CHECK(number("(rgb <1, 0, 0>).gray") == Approx(0.297));
    CHECK(number("(rgb <0.5, 1, 1>).grey") == Approx(0.297 * 0.5 + 0.589 + 0.114));
    CHECK(error_of("sphere { 0, (1).gray }") == "1:16: expected a vector or colour before `.gray`, found the number 1");
}

TEST_CASE("a `#` before no directive name is ignored with a warning, as POV-Ray reads on", "[dsl][corpus]") {
    const Parsed p = parse("camera { location -5 look_at <0, 2, 0>#\n}\nsphere { 0, 1 }");
    CHECK(p.desc.objects.size() == 1);
    REQUIRE(p.warnings.size() == 1);
    CHECK(p.warnings[0].location.line == 1);
    CHECK(p.warnings[0].location.column == 39);
    CHECK_THAT(p.warnings[0].message, Contains("`#` without a directive name"));
    CHECK(parse("sphere { 0, 1 } #").desc.objects.size() == 1);
}

TEST_CASE("average maps take entries without weights, density_file takes interpolate, mesh triangles uv_vectors",
          "[dsl][corpus]") {
    const CorpusScene b = build_corpus(std::string(stage) +
                               "sphere { 0, 1 texture { average texture_map {\n"
                               "  [pigment { rgb <1, 0, 0> } finish { phong 1 }]\n"
                               "  [pigment { rgb <0, 0, 1> }]\n"
                               "} } }\n");
    const auto m = b.scene.scene.material_of(0).params();
    CHECK(m.diffuse.x == Approx(m.diffuse.z));  // both entries weigh 1
    CHECK(m.diffuse.x > 0);
    CHECK(error_of("sphere { 0, 1 pigment { density_file df3 \"a.df3\" interpolate 1 color_map { [0 rgb 0] [1 rgb 1] } } }") == "");
    CHECK(error_of("sphere { 0, 1 pigment { density_file df3 \"a.df3\" interpolate 3 } }") != "");
    const Parsed mesh = parse("mesh { smooth_triangle { 0, y, x, y, z, y uv_vectors <0, 0>, <1, 0>, <0, 1> } }");
    CHECK(places(mesh.warnings, "ignored effect").size() == 2);  // smooth normals, uv_vectors
}

TEST_CASE("values POV-Ray takes and photon cannot render are replaced, with a located warning", "[dsl][corpus]") {
    SECTION("transmit 100: filter and transmit scaled to a sum of 1") {
        const CorpusScene b = build_corpus(std::string(stage) + "sphere { 0, 1\n  pigment { rgb 0.5 transmit 100 } }\n");
        CHECK(places(b.warnings, "approximated pigment") == std::vector<std::string>{"4:3 pigment"});
        CHECK_THAT(all_messages(b.warnings), Contains("uses filter 0 and transmit 1"));
        const auto m = b.scene.scene.material_of(0).params();
        CHECK(m.transmission.x == Approx(1));
        CHECK(m.diffuse.x == Approx(0).margin(1e-12));
    }
    SECTION("a negative pigment colour is read as 0 in those channels") {
        const CorpusScene b = build_corpus(std::string(stage) + "sphere { 0, 1 pigment { rgb <-0.5, 0.5, 0.25> } }\n");
        CHECK_THAT(all_messages(b.warnings), Contains("negative colour rgb <-0.5, 0.5, 0.25>"));
        const auto m = b.scene.scene.material_of(0).params();
        CHECK(m.diffuse.x == 0);
        CHECK(m.diffuse.y > 0);
    }
    SECTION("a negative light is left out, a partly negative one loses its negative channels") {
        const CorpusScene b = build_corpus(std::string(stage) +
                                   "light_source { 0, rgb -0.9 }\nlight_source { y, rgb <1, -1, 1> }\n"
                                   "sphere { 0, 1 }\n");
        CHECK(places(b.warnings, "approximated light") ==
              std::vector<std::string>{"3:1 light_source", "4:1 light_source"});
        REQUIRE(b.scene.scene.lights().size() == 2);  // the stage's and the partly negative one
        const auto& l = std::get<photon::PointLight<double>>(b.scene.scene.lights()[1]);
        CHECK(l.power.y == 0);
        CHECK(l.power.x > 0);
    }
    SECTION("phong_size 0 with a highlight becomes 1; without one it changes nothing") {
        const CorpusScene b = build_corpus(std::string(stage) + "sphere { 0, 1 finish { phong 1 phong_size 0 } }\n");
        CHECK_THAT(places(b.warnings, "approximated finish"), Catch::Matchers::VectorContains(std::string("3:32 phong_size")));
        CHECK(b.scene.scene.material_of(0).params().phong_exponent == 1);
        const CorpusScene quiet = build_corpus(std::string(stage) + "sphere { 0, 1 finish { phong 0 phong_size 0 } }\n");
        CHECK_THAT(all_messages(quiet.warnings), !Contains("phong_size"));
    }
}
