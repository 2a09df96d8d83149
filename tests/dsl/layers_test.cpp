// SPDX-License-Identifier: MIT
// Layered textures in the scene language: read on objects, in declarations and in materials,
// moved with their object, built into the composite reflectance POV-Ray 3.7 shows (values worked
// out by hand), with warnings only where photon still approximates, and written back by export-pov.

#include <catch2/catch.hpp>

#include "dsl_test_util.hpp"

#include <filesystem>

using namespace dsl_test;
using Catch::Matchers::Contains;
using photon::Rgb;
using photon::Vec3;

namespace {

const char* const layer_stage = "#version 3.7;\ncamera { location <0, 0, -5> look_at 0 }\nlight_source { <0, 5, -5>, 1 }\n";

StagedScene build_layers(const std::string& text) { return build_staged(text, {}, layer_stage); }

void check_near(const Rgb<double>& got, double r, double g, double b) {
    CHECK(got.x == Approx(r).margin(1e-12));
    CHECK(got.y == Approx(g).margin(1e-12));
    CHECK(got.z == Approx(b).margin(1e-12));
}

std::size_t layer_warnings(const std::vector<dsl::Diagnostic>& ws) {
    std::size_t n = 0;
    for (const auto& w : ws) n += w.message.find("layer") != std::string::npos;
    return n;
}

}  // namespace

TEST_CASE("layered textures are read on objects, in declarations and in materials", "[dsl][layers]") {
    const Parsed p = parse(std::string(layer_stage) +
                           "#declare T = texture { pigment { rgb 1 } } texture { pigment { rgbt <1, 0, 0, 0.5> } }\n"
                           "sphere { 0, 1 texture { pigment { rgb 1 } } texture { pigment { rgbf <0, 1, 0, 1> } } "
                           "texture { T } translate x }\n"
                           "sphere { 0, 1 material { texture { pigment { rgb 1 } } texture { pigment { rgbt 0.5 } } } }\n");
    CHECK(p.warnings.empty());
    REQUIRE(p.desc.objects.size() == 3);
    const dsl::Texture& t = *p.desc.objects[1].texture;
    // The bottom, then the filtered green, then T's two layers on top of it.
    REQUIRE(t.layers.size() == 3);
    CHECK(t.layers[0].pigment.color.filter == 1);
    CHECK(t.layers[2].pigment.color.transmit == 0.5);
    // The object's translation moves every layer.
    for (const dsl::Texture& layer : t.layers) CHECK(layer.pigment.transform == dsl::Transform::translate({1, 0, 0}));
    CHECK(p.desc.objects[2].texture->layers.size() == 1);
}

TEST_CASE("a layered texture's reflectance is POV-Ray's composite of its layers", "[dsl][layers]") {
    // Bottom: rgb <0.8, 0.6, 0.4>, diffuse 0.5, ambient 0.2 -> own (0.4, 0.3, 0.2), glow (0.16, 0.12, 0.08).
    const StagedScene b = build_layers(
        "plane { y, 0 texture { pigment { rgb <0.8, 0.6, 0.4> } finish { diffuse 0.5 ambient 0.2 } }\n"
        "  texture { pigment { gradient x color_map { [0 rgbt <1, 1, 1, 1>] [1 rgb <0, 0, 1>] } } "
        "finish { diffuse 1 ambient 0 } } }\n"
        "plane { y, -1 texture { pigment { rgb <0.8, 0.6, 0.4> } finish { diffuse 0.5 ambient 0 } }\n"
        "  texture { pigment { rgbf <1, 0, 0, 0.5> } finish { diffuse 0.6 ambient 0 } } }\n");
    INFO(all_messages(b.warnings));
    CHECK(layer_warnings(b.warnings) == 0);  // pigment-only layers: photon does exactly what POV-Ray does
    const auto& gradient = b.scene.material_of(0);
    // At x = 0.25 the top is rgb <0.75, 0.75, 1> transmit 0.75: 0.25 of its own colour, 0.75 of the bottom.
    check_near(gradient.diffuse_at({0.25, 0, 3}), 0.1875 + 0.3, 0.1875 + 0.225, 0.25 + 0.15);
    check_near(gradient.diffuse_at({0.0, 0, 3}), 0.4, 0.3, 0.2);  // clear: the bottom alone
    // The glow weighs each layer by its own ambient: the top's is 0.
    check_near(gradient.ambient_at({0.25, 0, 3}), 0.75 * 0.16, 0.75 * 0.12, 0.75 * 0.08);
    // Filter passes the bottom through the top's colour: red only, halved.
    const auto& filtered = b.scene.material_of(1);
    check_near(filtered.diffuse_at({0.3, -1, 2}), 0.3 + 0.5 * 0.4, 0, 0);
    check_near(filtered.ambient_at({0.3, -1, 2}), 0, 0, 0);
    CHECK(filtered.params().transmission == Rgb<double>(0));
}

TEST_CASE("what photon approximates in a layered texture is reported, and nothing else", "[dsl][layers]") {
    const StagedScene b = build_layers(
        // 4: the bottom's bumps shown through a partly clear top (its highlight is exact)
        "sphere { 0, 1 texture { pigment { rgb 1 } finish { phong 1 } normal { bumps 0.5 scale 0.2 } }\n"
        "  texture { pigment { bozo color_map { [0.5 rgbt 1] [0.5 rgb x] } } } }\n"
        // 6: two reflecting layers
        "sphere { 0, 1 translate 3*x texture { pigment { rgb 0.5 } finish { reflection 0.2 } }\n"
        "  texture { pigment { rgbt 0.5 } finish { reflection 0.1 } } }\n"
        // 8: a top that is opaque everywhere hides the layers below, their finish and normal too
        "sphere { 0, 1 translate -3*x texture { pigment { rgb 1 } finish { phong 1 } normal { bumps 0.5 } }\n"
        "  texture { pigment { rgb <0, 0.5, 0> } finish { diffuse 0.8 ambient 0 } } }\n"
        // 10: a highlight on the top layer alone is exact
        "sphere { 0, 1 translate 6*x texture { pigment { rgb 0.5 } finish { ambient 0 } }\n"
        "  texture { pigment { rgbf <1, 1, 1, 0.9> } finish { phong 0.8 ambient 0 } } }\n"
        // 12: an upper layer's negative ambient (POV-Ray takes light away there)
        "sphere { 0, 1 translate 9*x texture { pigment { rgb 0.5 } } texture { pigment { rgbt 0.5 } finish { ambient -0.2 } } }\n");
    INFO(all_messages(b.warnings));
    CHECK(places(b.warnings, "approximated texture") ==
          std::vector<std::string>{"4:62 texture", "6:68 texture"});  // normal, the lower reflection
    CHECK(places(b.warnings, "approximated finish") == std::vector<std::string>{"12:101 ambient"});
    CHECK_THAT(all_messages(b.warnings), Contains("photon shades every layer with this layer's `normal`"));
    CHECK_THAT(all_messages(b.warnings), Contains("POV-Ray adds every layer's"));
    const auto& bumpy = b.scene.material_of(0);
    CHECK(bumpy.has_normal_field());
    CHECK(bumpy.params().phong == 1);
    // The bottom's highlight shows where the top is clear (rgbt 1) and not where it is red.
    int clear = 0, covered = 0;
    for (int i = 0; i < 200; ++i) {
        const Vec3<double> q(std::cos(0.1 * i), std::sin(0.37 * i), std::sin(0.1 * i) * std::cos(0.37 * i));
        const Rgb<double> w = bumpy.highlight_weight_at(q);
        CHECK(w.x == w.y);
        CHECK((w.x == 1.0 || w.x == 0.0));
        (w.x == 1.0 ? clear : covered)++;
    }
    CHECK((clear > 10 && covered > 10));
    CHECK(b.scene.material_of(1).params().specular == Rgb<double>(0.1));  // the topmost reflection
    const auto& hidden = b.scene.material_of(2);
    CHECK(!hidden.has_normal_field());
    CHECK(hidden.params().phong == 0);
    check_near(hidden.diffuse_at({-3, 1, 0}), 0, 0.4, 0);
    const auto& coated = b.scene.material_of(3);
    CHECK(coated.params().phong == Approx(0.8));
    // top: 0.1 of white at the default diffuse 0.6; 0.9 of the bottom's 0.5 * 0.6
    check_near(coated.diffuse_at({6, 1, 0}), 0.06 + 0.9 * 0.3, 0.06 + 0.9 * 0.3, 0.06 + 0.9 * 0.3);
}

TEST_CASE("layers that share a highlight each add it, dimmed by the layers above, as POV-Ray does", "[dsl][layers]") {
    // POV-Ray's woods: a #default finish gives every layer the same specular.
    const StagedScene b = build_layers(
        "#default { finish { specular 0.5 roughness 0.0025 } }\n"
        "sphere { 0, 1 texture { pigment { rgb <0.6, 0.4, 0.2> } }\n"
        "  texture { pigment { gradient x color_map { [0 rgbf <1, 0.5, 0.5, 0.6>] [1 rgbt <0.2, 0.2, 0.2, 0.3>] } } } }\n");
    INFO(all_messages(b.warnings));
    CHECK(places(b.warnings, "approximated texture").empty());
    const auto& m = b.scene.material_of(0);
    CHECK(m.params().blinn == Approx(0.5));
    for (double x : {0.0, 0.25, 0.5, 0.8}) {
        // the top's own highlight (1) plus the bottom's through the top: filter * colour + transmit
        const double filter = 0.6 * (1 - x), transmit = 0.3 * x;
        const Rgb<double> colour = (1 - x) * Rgb<double>(1, 0.5, 0.5) + x * Rgb<double>(0.2);
        const Rgb<double> expected = Rgb<double>(1.0) + filter * colour + Rgb<double>(transmit);
        check_near(m.highlight_weight_at({x, 0.3, 0.1}), expected.x, expected.y, expected.z);
    }
}

TEST_CASE("export-pov writes a layered texture's layers back", "[dsl][layers]") {
    const StagedScene a = build_layers(
        "plane { y, 0 texture { pigment { checker rgb 1, rgb <0, 0, 0.5> } finish { diffuse 0.7 } }\n"
        "  texture { pigment { gradient x color_map { [0 rgbt <1, 1, 1, 1>] [1 rgbf <0, 1, 0, 0.3>] } "
        "scale 2 } } translate 0.5*z }\n");
    const auto b = dsl::build<double>(dsl::parse_string(dsl::export_pov(a.desc), "exported.pov"));
    REQUIRE(b.scene.objects().size() == a.scene.objects().size());
    for (const Vec3<double>& p : {Vec3<double>(0.3, 0, 0.2), Vec3<double>(1.7, 0, 0.9), Vec3<double>(-2.6, 0, 3.1)}) {
        const Rgb<double> x = a.scene.material_of(0).diffuse_at(p), y = b.scene.material_of(0).diffuse_at(p);
        CHECK(glm::length(x - y) < 1e-9);
        CHECK(a.scene.material_of(0).ambient_at(p) == b.scene.material_of(0).ambient_at(p));
    }
}

TEST_CASE("examples/scenes/layers.pov builds without warnings and exports to the same reflectances", "[dsl][layers]") {
    std::vector<dsl::Diagnostic> warnings;
    dsl::ParseOptions po;
    po.diagnostics = collect(warnings);
    const auto desc = dsl::parse_file(std::filesystem::path(PHOTON_SCENES_DIR) / "layers.pov", po);
    dsl::BuildOptions bo;
    bo.diagnostics = collect(warnings);
    const auto a = dsl::build<double>(desc, bo);
    INFO(all_messages(warnings));
    CHECK(warnings.empty());
    std::size_t layered = 0;
    for (const auto& o : desc.objects) layered += o.texture && !o.texture->layers.empty();
    CHECK(layered == 6);
    const auto b = dsl::build<double>(dsl::parse_string(dsl::export_pov(desc), "exported.pov"));
    REQUIRE(b.scene.objects().size() == a.scene.objects().size());
    for (std::uint32_t i = 0; i < a.scene.objects().size(); ++i)
        for (const Vec3<double>& p : {Vec3<double>(-2.1, 0.9, -0.2), Vec3<double>(0.7, 0.3, -0.4), Vec3<double>(1.3, 0, -1.1)}) {
            INFO("object " << i);
            CHECK(glm::length(a.scene.material_of(i).diffuse_at(p) - b.scene.material_of(i).diffuse_at(p)) < 1e-9);
        }
}
