// SPDX-License-Identifier: MIT
// Patterned pigments in the scene language: read with their modifiers and transformations, moved
// with their object as POV-Ray moves them, evaluated by the built material, checked for energy,
// and written back by export-pov.

#include <catch2/catch.hpp>

#include "dsl_test_util.hpp"

#include <algorithm>

#include <optional>
#include <utility>

using namespace dsl_test;
using Catch::Matchers::Contains;
using photon::Rgb;
using photon::Vec3;

namespace {

const char* const pattern_stage = "camera { location <0, 0, -5> look_at 0 }\nlight_source { <0, 5, -5>, 1 }\n";

struct PatternScene {
    std::vector<dsl::Diagnostic> warnings;
    std::optional<dsl::BuiltScene<double>> built;
};
PatternScene build_patterned(const std::string& text) {
    PatternScene b;
    dsl::ParseOptions po;
    po.diagnostics = collect(b.warnings);
    const auto desc = dsl::parse_string(std::string(pattern_stage) + text, "test.pov", po);
    dsl::BuildOptions bo;
    bo.diagnostics = collect(b.warnings);
    b.built.emplace(dsl::build<double>(desc, bo));
    return b;
}

/// The diffuse albedo of object `i` at world point p.
Rgb<double> albedo(const PatternScene& b, std::uint32_t i, const Vec3<double>& p) {
    return b.built->scene.material_of(i).diffuse_at(p);
}

}  // namespace

TEST_CASE("a pattern's modifiers, colours and transformations are read", "[dsl][texture]") {
    const Parsed p = parse(std::string(pattern_stage) +
                           "sphere { 0, 1 pigment { marble turbulence 0.5 octaves 4 omega 0.6 lambda 2.2 "
                           "frequency 2 phase 0.1 sine_wave noise_generator 3 "
                           "color_map { [0 rgb 1] [0.5 rgbt <1, 0, 0, 0.5>] } scale 2 } }\n"
                           "sphere { 0, 1 pigment { gradient <0, 3, 0> } }\n");
    REQUIRE(p.warnings.empty());
    const dsl::Pigment& m = p.desc.objects.at(1).texture->pigment;
    REQUIRE(m.pattern);
    CHECK(m.pattern->name == "marble");
    CHECK(m.pattern->turbulence == dsl::Vector3(0.5));
    CHECK(m.pattern->octaves == 4);
    CHECK(m.pattern->omega == 0.6);
    CHECK(m.pattern->lambda == 2.2);
    CHECK(m.pattern->frequency == 2);
    CHECK(m.pattern->phase == 0.1);
    CHECK(m.pattern->wave == "sine_wave");
    CHECK(m.pattern->noise_generator == 3);
    REQUIRE(m.pattern->colors.size() == 2);
    CHECK(m.pattern->colors[1].second.transmit == 0.5);
    CHECK(m.transform == dsl::Transform::scale(dsl::Vector3(2)));
    const dsl::Pigment& g = p.desc.objects.at(2).texture->pigment;
    REQUIRE(g.pattern);
    CHECK(g.pattern->gradient == dsl::Vector3(0, 3, 0));
    CHECK(g.pattern->colors.size() == 2);  // POV-Ray's default map, black to white
    CHECK(g.color.rgb == dsl::Vector3(0.5));
}

TEST_CASE("the built material evaluates the pattern where light meets it", "[dsl][texture]") {
    const PatternScene b = build_patterned("plane { y, 0 pigment { checker rgb 1, rgb <0, 0, 0.5> } finish { ambient 0 diffuse 0.5 } }\n"
                               "plane { y, -1 pigment { gradient x color_map { [0 rgb 0] [1 rgb 0.8] } } "
                               "finish { ambient 0 diffuse 1 } }\n");
    INFO(all_messages(b.warnings));
    CHECK(albedo(b, 0, {0.5, 0, 0.5}) == Rgb<double>(0.5));
    CHECK(albedo(b, 0, {1.5, 0, 0.5}) == Rgb<double>(0, 0, 0.25));
    CHECK(albedo(b, 0, {1.5, 0, 1.5}) == Rgb<double>(0.5));
    CHECK(albedo(b, 1, {0.25, -1, 3}).x == Approx(0.2));
    CHECK(albedo(b, 1, {1.75, -1, 3}).x == Approx(0.6));
    CHECK(b.built->scene.material_of(0).is_textured());
}

TEST_CASE("hexagon's three listed colours, or POV-Ray's defaults, are picked cell by cell without a warning",
          "[dsl][texture]") {
    const PatternScene b = build_patterned(
        "plane { y, 0 pigment { hexagon rgb 0.2, rgb 0.4, rgb 0.8 } finish { ambient 0 diffuse 1 } }\n"
        "plane { y, -1 pigment { hexagon rgb 0.2 } finish { ambient 0 diffuse 1 } }\n");  // 2 of 3 defaulted
    INFO(all_messages(b.warnings));
    CHECK(b.warnings.empty());
    // Points inside each colour's cells (POV-Ray: 0 at the origin's hexagon, 1 above it, 2 beside it).
    const double shown[3] = {0.2, 0.4, 0.8};
    const Vec3<double> at[3] = {{0.1, 0, 0.1}, {0.1, 0, 1.0}, {0.9, 0, 0.6}};
    for (int c = 0; c < 3; ++c) CHECK(albedo(b, 0, at[c]) == Rgb<double>(shown[photon::pattern_detail::hexagon_colour(at[c].x, at[c].z)]));
    CHECK(photon::pattern_detail::hexagon_colour(0.1, 0.1) == 0);
    CHECK(photon::pattern_detail::hexagon_colour(0.1, 1.0) == 1);
    CHECK(photon::pattern_detail::hexagon_colour(0.9, 0.6) == 2);
    CHECK(albedo(b, 1, {0.1, -1, 0.1}) == Rgb<double>(0.2));       // written
    CHECK(albedo(b, 1, {0.1, -1, 1.0}) == Rgb<double>(0, 1, 0));   // POV-Ray's default second colour, green
    CHECK(albedo(b, 1, {0.9, -1, 0.6}) == Rgb<double>(1, 0, 0));   // and third, red
}

TEST_CASE("crackle and cells are evaluated with crackle's form, metric, offset and solid, without a warning",
          "[dsl][texture]") {
    const PatternScene b = build_patterned(
        "plane { y, 0 pigment { crackle form <0.3, 0.6, -0.4> metric 1 offset 0.2 color_map { [0 rgb 0] [1 rgb 1] } } "
        "finish { ambient 0 diffuse 1 } }\n"
        "plane { y, -1 pigment { cells color_map { [0 rgb 0] [1 rgb 1] } } finish { ambient 0 diffuse 1 } }\n"
        "plane { y, -2 pigment { crackle solid color_map { [0 rgb 0] [1 rgb 1] } } finish { ambient 0 diffuse 1 } }\n");
    INFO(all_messages(b.warnings));
    CHECK(b.warnings.empty());
    photon::CrackleParams c;
    c.form = {0.3, 0.6, -0.4};
    c.metric = 1;
    c.offset = 0.2;
    photon::CrackleParams solid;
    solid.solid = true;
    for (const Vec3<double>& q : {Vec3<double>(0.3, 0, 0.7), Vec3<double>(-2.1, 0, 5.4), Vec3<double>(7.7, 0, -0.2)}) {
        CHECK(albedo(b, 0, q).x == Approx(photon::crackle_value(q, c)));
        CHECK(albedo(b, 1, q - Vec3<double>(0, 1, 0)).x == Approx(photon::cells_value(q - Vec3<double>(0, 1, 0))));
        CHECK(albedo(b, 2, q - Vec3<double>(0, 2, 0)).x == Approx(photon::crackle_value(q - Vec3<double>(0, 2, 0), solid)));
    }
    CHECK_THROWS_WITH(build_patterned("plane { y, 0 pigment { crackle metric 0 } }\n"),
                      Contains("test.pov:3:") && Contains("crackle's `metric` must be positive, found 0"));
}

TEST_CASE("a texture moves with the transformations written after it, as in POV-Ray", "[dsl][texture]") {
    const PatternScene b = build_patterned(
        "sphere { 0, 1 pigment { checker rgb 1, rgb 0 } finish { ambient 0 diffuse 1 } translate x }\n"  // moved
        "sphere { 0, 1 translate x pigment { checker rgb 1, rgb 0 } finish { ambient 0 diffuse 1 } }\n"  // not moved
        "union { sphere { 0, 1 pigment { checker rgb 1, rgb 0 } finish { ambient 0 diffuse 1 } } translate x }\n"
        "union { sphere { 0, 1 } pigment { checker rgb 1, rgb 0 scale 2 } finish { ambient 0 diffuse 1 } "
        "translate <2, 0, 0> }\n");
    const Vec3<double> p(1.5, 0.1, 0.5);  // in cell (1, 0, 0) of the world, (0, 0, 0) one unit to the left
    CHECK(albedo(b, 0, p) == Rgb<double>(1));
    CHECK(albedo(b, 1, p) == Rgb<double>(0));
    CHECK(albedo(b, 2, p) == Rgb<double>(1));
    // The union's own texture, scaled by 2 and then moved by 2: world x 2.5 is pattern x 0.25.
    CHECK(albedo(b, 3, {2.5, 0.1, 0.5}) == Rgb<double>(1));
    CHECK(albedo(b, 3, {1.5, 0.1, 0.5}) == Rgb<double>(0));
}

TEST_CASE("a declared pigment's pattern takes further modifiers", "[dsl][texture]") {
    const Parsed p = parse(std::string(pattern_stage) +
                           "#declare P = pigment { bozo color_map { [0 rgb 0] [1 rgb 1] } }\n"
                           "sphere { 0, 1 pigment { P turbulence 0.3 scale 2 } }\n"
                           "sphere { 0, 1 pigment { P rgb <1, 0, 0> } }\n");
    const dsl::Pigment& a = p.desc.objects.at(1).texture->pigment;
    REQUIRE(a.pattern);
    CHECK(a.pattern->name == "bozo");
    CHECK(a.pattern->turbulence == dsl::Vector3(0.3));
    CHECK(a.pattern->colors.size() == 2);
    CHECK(a.transform == dsl::Transform::scale(dsl::Vector3(2)));
    CHECK_FALSE(p.desc.objects.at(2).texture->pigment.pattern);  // a colour after it: one colour
}

TEST_CASE("what photon cannot evaluate is averaged with a warning that says why", "[dsl][texture]") {
    const Parsed p = parse(std::string(pattern_stage) +
                           "sphere { 0, 1 pigment { bozo warp { turbulence 0.5 } } }\n"
                           "sphere { 0, 1 pigment { gradient x uv_mapping } }\n"
                           "sphere { 0, 1 pigment { tiling 1 } }\n");
    CHECK(places(p.warnings, "approximated pigment") == std::vector<std::string>{"3:25 bozo", "4:25 gradient", "5:25 tiling"});
    CHECK_THAT(all_messages(p.warnings), Contains("photon does not evaluate `warp` (at 3:30)"));
    CHECK_THAT(all_messages(p.warnings), Contains("photon does not evaluate `uv_mapping`"));
    for (std::size_t i = 1; i <= 3; ++i) CHECK_FALSE(p.desc.objects.at(i).texture->pigment.pattern);
}

TEST_CASE("a pattern's brightest colour is what the energy check scales", "[dsl][texture]") {
    // Warned under radiosity only: without it the camera sees the surface as POV-Ray does.
    const PatternScene b = build_patterned("global_settings { radiosity { } }\n"
                                           "sphere { 0, 1 pigment { checker rgb 1, rgb 0.2 } "
                                           "finish { ambient 0 diffuse 1 reflection 0.3 } }\n");
    CHECK_THAT(all_messages(b.warnings), Contains("diffuse (the pattern's brightest colour) 1 + reflection 0.3"));
    const auto& m = b.built->scene.material_of(0);
    CHECK(m.seen_gain() == Approx(1.3));
    CHECK(m.diffuse_at({0.5, 0.5, 0.5}).x == Approx(1 / 1.3));
    CHECK(m.diffuse_at({0.5, 0.5, 1.5}).x == Approx(0.2 / 1.3));
    CHECK(m.params().specular.x == Approx(0.3 / 1.3));
}

TEST_CASE("mandel is evaluated with its iteration count, interior and exterior, without a warning", "[dsl][texture]") {
    const PatternScene b = build_patterned(
        "plane { z, 0 pigment { mandel 40 interior 1, 2 exterior 6, 0.25 color_map { [0 rgb 0] [1 rgb 1] } } "
        "finish { ambient 0 diffuse 1 } }\n"
        "plane { z, 1 pigment { mandel 25 exponent 2 } finish { ambient 0 diffuse 1 } }\n"
        "sphere { 0, 1 pigment { rgb 1 } normal { mandel 80 0.5 interior 1, 5 } }\n");
    INFO(all_messages(b.warnings));
    CHECK(b.warnings.empty());
    const photon::FractalParams f{.iterations = 40, .interior_type = 1, .exterior_type = 6, .interior_factor = 2, .exterior_factor = 0.25};
    for (const Vec3<double>& q : {Vec3<double>(0.1, 0.2, 0), Vec3<double>(0.45, -0.3, 0), Vec3<double>(-0.75, 0.12, 0)})
        CHECK(albedo(b, 0, q).x == Approx(std::clamp(photon::mandel_value(q.x, q.y, f), 0.0, 1.0)));
    // POV-Ray's own colour map for mandel: the set (value 1) is cyan, past the map's last entry.
    const Rgb<double> inside = albedo(b, 1, {0, 0, 1});
    CHECK(inside.x == Approx(0.0));
    CHECK(inside.y == Approx(1.0));
    CHECK(inside.z == Approx(1.0));
    // The normal reads its iteration count before its bump size.
    const auto& normal = b.built->scene.material_of(2);
    CHECK(normal.has_normal_field());
    // What photon does not evaluate is still said: another exponent, and bad types are errors.
    const PatternScene cubic = build_patterned("plane { z, 0 pigment { mandel 25 exponent 3 } }\n");
    CHECK_THAT(all_messages(cubic.warnings), Contains("photon does not evaluate `exponent`"));
    CHECK_THROWS_WITH(build_patterned("plane { z, 0 pigment { mandel 25 interior 7, 1 } }\n"),
                      Contains("the type of `interior` (0 to 6) must be a whole number from 0 to 6, found 7"));
    CHECK_THROWS_WITH(build_patterned("plane { z, 0 pigment { mandel 25 exterior 7, 0.5 } }\n"),
                      Contains("`exterior 7` takes the iteration count modulo its factor"));
    CHECK_THROWS_WITH(build_patterned("plane { z, 0 pigment { mandel 0 } }\n"), Contains("mandel's iteration count must be"));
}

TEST_CASE("spiral1, spiral2 and quilted are evaluated with their arms and controls, in pigments and normals",
          "[dsl][texture]") {
    const PatternScene b = build_patterned(
        "plane { z, 0 pigment { spiral1 5 color_map { [0 rgb 0] [1 rgb 1] } } finish { ambient 0 diffuse 1 } }\n"
        "plane { z, 1 pigment { quilted control0 0.3 control1 0.8 color_map { [0 rgb 0] [1 rgb 1] } } "
        "finish { ambient 0 diffuse 1 } }\n"
        "sphere { 0, 1 pigment { rgb 1 } normal { spiral2 5, 1.6 } }\n"
        "sphere { 0, 1 pigment { rgb 1 } normal { quilted 0.4 control0 0.5 control1 1 } }\n");
    INFO(all_messages(b.warnings));
    CHECK(b.warnings.empty());
    for (const Vec3<double>& q : {Vec3<double>(0.1, 0.2, 0), Vec3<double>(0.45, -0.3, 0), Vec3<double>(-0.75, 0.12, 0)}) {
        CHECK(albedo(b, 0, q).x == Approx(photon::Wave{.type = photon::WaveType::triangle}(photon::spiral_value(q, 5, false))));
        const Vec3<double> up = q + Vec3<double>(0, 0, 1);
        CHECK(albedo(b, 1, up).x == Approx(photon::quilted_value(up, 0.3, 0.8)));  // frequency 0: not wrapped
    }
    CHECK(b.built->scene.material_of(2).has_normal_field());
    CHECK(b.built->scene.material_of(3).has_normal_field());
    // A spiral's turbulence is its own formula's, which photon does not evaluate: said.
    const PatternScene turbulent = build_patterned("plane { z, 0 pigment { spiral1 5 turbulence 0.3 } }\n");
    CHECK_THAT(all_messages(turbulent.warnings), Contains("photon does not evaluate `turbulence`"));
    CHECK_THROWS_WITH(build_patterned("plane { z, 0 pigment { spiral2 1e6 } }\n"), Contains("takes -32767 to 32767 arms"));
}

TEST_CASE("export-pov writes a pattern back, and reading it gives the same pattern", "[dsl][texture]") {
    const Parsed p = parse(std::string(pattern_stage) +
                           "sphere { 0, 1 pigment { wood turbulence <0.1, 0.2, 0> octaves 3 frequency 2 cubic_wave "
                           "color_map { [0 rgb 1] [0.5 rgb <1, 0, 0>] } rotate x * 90 scale 0.2 } "
                           "finish { ambient 0 } translate <1, 2, 3> }\n"
                           "box { 0, 1 pigment { checker rgb 1, rgb 0 } }\n"
                           "box { 0, 1 pigment { crackle form <0.3, 0.6, -0.4> metric 3 offset 0.1 solid scale 0.5 } }\n"
                           "box { 0, 1 pigment { hexagon rgb 0.1, rgb 0.2, rgb 0.3 } }\n"
                           "box { 0, 1 pigment { mandel 70 interior 1, 2 exterior 6, 0.5 } }\n"
                           "box { 0, 1 pigment { spiral2 7 frequency 2 } }\n"
                           "box { 0, 1 pigment { quilted control0 0.2 control1 0.7 } }\n");
    const std::string pov = dsl::export_pov(p.desc);
    INFO(pov);
    const Parsed q = parse(pov);
    REQUIRE(q.desc.objects.size() == p.desc.objects.size());
    for (std::size_t i = 1; i < p.desc.objects.size(); ++i) {
        const dsl::Pigment& a = p.desc.objects[i].texture->pigment;
        const dsl::Pigment& c = q.desc.objects[i].texture->pigment;
        REQUIRE(c.pattern);
        CHECK(*a.pattern == *c.pattern);
        CHECK(a.transform == c.transform);
        CHECK(p.desc.objects[i].transform == q.desc.objects[i].transform);
    }
}

TEST_CASE("examples/scenes/textures.pov and patterns.pov build without warnings, and exported they build the same "
          "textures",
          "[dsl][texture]") {
    // The floor, three walls and three balls of textures.pov; of patterns.pov, the floor, three
    // walls and the mandel ball (the quilted ball is plain, with a normal). Not the ceiling or glass.
    for (const auto& [file, expected_textured] : {std::pair{"textures.pov", 7}, std::pair{"patterns.pov", 5}}) {
        INFO(file);
        std::vector<dsl::Diagnostic> warnings;
        dsl::ParseOptions po;
        po.diagnostics = collect(warnings);
        const auto desc = dsl::parse_file(std::filesystem::path(PHOTON_SCENES_DIR) / file, po);
        dsl::BuildOptions bo;
        bo.diagnostics = collect(warnings);
        const auto a = dsl::build<double>(desc, bo);
        INFO(all_messages(warnings));
        CHECK(warnings.empty());
        int textured = 0;
        for (std::uint32_t i = 0; i < a.scene.objects().size(); ++i) textured += a.scene.material_of(i).is_textured();
        CHECK(textured == expected_textured);
        const auto b = dsl::build<double>(dsl::parse_string(dsl::export_pov(desc), "exported.pov"));
        REQUIRE(b.scene.objects().size() == a.scene.objects().size());
        for (std::uint32_t i = 0; i < a.scene.objects().size(); ++i)
            for (const Vec3<double>& p :
                 {Vec3<double>(0.3, 0.01, -0.7), Vec3<double>(-1.21, 0.9, 0.4), Vec3<double>(0.6, 0.3, 0.4),
                  Vec3<double>(-0.2, 1.1, 1.2), Vec3<double>(-0.5, 0.3, -0.6)}) {
                INFO("object " << i);
                const Rgb<double> x = a.scene.material_of(i).diffuse_at(p), y = b.scene.material_of(i).diffuse_at(p);
                CHECK(glm::length(x - y) < 1e-9);
            }
    }
}

TEST_CASE("a pigment_map's patterned entries nest, moved by the pigment that holds them", "[dsl][texture]") {
    // gradient y blends red (value 0) into a checker of size 0.5 (value 1); the outer `scale 2`
    // moves both. Albedos are the colours times the finish's diffuse 0.6 (POV-Ray's default).
    const PatternScene b = build_patterned(
        "#declare Check = pigment { checker rgb 0, rgb 1 scale 0.5 }\n"
        "sphere { 0, 1 pigment { gradient y pigment_map { [0 rgb <1, 0, 0>] [1 Check] } } }\n"
        "sphere { 0, 1 pigment { gradient y pigment_map { [0 rgb <1, 0, 0>] [1 Check] } scale 2 } }\n"
        "sphere { 0, 1 pigment { gradient y pigment_map { [0 rgb <1, 0, 0>] [1 Check translate 0.5 * x] } } }\n");
    CHECK(places(b.warnings, "approximated pigment").empty());
    // Point (0.1, 0.9, 0.1): gradient 0.9; checker cell (0, 1, 0), odd: its second colour, white.
    const Rgb<double> a = albedo(b, 0, {0.1, 0.9, 0.1});
    CHECK(a.x == Approx(0.6 * (0.1 * 1 + 0.9 * 1)));
    CHECK(a.y == Approx(0.6 * 0.9));
    // Scaled by 2: the point (0.2, 1.8, 0.2) is where (0.1, 0.9, 0.1) was.
    const Rgb<double> s = albedo(b, 1, {0.2, 1.8, 0.2});
    CHECK(s.x == Approx(a.x));
    CHECK(s.y == Approx(a.y));
    // The entry's own translation moves its checker alone: cell (1, 1, 0), even: black.
    const Rgb<double> t = albedo(b, 2, {0.1, 0.9, 0.1});
    CHECK(t.x == Approx(0.6 * 0.1));
    CHECK(t.y == Approx(0.0).margin(1e-12));
}

TEST_CASE("POV-Ray's cloudy skies (skies.inc, a pigment_map of patterns) build with no warning", "[dsl][texture][sky]") {
    const std::filesystem::path includes = "/usr/share/povray-3.7/include";
    if (!std::filesystem::exists(includes / "skies.inc")) {
        WARN("povray-includes is not installed: skipped");
        return;
    }
    std::vector<dsl::Diagnostic> warnings;
    dsl::ParseOptions po;
    po.diagnostics = collect(warnings);
    po.include_paths.push_back(includes);
    const auto desc = dsl::parse_string(std::string(pattern_stage) + "#include \"colors.inc\"\n#include \"skies.inc\"\nsky_sphere { S_Cloud1 }\n"
                                        "sphere { 0, 1 }\n", "test.pov", po);
    dsl::BuildOptions bo;
    bo.diagnostics = collect(warnings);
    const auto built = dsl::build<double>(desc, bo);
    CHECK(all_messages(warnings).find("pigment_map") == std::string::npos);
    const auto& sky = *built.scene.environment();
    // Clouds: the sky's colour changes from direction to direction above the horizon.
    double lo = 1e9, hi = -1e9;
    for (int i = 0; i < 64; ++i) {
        const double a = i * 0.1;
        const double v = photon::average(sky.radiance(glm::normalize(Vec3<double>(std::cos(a), 0.6, std::sin(a)))));
        lo = std::min(lo, v), hi = std::max(hi, v);
    }
    CHECK(hi - lo > 0.05);
}

TEST_CASE("listed colours need no comma: a second rgb starts the next colour, as in POV-Ray", "[dsl][texture]") {
    const PatternScene b = build_patterned("sphere { 0, 1 pigment { checker rgb 1 rgb 0.5 } }\n"
                                           "sphere { 0, 1 pigment { checker color rgb <1, 0, 0> green 0.5 rgbf <0, 0, 1, 0> } }\n");
    CHECK(albedo(b, 0, {0.5, 0.5, 0.5}).y == Approx(0.6));      // cell (0, 0, 0): the first colour
    CHECK(albedo(b, 0, {0.5, 0.5, 1.5}).y == Approx(0.6 * 0.5));  // cell (0, 0, 1): the second, not green
    CHECK(albedo(b, 1, {0.5, 0.5, 0.5}) == Rgb<double>(0.6, 0.3, 0));  // `green 0.5` modifies the first
    CHECK(albedo(b, 1, {0.5, 0.5, 1.5}) == Rgb<double>(0, 0, 0.6));
}
