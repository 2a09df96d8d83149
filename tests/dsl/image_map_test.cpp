// SPDX-License-Identifier: MIT
// image_map in the scene language: the block in POV-Ray 3.7's syntax, built into the library's
// ImageMap through the reader the program gives (here one that makes the pixels in memory), its
// colours as the material's reflectance, located errors for a missing file, an absent reader and
// a bad option, and export_pov writing it back.

#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <optional>
#include <string>
#include <unistd.h>

#include <photon/dsl/dsl.hpp>
#include <photon/dsl/export_pov.hpp>

#include "dsl_test_util.hpp"

using namespace photon;
using namespace dsl_test;

namespace {

/// A file the parser can find (its bytes are never read: the reader below makes the pixels), in
/// the current folder: a scene read from a string may read there (file_access.hpp).
struct ImageStandIn {
    std::filesystem::path path = std::filesystem::current_path() /
                                 ("photon-image-map-test-" + std::to_string(::getpid()) + ".png");
    ImageStandIn() { std::ofstream(path) << "not read"; }
    ~ImageStandIn() { std::filesystem::remove(path); }
};

/// 2 x 1 pixels: red on the left, blue on the right, opaque.
dsl::ImageReader two_pixel_reader(int* reads = nullptr, ImageGamma* seen = nullptr) {
    return [reads, seen](const std::filesystem::path&, ImageGamma g) {
        if (reads) ++*reads;
        if (seen) *seen = g;
        return PixelGrid(2, 1, {{1.0f, 0.0f, 0.0f, 1.0f}, {0.0f, 0.0f, 1.0f, 1.0f}});
    };
}

struct BuiltImageScene {
    dsl::SceneDescription desc;
    std::vector<dsl::Diagnostic> warnings;
    std::optional<dsl::BuiltScene<double>> built;  ///< set by build_image_scene
};

BuiltImageScene build_image_scene(const std::string& text, dsl::ImageReader reader) {
    BuiltImageScene b;
    dsl::ParseOptions po;
    po.diagnostics = collect(b.warnings);
    b.desc = dsl::parse_string(std::string(stage) + text, "test.pov", po);
    dsl::BuildOptions bo;
    bo.diagnostics = collect(b.warnings);
    bo.read_image = std::move(reader);
    b.built.emplace(dsl::build<double>(b.desc, bo));
    return b;
}

}  // namespace

TEST_CASE("an image_map pigment colours a surface pixel by pixel, with no warning", "[dsl][image_map]") {
    const ImageStandIn file;
    int reads = 0;
    ImageGamma gamma;
    const auto b = build_image_scene("#version 3.7;\nplane { z, 0 pigment { image_map { png \"" + file.path.string() +
                                         "\" } } }\n"
                                         "plane { z, 1 pigment { image_map { png \"" + file.path.string() + "\" } } }\n",
                                     two_pixel_reader(&reads, &gamma));
    INFO(all_messages(b.warnings));
    CHECK(b.warnings.empty());
    CHECK(reads == 1);  // read once for both planes
    CHECK(gamma.kind == ImageGamma::Kind::file);
    const auto& m = b.built->scene.material_of(0);
    // The planar map: x in [0, 0.5) is the left pixel, [0.5, 1) the right; diffuse 0.6 by default.
    const Rgb<double> left = m.diffuse_at({0.25, 0.5, 0.0}), right = m.diffuse_at({0.75, 0.5, 0.0});
    CHECK_THAT(left.x, Catch::WithinAbs(0.6, 1e-12));
    CHECK_THAT(left.z, Catch::WithinAbs(0.0, 1e-12));
    CHECK_THAT(right.z, Catch::WithinAbs(0.6, 1e-12));
    CHECK_THAT(m.diffuse_at({1.25, -3.5, 0.0}).x, Catch::WithinAbs(0.6, 1e-12));  // repeated
}

TEST_CASE("image_map's options reach the library, and `gamma` the reader", "[dsl][image_map]") {
    const ImageStandIn file;
    ImageGamma gamma;
    const auto b = build_image_scene("#version 3.7;\nsphere { 0, 1 pigment { image_map { png \"" + file.path.string() +
                                         "\" gamma 2.2 map_type 1 interpolate 2 } scale 2 } }\n",
                                     two_pixel_reader(nullptr, &gamma));
    INFO(all_messages(b.warnings));
    CHECK(b.warnings.empty());
    CHECK(gamma.kind == ImageGamma::Kind::power);
    CHECK(gamma.gamma == 2.2);
    // Spherical and bilinear: at +z (a quarter turn, u = 0.5 of width 2) the centre of the red
    // pixel; at -x (half a turn, u = 1) half way between the two pixel centres, red and blue
    // blend evenly.
    CHECK_THAT(b.built->scene.material_of(0).diffuse_at({0.0, 0.0, 2.0}).x, Catch::WithinAbs(0.6, 1e-9));
    const Rgb<double> c = b.built->scene.material_of(0).diffuse_at({-2.0, 0.0, 0.0});
    CHECK_THAT(c.x, Catch::WithinAbs(0.3, 1e-9));
    CHECK_THAT(c.z, Catch::WithinAbs(0.3, 1e-9));
}

TEST_CASE("image_map's errors name the place in the scene", "[dsl][image_map]") {
    CHECK_THAT(error_of("plane { y, 0 pigment { image_map { png \"photon-no-such.png\" } } }"),
               Catch::Contains("1:40: cannot find the image file"));
    const ImageStandIn file;
    CHECK_THAT(error_of("plane { y, 0 pigment { image_map { png \"" + file.path.string() + "\" map_type 3 } } }"),
               Catch::Contains("`map_type` must be 0"));
    std::vector<dsl::Diagnostic> warnings;
    const auto desc = dsl::parse_string(std::string(stage) + "plane { y, 0 pigment { image_map { png \"" +
                                            file.path.string() + "\" } } }\n",
                                        "test.pov");
    CHECK_THROWS_WITH(dsl::build<double>(desc), Catch::Contains("test.pov:3:") && Catch::Contains("reads no images"));
}

TEST_CASE("image_map is written back by export_pov and builds the same", "[dsl][image_map]") {
    const ImageStandIn file;
    const auto a = build_image_scene("#version 3.7;\nplane { z, 0 pigment { image_map { png \"" + file.path.string() +
                                         "\" once interpolate 4 transmit all 0.25 } scale 3 translate x } }\n",
                                     two_pixel_reader());
    const std::string exported = dsl::export_pov(a.desc);
    CHECK_THAT(exported, Catch::Contains("image_map { png") && Catch::Contains("once") &&
                             Catch::Contains("interpolate 4") && Catch::Contains("transmit all 0.25"));
    dsl::BuildOptions bo;
    bo.read_image = two_pixel_reader();
    const auto b = dsl::build<double>(dsl::parse_string(exported, "exported.pov"), bo);
    for (const Vec3<double>& p : {Vec3<double>(1.4, 0.3, 0), Vec3<double>(3.1, 2.9, 0), Vec3<double>(-1.0, 0.5, 0)})
        CHECK(glm::length(a.built->scene.material_of(0).diffuse_at(p) - b.scene.material_of(0).diffuse_at(p)) < 1e-12);
}

TEST_CASE("height_field reads its image's heights as POV-Ray does, in CSG too, and exports", "[dsl][height_field]") {
    const ImageStandIn file;
    ImageGamma gamma{ImageGamma::Kind::file};
    // 3 x 2 grey pixels, 16 bits: the top row (far edge, z = 1) high, the bottom row low.
    const dsl::ImageReader reader = [&gamma](const std::filesystem::path&, ImageGamma g) {
        gamma = g;
        PixelGrid grid(3, 2, {{1, 1, 1, 1}, {1, 1, 1, 1}, {1, 1, 1, 1}, {0, 0, 0, 1}, {0, 0, 0, 1}, {0, 0, 0, 1}});
        grid.grayscale = true;
        grid.max_value = 65535;
        return grid;
    };
    const std::string hf = "height_field { png \"" + file.path.string() + "\" smooth water_level 0.1 scale <2, 1, 4> }\n";
    const auto b = build_image_scene("#version 3.7;\n" + hf, reader);
    INFO(all_messages(b.warnings));
    CHECK(b.warnings.empty());
    CHECK(gamma.kind == ImageGamma::Kind::none);  // heights are read as stored
    REQUIRE(b.built->scene.objects().size() == 1);
    const auto* field = std::get_if<Transformed<HeightField<double>>>(&b.built->scene.objects()[0].shape);
    REQUIRE(field != nullptr);
    CHECK(field->shape().options().smooth);
    // Straight down at z = 2 of 4 (half way): the surface rises linearly from 0 to 65535 / 65536.
    Ray<double> down{{1.0, 5.0, 2.0}, {0, -1, 0}};
    const auto hit = b.built->scene.intersect(down);
    REQUIRE(hit);
    CHECK(hit->hit.point.y == Approx(0.5 * 65535.0 / 65536));

    // In a difference, as a solid.
    const auto c = build_image_scene("#version 3.7;\ndifference { box { <0.1, -1, 0.1>, <1.9, 0.2, 3.9> } " + hf + "}\n", reader);
    INFO(all_messages(c.warnings));
    CHECK(c.warnings.empty());

    const std::string exported = dsl::export_pov(b.desc);
    CHECK_THAT(exported, Catch::Contains("height_field { png") && Catch::Contains("smooth") && Catch::Contains("water_level 0.1"));
    dsl::BuildOptions bo;
    bo.read_image = reader;
    const auto again = dsl::build<double>(dsl::parse_string(exported, "exported.pov"), bo);
    const auto hit2 = again.scene.intersect(down);
    REQUIRE(hit2);
    CHECK(hit2->hit.point.y == Approx(hit->hit.point.y));
}

TEST_CASE("height_field's function form is skipped with a warning", "[dsl][height_field]") {
    const auto p = parse("height_field { function 20, 20 { x * y } smooth }");
    CHECK_THAT(all_messages(p.warnings), Catch::Contains("skipped") && Catch::Contains("image files only"));
}

TEST_CASE("normal { bump_map } tilts the shading normal by the image, and exports", "[dsl][bump_map]") {
    const ImageStandIn file;
    ImageGamma gamma{ImageGamma::Kind::file};
    // 4 x 1 pixels rising to the right: a slope along x.
    const dsl::ImageReader reader = [&gamma](const std::filesystem::path&, ImageGamma g) {
        gamma = g;
        return PixelGrid(4, 1, {{0.0f, 0.0f, 0.0f, 1.0f}, {0.2f, 0.2f, 0.2f, 1.0f}, {0.4f, 0.4f, 0.4f, 1.0f},
                                {0.6f, 0.6f, 0.6f, 1.0f}});
    };
    const std::string scene = "#version 3.7;\nplane { y, 0 pigment { rgb 0.5 } normal { bump_map { png \"" +
                              file.path.string() + "\" bump_size 3 } rotate 90*x } }\n";
    const auto b = build_image_scene(scene, reader);
    INFO(all_messages(b.warnings));
    CHECK(b.warnings.empty());
    CHECK(gamma.kind == ImageGamma::Kind::none);  // bump maps are read as stored
    const auto& m = b.built->scene.material_of(0);
    REQUIRE(m.params().normal_field);
    // Over pixel 1 (x in [0.25, 0.5)): the neighbours' heights differ by 3 * (0.4 - 0.0) across two pixels.
    const Vec3<double> n = m.params().normal_field({0.375, 0.0, 0.5}, {0, 1, 0});
    CHECK(n.x < -0.3);  // leaning away from the rise
    CHECK(glm::length(n) == Approx(1.0));
    const std::string exported = dsl::export_pov(b.desc);
    CHECK_THAT(exported, Catch::Contains("normal { bump_map { png") && Catch::Contains("bump_size 3"));
    dsl::BuildOptions bo;
    bo.read_image = reader;
    const auto again = dsl::build<double>(dsl::parse_string(exported, "exported.pov"), bo);
    const Vec3<double> n2 = again.scene.material_of(0).params().normal_field({0.375, 0.0, 0.5}, {0, 1, 0});
    CHECK(glm::length(n2 - n) < 1e-9);
}
