// SPDX-License-Identifier: MIT
// Graceful degradation: what photon reads but cannot render (objects it has no shape for,
// patterns, effects, camera and light types) is a warning at its place, of a kind, that says
// what photon does instead, and the rest of the scene is built; syntax errors inside stay errors.

#include <catch2/catch.hpp>

#include "dsl_test_util.hpp"

using namespace dsl_test;
using Catch::Matchers::Contains;

namespace {

const char* const lit = "camera { location <0, 0, -5> look_at 0 }\nlight_source { <0, 5, -5>, 1 }\n";

/// Parse and build, warnings of both steps collected.
struct Built {
    dsl::SceneDescription desc;
    std::vector<dsl::Diagnostic> warnings;
    std::size_t objects = 0, lights = 0;
};
Built build_text(const std::string& text) {
    Built b;
    dsl::ParseOptions po;
    po.diagnostics = collect(b.warnings);
    b.desc = dsl::parse_string(text, "test.pov", po);
    dsl::BuildOptions bo;
    bo.diagnostics = collect(b.warnings);
    const auto built = dsl::build<float>(b.desc, bo);
    b.objects = built.scene.objects().size();
    b.lights = built.scene.lights().size();
    return b;
}

/// The colour of the first object's pigment.
dsl::Vector3 first_color(const std::string& pigment_or_texture) {
    const Parsed p = parse(std::string(lit) + "sphere { 0, 1 " + pigment_or_texture + " }");
    const dsl::Object& o = p.desc.objects.at(1);
    REQUIRE(o.texture.has_value());
    return o.texture->pigment.color.rgb;
}

void check_rgb(const dsl::Vector3& c, double r, double g, double b) {
    CHECK(c.x == Approx(r).margin(1e-12));
    CHECK(c.y == Approx(g).margin(1e-12));
    CHECK(c.z == Approx(b).margin(1e-12));
}

}  // namespace

TEST_CASE("objects photon has no shape for are skipped with a warning at their place", "[dsl][degradation]") {
    const Built b = build_text(std::string(lit) +
                               "ovus { 1, 0.5 pigment { rgb 1 } }\n"
                               "cylinder { 0, y, 1 open }\n"
                               "sphere_sweep { linear_spline 2, <0, 0, 0>, 1, <1, 0, 0>, 1 }\n"
                               "difference { box { -1, 1 } sphere { 0, 1.2 } }\n"
                               "bicubic_patch { type 0 <0,0,0>,<1,0,0>,<2,0,0>,<3,0,0>, <0,1,0>,<1,1,0>,<2,1,0>,<3,1,0>, <0,2,0>,<1,2,0>,<2,2,0>,<3,2,0>, <0,3,0>,<1,3,0>,<2,3,0>,<3,3,0> }\n"
                               "sphere { 0, 1 }\n"
                               "union { sphere { 0, 1 } julia_fractal { <0.4, 0.2, 0.3, -0.2> } }\n");
    CHECK(places(b.warnings, "skipped object") ==
          std::vector<std::string>{"3:1 ovus", "5:1 sphere_sweep", "7:1 bicubic_patch", "9:25 julia_fractal"});
    CHECK_THAT(all_messages(b.warnings), Contains("`ovus` is skipped: photon has no ovus yet"));
    CHECK(b.objects == 4);  // the cylinder, the difference, the sphere and the union's sphere
    CHECK(b.lights == 1);
    REQUIRE(b.desc.objects.size() == 8);  // the light and seven objects
    CHECK(std::holds_alternative<dsl::SkippedShape>(b.desc.objects[1].shape));
    CHECK(std::holds_alternative<dsl::CylinderShape>(b.desc.objects[2].shape));
    CHECK(std::string(dsl::keyword(b.desc.objects[4].shape)) == "difference");
    CHECK(std::string(dsl::keyword(b.desc.objects[2].shape)) == "cylinder");
}

TEST_CASE("a skipped object is read with its syntax: errors inside are errors", "[dsl][degradation]") {
    CHECK_THAT(error_of("difference { }"), Contains("1:14: expected an object in `difference`"));
    CHECK_THAT(error_of("difference { box { 0, 1 } pigment { rgb 1 } blah }"), Contains("1:45: expected an object modifier"));
    CHECK_THAT(error_of("lemon { 0, 1, 1, 0.5, 2\n"), Contains("expected `}` to close `lemon`"));
    CHECK_THAT(error_of("intersection { sphere { 0, -1 } box { 0, 1 } }"), Contains("sphere radius must be positive"));
}

TEST_CASE("directives inside a skipped block still run", "[dsl][degradation]") {
    const Parsed p = parse(std::string(lit) + "isosurface { #declare R = 2; function { x } }\nsphere { 0, R }\n");
    CHECK(std::get<dsl::SphereShape>(p.desc.objects.back().shape).radius == 2);
}

TEST_CASE("a declared skipped object warns again where it is used", "[dsl][degradation]") {
    const Built b = build_text(std::string(lit) +
                               "#declare Post = lemon { <0, 0, 0>, <0, 1, 0>, 1, 2, 3 }\n"
                               "object { Post translate x }\n"
                               "union { object { Post } sphere { 0, 1 } }\n");
    CHECK(places(b.warnings, "skipped object") ==
          std::vector<std::string>{"3:17 lemon", "4:10 lemon", "5:18 lemon"});
    CHECK_THAT(all_messages(b.warnings),
               Contains("`Post` is a `lemon` (declared at 3:10): skipped, photon has no lemon yet"));
    CHECK(b.objects == 1);
}

TEST_CASE("a scene whose every object was skipped says that nothing renders", "[dsl][degradation]") {
    const Built b = build_text(std::string(lit) + "ovus { 1, 0.5 }\nlemon { <0, 0, 0>, <0, 1, 0>, 1, 2, 3 }\n");
    CHECK(b.objects == 0);
    CHECK(places(b.warnings, "nothing renders") == std::vector<std::string>{"1:1 "});
    CHECK_THAT(all_messages(b.warnings),
               Contains("nothing renders: photon skipped every object of the scene (2 objects it has no shape for)"));
}

TEST_CASE("listed patterns are approximated by the mean of their colours", "[dsl][degradation]") {
    // checker is evaluated (pigment_pattern_test.cpp); its average colour is still recorded.
    check_rgb(first_color("pigment { checker rgb 1, rgb 0 }"), 0.5, 0.5, 0.5);
    check_rgb(first_color("pigment { checker color rgb <1, 0, 0> color rgb <0, 0, 1> scale 0.5 }"), 0.5, 0, 0.5);
    check_rgb(first_color("pigment { checker }"), 0, 0.5, 0.5);  // POV-Ray's blue and green
    check_rgb(first_color("pigment { checker pigment { rgb 1 } pigment { checker rgb 1, rgb 0 } }"), 0.75, 0.75, 0.75);
    check_rgb(first_color("pigment { square rgb <1, 0, 0>, rgb <0, 1, 0>, rgb <0, 0, 1>, rgb 1 }"), 0.5, 0.5, 0.5);
    // Mortar 0.5 between bricks of 8 x 3 x 4.5: the bricks are 7.5 * 2.5 * 4 / 108 of the volume.
    const double brick = 7.5 * 2.5 * 4 / 108;
    check_rgb(first_color("pigment { brick rgb 1, rgb 0 }"), 1 - brick, 1 - brick, 1 - brick);
    check_rgb(first_color("pigment { brick rgb 0, rgb 1 brick_size <1, 1, 1> mortar 0.5 }"), 0.125, 0.125, 0.125);
    const Parsed p = parse(std::string(lit) +
                           "plane { y, 0 pigment { square rgb 1, rgb 0, rgb 0.5, rgb 0.5 } }\n"
                           "plane { y, 0 pigment { checker rgb 1, rgb 0 } }\n"
                           "plane { y, 0 pigment { checker pigment { rgb 1 } pigment { bozo } } }\n");
    CHECK(places(p.warnings, "approximated pigment") == std::vector<std::string>{"3:24 square", "5:24 checker"});
    CHECK_THAT(all_messages(p.warnings),
               Contains("`square` is approximated by the mean of its 4 colours, rgb <0.5, 0.5, 0.5>: photon does not "
                        "evaluate this pattern"));
    CHECK_THAT(all_messages(p.warnings), Contains("its entries are patterned pigments, which photon does not nest"));
}

TEST_CASE("mapped patterns are approximated by their colour map's average over [0, 1]", "[dsl][degradation]") {
    check_rgb(first_color("pigment { gradient y color_map { [0 rgb 0] [1 rgb 1] } }"), 0.5, 0.5, 0.5);
    // A step: red below 0.25, blue above.
    check_rgb(first_color("pigment { marble colour_map { [0.25 color rgb x] [0.25 color rgb z] } turbulence 0.5 }"),
              0.25, 0, 0.75);
    // Linear from 0 at 0 to 1 at 2: over [0, 1] the mean of x / 2 is 1/4.
    check_rgb(first_color("pigment { wood color_map { [0 rgb 0] [2 rgb 1] } }"), 0.25, 0.25, 0.25);
    // POV-Ray's old form [v1, v2 colour1 colour2], and constant colour below the first entry.
    check_rgb(first_color("pigment { bozo color_map { [0.5, 1 color rgb 1 color rgb 0] } }"), 0.75, 0.75, 0.75);
    // Without a colour map: POV-Ray's default for bozo (white to 0.4, then green, blue and red).
    check_rgb(first_color("pigment { bozo }"), 0.6, 0.6, 0.6);
    check_rgb(first_color("pigment { granite }"), 0.5, 0.5, 0.5);  // black to white
    // Wave modifiers and pattern arguments parse.
    check_rgb(first_color("pigment { spiral1 5 sine_wave frequency 2 phase 0.5 octaves 4 omega 0.5 lambda 2 "
                          "turbulence <0.1, 0.2, 0.3> warp { turbulence 0.5 } poly_wave 2 noise_generator 2 "
                          "color_map { [0 rgb 1] [1 rgb 1] } }"),
              1, 1, 1);
    check_rgb(first_color("pigment { crackle form <1, -1, 0> metric 2 offset 0.1 solid "
                          "color_map { [0 rgb 1] [1 rgb 1] } }"),
              1, 1, 1);
}

TEST_CASE("declared maps, pigment_map, average and image_map", "[dsl][degradation]") {
    check_rgb(first_color("pigment { average pigment_map { [1 rgb x] [3 rgb z] } }"), 0.25, 0, 0.75);
    check_rgb(first_color("pigment { gradient x pigment_map { [0 rgb 0] [1 checker rgb 1, rgb 1] } }"), 0.5, 0.5,
              0.5);
    // A sandbox reads no files: the image is recorded as named, not looked for.
    dsl::ParseOptions sandbox;
    sandbox.read_include = [](const std::string&) { return std::optional<std::string>{}; };
    const Parsed p = parse(std::string(lit) +
                           "#declare M = color_map { [0 rgb 0] [1 rgb <1, 0, 0>] }\n"
                           "#declare PM = pigment_map { [0 rgb 1] [1 rgb 1] }\n"
                           "#declare N = normal_map { [0 bumps 0.5] [1 dents 0.2 scale 2] }\n"
                           "sphere { 0, 1 pigment { onion color_map { M } } }\n"
                           "sphere { 0, 1 pigment { leopard pigment_map { PM } } normal { bumps normal_map { N } } }\n"
                           "sphere { 0, 1 pigment { image_map { png \"wall.png\" map_type 1 once } turbulence 0.5 } }\n",
                           sandbox);
    REQUIRE(p.desc.objects.size() == 4);
    check_rgb(p.desc.objects[1].texture->pigment.color.rgb, 0.5, 0, 0);
    check_rgb(p.desc.objects[2].texture->pigment.color.rgb, 1, 1, 1);
    check_rgb(p.desc.objects[3].texture->pigment.color.rgb, 0.5, 0.5, 0.5);
    // onion and leopard (whose pigment_map entries are plain colours) are evaluated.
    CHECK(places(p.warnings, "approximated pigment") == std::vector<std::string>{"8:25 image_map"});
    CHECK(p.desc.objects[1].texture->pigment.pattern != nullptr);
    CHECK(p.desc.objects[2].texture->pigment.pattern != nullptr);
    CHECK_THAT(all_messages(p.warnings), Contains("`image_map` is approximated by mid grey") && Contains("turbulence"));
    CHECK_THAT(error_of("#declare M = color_map { [0 rgb 1] }\nsphere { 0, 1 pigment { bozo pigment_map { M } } }"),
               Contains("2:44: expected a pigment_map identifier, found `M` (a color_map, declared at 1:10)"));
}

TEST_CASE("patterned textures become one texture, layered ones keep their layers", "[dsl][degradation]") {
    const Parsed p = parse(std::string(lit) +
                           "sphere { 0, 1 texture { pigment { rgb 1 } finish { phong 1 } } "
                           "texture { pigment { rgbt <0, 0, 0, 0.8> } } }\n"
                           "sphere { 0, 1 texture { checker texture { pigment { rgb x } finish { phong 0.5 } } "
                           "texture { pigment { rgb z } } } }\n"
                           "sphere { 0, 1 texture { gradient y texture_map { [0 pigment { rgb 0 } finish { diffuse 0.3 }] "
                           "[1 pigment { rgb 1 }] } } }\n"
                           "sphere { 0, 1 texture { tiles { pigment { rgb 1 } tile2 pigment { rgb 0 } } } }\n"
                           "sphere { 0, 1 texture { material_map { png \"m.png\" once texture { pigment { rgb 1 } } "
                           "texture { pigment { rgb 0 } } } } }\n"
                           "sphere { 0, 1 texture { pigment { rgb 1 } normal { bumps 0.5 scale 0.1 } uv_mapping } }\n");
    REQUIRE(p.desc.objects.size() == 7);
    check_rgb(p.desc.objects[1].texture->pigment.color.rgb, 1, 1, 1);  // the first (bottom) layer
    CHECK(p.desc.objects[1].texture->finish.phong == 1);
    REQUIRE(p.desc.objects[1].texture->layers.size() == 1);  // built as POV-Ray composes them (layers_test.cpp)
    CHECK(p.desc.objects[1].texture->layers[0].pigment.color.transmit == 0.8);
    check_rgb(p.desc.objects[2].texture->pigment.color.rgb, 0.5, 0, 0.5);
    CHECK(p.desc.objects[2].texture->finish.phong == 0.5);
    check_rgb(p.desc.objects[3].texture->pigment.color.rgb, 0.5, 0.5, 0.5);
    CHECK(p.desc.objects[3].texture->finish.diffuse == 0.3);
    check_rgb(p.desc.objects[4].texture->pigment.color.rgb, 0.5, 0.5, 0.5);
    check_rgb(p.desc.objects[5].texture->pigment.color.rgb, 0.5, 0.5, 0.5);
    CHECK(places(p.warnings, "approximated texture") ==
          std::vector<std::string>{"4:25 checker", "5:25 gradient", "6:25 tiles", "7:25 material_map"});
    CHECK(places(p.warnings, "ignored effect").empty());  // photon renders the bumps
}

TEST_CASE("effects photon does not render are ignored with a warning", "[dsl][degradation]") {
    const Built b = build_text(std::string(lit) +
                               "fog { distance 10 color rgb 0.5 fog_type 2 up y }\n"
                               "rainbow { angle 42.5 width 5 distance 1e3 direction -z "
                               "color_map { [0 rgbt 1] [1 rgbt 1] } }\n"
                               "sky_sphere { pigment { gradient y color_map { [0 rgb 1] [1 rgb z] } } }\n"
                               "background { rgb 1 }\n"
                               "media { scattering { 1, 0.1 } }\n"
                               "#declare F = rainbow { distance 5 }\n"
                               "rainbow { F }\n"
                               "background { rgb 1 }\n"
                               "sphere { 0, 1 interior { ior 1.5 media { absorption 1 } } "
                               "finish { subsurface { translucency 0.5 } } bounded_by { box { -1, 1 } } "
                               "clipped_by { plane { y, 0 } } }\n"
                               "global_settings { subsurface { samples 10, 10 } }\n");
    CHECK(places(b.warnings, "ignored effect") ==
          std::vector<std::string>{"4:1 rainbow", "9:1 rainbow", "11:68 subsurface", "12:19 subsurface"});
    CHECK(all_messages(b.warnings).find("sky_sphere") == std::string::npos);  // the sky is rendered
    CHECK(all_messages(b.warnings).find("background") == std::string::npos);
    CHECK(all_messages(b.warnings).find("fog") == std::string::npos);  // the fog is rendered (fog_test.cpp)
    CHECK(all_messages(b.warnings).find("media") == std::string::npos);  // and the media (media_test.cpp)
    CHECK_THAT(all_messages(b.warnings), Contains("`rainbow` is ignored: photon renders no rainbow"));
    // A sphere's bound POV-Ray removes itself, and the clip is rendered (csg_test.cpp).
    CHECK(b.objects == 1);
}

TEST_CASE("camera types and lights photon lacks are approximated", "[dsl][degradation]") {
    const Built b = build_text(
        "camera { mesh_camera { 1 0 mesh { triangle { 0, x, y } } } location <0, 0, -5> look_at 0 }\n"
        "light_source { <0, 5, -5>, 1 parallel point_at 0 }\n"
        "light_source { <0, 5, -5>, 1 cylinder radius 2 falloff 3 point_at 0 }\n"
        "light_source { <0, 5, -5>, 1 projected_through { sphere { 0, 1 } } }\n"
        "sphere { 0, 1 }\n");
    CHECK(places(b.warnings, "approximated camera") == std::vector<std::string>{"1:10 mesh_camera"});
    CHECK(places(b.warnings, "approximated light") == std::vector<std::string>{"3:30 cylinder"});  // parallel is exact
    CHECK(places(b.warnings, "ignored effect") == std::vector<std::string>{"4:30 projected_through"});
    CHECK(b.lights == 3);
    CHECK(std::get<dsl::LightSource>(b.desc.objects[0].shape).parallel);
    CHECK_FALSE(std::get<dsl::LightSource>(b.desc.objects[1].shape).spotlight.has_value());  // the cylinder light
    // POV-Ray's other camera types, its focal blur and its orthographic bare `angle` are exact: no warning.
    for (const char* type : {"orthographic", "fisheye angle 360", "ultra_wide_angle angle 200", "omnimax", "panoramic",
                             "cylinder 1", "cylinder 4 angle 120", "spherical angle 180, 90", "orthographic angle",
                             "aperture 0.5 blur_samples 7, 20 focal_point <0, 0, 1> confidence 0.9 variance 0.001"}) {
        const Built t = build_text(std::string("camera { ") + type + " location <0, 0, -5> look_at 0 }\n"
                                   "light_source { <0, 5, -5>, 1 }\nsphere { 0, 1 }\n");
        INFO(type << ": " << all_messages(t.warnings));
        CHECK(t.warnings.empty());
    }
    const Parsed ray_normal = parse("camera { normal { bumps 0.5 } }\nlight_source { 0, 1 }\nsphere { z, 1 }\n");
    CHECK(places(ray_normal.warnings, "ignored effect") == std::vector<std::string>{"1:10 normal"});
    CHECK_THAT(error_of("camera { angle 180 }\nsphere { 0, 1 }"), Contains("camera `angle` must be below 180 degrees"));
    CHECK_THAT(error_of("camera { orthographic angle 200 }\nsphere { 0, 1 }"), Contains("must be below 180"));
    CHECK_THAT(error_of("camera { fisheye angle -1 }\nsphere { 0, 1 }"), Contains("must not be negative"));
    CHECK_THAT(error_of("camera { cylinder 5 }\nsphere { 0, 1 }"), Contains("cylinder camera"));
}

TEST_CASE("every form of normal parses, and those photon cannot evaluate are ignored", "[dsl][degradation]") {
    dsl::ParseOptions sandbox;  // reads no files: the bump map's image is recorded as named
    sandbox.read_include = [](const std::string&) { return std::optional<std::string>{}; };
    const Parsed p = parse(std::string(lit) +
                           "#declare N = normal { wrinkles 0.3 scale 0.2 }\n"
                           "sphere { 0, 1 normal { N } }\n"
                           "sphere { 0, 1 normal { bump_map { png \"b.png\" bump_size 2 } } }\n"
                           "sphere { 0, 1 normal { gradient x normal_map { [0 bumps 1] [1 granite 0.2] } } }\n"
                           "sphere { 0, 1 normal { facets coords 0.5 slope_map { [0 <0, 1>] } } }\n",
                           sandbox);
    INFO(all_messages(p.warnings));
    CHECK(places(p.warnings, "ignored effect") ==
          std::vector<std::string>{"6:24 normal", "7:24 normal"});  // normal_map, facets
    CHECK(p.desc.objects.size() == 5);
    REQUIRE(p.desc.objects[2].texture->normal);
    CHECK(p.desc.objects[2].texture->normal->pattern->name == "bump_map");  // read, built with its image
    CHECK(p.desc.objects[2].texture->normal->amount == 2);
    REQUIRE(p.desc.objects[1].texture->normal);
    CHECK(p.desc.objects[1].texture->normal->pattern->name == "wrinkles");
    CHECK(p.desc.objects[1].texture->normal->amount == 0.3);
}

TEST_CASE("photon's own warnings about what it renders differently carry a kind", "[dsl][degradation]") {
    // Every warning of these constructs has its kind and keyword for the summary of `photon check`.
    const Parsed b = parse(std::string(lit) +
                           "rainbow { distance 1 } ovus { 1, 0.5 } sphere { 0, 1 pigment { tiling 1 } "
                           "normal { facets 1 } }\n");
    INFO(all_messages(b.warnings));
    REQUIRE(b.warnings.size() == 4);
    for (const auto& w : b.warnings) {
        INFO(w.message);
        CHECK_FALSE(w.kind.empty());
        CHECK_FALSE(w.keyword.empty());
    }
}

TEST_CASE("mesh2 is read into a mesh: its normals and per-face textures are left out", "[dsl][degradation]") {
    const Built b = build_text(std::string(lit) +
                               "mesh2 {\n"
                               "  vertex_vectors { 4, <0, 0, 0>, <1, 0, 0>, <1, 1, 0>, <0, 1, 0> }\n"
                               "  normal_vectors { 1, <0, 0, -1> }\n"
                               "  texture_list { 2, texture { pigment { rgb x } } texture { pigment { rgb y } } }\n"
                               "  face_indices { 2, <0, 1, 2>, 0, <0, 2, 3>, 1 }\n"
                               "  normal_indices { 2, <0, 0, 0>, <0, 0, 0> }\n"
                               "  pigment { rgb 1 }\n"
                               "}\n");
    REQUIRE(b.desc.objects.size() == 2);
    INFO(dsl::keyword(b.desc.objects[1].shape));
    REQUIRE(std::holds_alternative<dsl::MeshShape>(b.desc.objects[1].shape));
    const auto& mesh = std::get<dsl::MeshShape>(b.desc.objects[1].shape);
    REQUIRE(mesh.triangles->size() == 2);
    CHECK((*mesh.triangles)[1][2] == dsl::Vector3(0, 1, 0));
    CHECK(b.objects == 1);  // one triangle mesh
    CHECK(places(b.warnings, "ignored effect") == std::vector<std::string>{"5:3 normal_vectors"});
    CHECK(places(b.warnings, "approximated texture") == std::vector<std::string>{"6:3 texture_list"});
    CHECK_THAT(error_of("mesh2 { vertex_vectors { 2, 0, x } face_indices { 1, <0, 1, 2> } }"),
               Contains("1:54: vertex index 2 of face 0 is not one of the 2 vertices"));
    CHECK_THAT(error_of("mesh2 { vertex_vectors { 3, 0, x } face_indices { 1, <0, 1, 2> } }"),
               Contains("expected vertex 2 of the mesh2"));
}

TEST_CASE("forms the sample scenes use: a spotlight's negative radius, a mesh2 count without comma, fractals",
          "[dsl][degradation]") {
    // POV-Ray keeps cos(angle): radius -90 is radius 90 (its radiosity/cornell.pov).
    const Parsed p = parse("light_source { 0, 1 spotlight radius -90 falloff 270 point_at y }\nsphere { 0, 1 }\n");
    const auto& spot = *std::get<dsl::LightSource>(p.desc.objects[0].shape).spotlight;
    CHECK(spot.radius == Approx(90));
    CHECK(spot.falloff == Approx(90));
    const Parsed m = parse(std::string(lit) + "mesh2 { vertex_vectors { 3\n <0, 0, 0>, <1, 0, 0>, <0, 1, 0>, }\n"
                                              "face_indices { 1\n <0, 1, 2> } }\n");
    CHECK(std::get<dsl::MeshShape>(m.desc.objects[1].shape).triangles->size() == 1);
    check_rgb(first_color("pigment { magnet 1 mandel 50 color_map { [0 rgb 1] [1 rgb 0] } interior 1, 200 "
                          "exterior 5, 1 }"),
              0.5, 0.5, 0.5);
    CHECK_THAT(error_of("sphere { 0, 1 pigment { rgb 1 interior 1, 2 } }"), Contains("found `interior`"));
}

TEST_CASE("warnings about finish items and modifiers photon ignores carry a kind too", "[dsl][degradation]") {
    const Built b = build_text(std::string(lit) +
                               "sphere { 0, 1 finish { ambient 0.2 diffuse 0.6, 0.3 crand 0.1 } no_image }\n"
                               "merge { sphere { 0, 1 } sphere { x, 1 } finish { ambient 0 } }\n"
                               "mesh { smooth_triangle { 0, y, x, y, y, y } finish { ambient 0 } }\n");
    CHECK(places(b.warnings, "approximated finish") ==
          std::vector<std::string>{"3:36 diffuse", "3:53 crand"});
    CHECK(places(b.warnings, "ignored effect") == std::vector<std::string>{"3:65 no_image", "5:8 smooth_triangle"});
    CHECK(places(b.warnings, "approximated object").empty());  // a merge is a merge
}
