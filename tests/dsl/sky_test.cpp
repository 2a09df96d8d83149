// SPDX-License-Identifier: MIT
// `background` and `sky_sphere` build the library's sky (light/environment.hpp) with POV-Ray
// 3.7's composition (Trace::ComputeSky; 3.6's before #version 3.7): the pigments from the last written down, each times
// `emission`, the background under them, evaluated at the direction moved back by the
// sky_sphere's transformations (all of its pigments, wherever written); and export-pov writes
// them back.

#include <catch2/catch.hpp>

#include "dsl_test_util.hpp"

using namespace dsl_test;
using Catch::Matchers::Contains;
using photon::Rgb;
using photon::Vec3;

namespace {

const char* const sky_stage = "camera { location <0, 0, -5> look_at 0 }\nsphere { 0, 1 }\n";

StagedScene build_sky(const std::string& text) { return build_staged(text, {}, sky_stage); }

void check_sky(const StagedScene& b, Vec3<double> direction, Rgb<double> expected) {
    REQUIRE(b.scene.environment().has_value());
    const Rgb<double> got = b.scene.environment()->radiance(glm::normalize(direction));
    INFO("direction " << direction.x << ", " << direction.y << ", " << direction.z);
    for (int c = 0; c < 3; ++c) CHECK(got[c] == Approx(expected[c]).margin(1e-9));
}

}  // namespace

TEST_CASE("background is the sky's colour, with no warning", "[dsl][sky]") {
    const StagedScene b = build_sky("background { rgb <0.2, 0.4, 0.6> }\n");
    check_sky(b, {0, 1, 0}, {0.2, 0.4, 0.6});
    check_sky(b, {1, -1, 0.3}, {0.2, 0.4, 0.6});
    CHECK(b.scene.environment()->is_constant());
    CHECK(all_messages(b.warnings).find("background") == std::string::npos);
    // The sky lights the scene: no "no light_source" warning.
    CHECK(all_messages(b.warnings).find("no light_source") == std::string::npos);
    // POV-Ray's default, black, is no sky at all.
    CHECK_FALSE(build_sky("background { rgb 0 }\n").scene.environment().has_value());
}

TEST_CASE("sky_sphere's pigment is evaluated at the direction, moved back by its transformations", "[dsl][sky]") {
    // The common idiom: c0 at the nadir, c1 at the zenith.
    const StagedScene a = build_sky(
        "sky_sphere { pigment { gradient y color_map { [0 rgb <1, 0.5, 0>] [1 rgb <0, 0.5, 1>] } scale 2 translate -1 } }\n");
    check_sky(a, {0, 1, 0}, {0, 0.5, 1});
    check_sky(a, {0, -1, 0}, {1, 0.5, 0});
    check_sky(a, {1, 0, 0}, {0.5, 0.5, 0.5});
    CHECK(all_messages(a.warnings).find("sky_sphere") == std::string::npos);
    // The sky_sphere's own rotation turns the gradient: after rotate 90 about z, +y goes to -x.
    const StagedScene r = build_sky(
        "sky_sphere { pigment { gradient y color_map { [0 rgb <1, 0.5, 0>] [1 rgb <0, 0.5, 1>] } scale 2 translate -1 }"
        " rotate <0, 0, 90> }\n");
    check_sky(r, {-1, 0, 0}, {0, 0.5, 1});
    check_sky(r, {0, 1, 0}, {0.5, 0.5, 0.5});
    // emission multiplies the pigments, not the background.
    const StagedScene e = build_sky("background { rgb 0.1 }\nsky_sphere { pigment { rgb <0.2, 0.4, 0.6> } emission rgb 2 }\n");
    check_sky(e, {0, 0, 1}, {0.4, 0.8, 1.2});
}

TEST_CASE("sky_sphere's layers compose as POV-Ray 3.7's over the background, or as 3.6's before 3.7", "[dsl][sky]") {
    // Top, rgbt <1, 1, 1, 0.5>: its own 0.5, and passes 0.5 (transmit). Below, rgbf <0, 1, 1, 0.5>:
    // 0.5 * <0, 1, 1> * 0.5, and passes 0.5 * <0, 1, 1> of what reaches it (filter). The
    // background <1, 1, 1> under both: 0.5 * 0.5 * <0, 1, 1>.
    const std::string layers = "background { rgb 1 }\n"
                               "sky_sphere { pigment { rgbf <0, 1, 1, 0.5> } pigment { rgbt <1, 1, 1, 0.5> } }\n";
    const StagedScene b = build_sky("#version 3.7;\n" + layers);
    check_sky(b, {0, 1, 0}, {0.5, 0.5 + 0.25 + 0.25, 0.5 + 0.25 + 0.25});
    // Before 3.7 (no #version reads as 3.62), POV-Ray 3.6's composition (Trace::ComputeSky): the
    // lower layer weighed by the upper's filter + transmit, 0.5 (a scalar, no tint), so 0.5 *
    // 0.5 * <0, 1, 1>; the background by the product of the filters (0) plus the product of the
    // transmits (0): nothing.
    check_sky(build_sky(layers), {0, 1, 0}, {0.5, 0.5 + 0.25, 0.5 + 0.25});
    check_sky(build_sky("#version 3.6;\n" + layers), {0, 1, 0}, {0.5, 0.75, 0.75});
    // One layer reads alike in both: 0.5 of its own and 0.5 of the background through it.
    check_sky(build_sky("background { rgb <0, 0, 1> }\nsky_sphere { pigment { rgbt <1, 0, 0, 0.5> } }\n"), {0, 1, 0},
              {0.5, 0, 0.5});
    // Without a background the transparent parts show black, as in POV-Ray.
    const StagedScene black = build_sky("sky_sphere { pigment { rgbt <1, 1, 1, 0.5> } }\n");
    check_sky(black, {0, 1, 0}, {0.5, 0.5, 0.5});
}

TEST_CASE("a declared sky_sphere is used by name and added to, and a bad emission is an error", "[dsl][sky]") {
    const StagedScene b = build_sky("#declare Sky = sky_sphere { pigment { gradient y color_map { [0 rgb 0] [1 rgb 1] } } }\n"
                                    "sky_sphere { Sky emission rgb 2 rotate <0, 0, 90> }\n");
    CHECK(places(b.warnings, "ignored effect").empty());
    check_sky(b, {0, 1, 0}, {0, 0, 0});  // rotated: the gradient now runs along -x
    check_sky(b, {-0.6, 0.8, 0}, {1.2, 1.2, 1.2});
    CHECK_THROWS_WITH(build_sky("sky_sphere { pigment { rgb 1 } emission rgb -1 }\n"), Contains("sky_sphere"));
}

TEST_CASE("export-pov writes background and sky_sphere back", "[dsl][sky]") {
    const StagedScene a = build_sky("background { rgb <0.1, 0.2, 0.3> }\n"
                                    "sky_sphere { pigment { gradient y color_map { [0 rgb 1] [1 rgbt <0, 0, 1, 0.5>] } } "
                                    "emission rgb 1.5 rotate <0, 0, 30> }\n");
    const auto b = dsl::build<double>(dsl::parse_string(dsl::export_pov(a.desc), "exported.pov"));
    for (const Vec3<double> d : {Vec3<double>(0, 1, 0), Vec3<double>(0.3, 0.5, -0.2), Vec3<double>(-1, 0.1, 0)}) {
        const Rgb<double> want = a.scene.environment()->radiance(glm::normalize(d));
        const Rgb<double> got = b.scene.environment()->radiance(glm::normalize(d));
        for (int c = 0; c < 3; ++c) CHECK(got[c] == Approx(want[c]).margin(1e-9));
    }
}

TEST_CASE("fog builds the library's fogs as POV-Ray reads them, with no warning", "[dsl][fog]") {
    const StagedScene b = build_sky("#declare F = fog { fog_type 2 distance 5 color rgbf <0.3, 0.4, 0.5, 0.2> fog_alt 2 }\n"
                                    "fog { F fog_offset 0.5 up <0, 0, 3> rotate <90, 0, 0> turbulence <1, 2, 3> octaves 3 }\n"
                                    "#declare Red = rgb <1, 0, 0>;\n"
                                    "fog { Red 150 }\n"  // a colour identifier first; POV-Ray 1.5's bare distance
                                    "fog { distance 0 rgb 1 }\n");  // POV-Ray skips a fog of distance 0
    CHECK(places(b.warnings, "ignored effect").empty());
    const auto fogs = b.scene.fogs();
    REQUIRE(fogs.size() == 2);
    const photon::Fog<double>& ground = fogs[0];
    CHECK(ground.kind == photon::Fog<double>::Kind::ground);
    CHECK(ground.distance == 5);
    CHECK(ground.altitude == 2);
    CHECK(ground.offset == 0.5);
    CHECK(ground.filter == Approx(0.2));
    CHECK(ground.colour[2] == Approx(0.5));
    // rotate <90, 0, 0> turns +z to -y (POV-Ray's left-handed rotation), normalised.
    CHECK(ground.up.y == Approx(-1).margin(1e-12));
    CHECK(std::abs(ground.up.z) < 1e-12);
    REQUIRE(ground.turbulence.has_value());
    CHECK(ground.turbulence->scale == Vec3<double>(1, 2, 3));
    CHECK(ground.turbulence->params.octaves == 3);
    CHECK(fogs[1].kind == photon::Fog<double>::Kind::constant);
    CHECK(fogs[1].distance == 150);
    CHECK(fogs[1].colour == Rgb<double>(1, 0, 0));
}

TEST_CASE("a fog with a negative distance or fog_alt is an error at its place, and translate is said to do nothing", "[dsl][fog]") {
    CHECK(error_of("fog { fog_type 2 distance 3 rgb 1 fog_alt -1 }\nsphere { 0, 1 }\n") ==
          "1:1: fog: a ground fog's fog_alt must be >= 0, found -1");
    CHECK(error_of("fog { distance -3 rgb 1 }\nsphere { 0, 1 }\n").rfind("1:1: fog: distance must be positive", 0) == 0);
    CHECK(error_of("sphere { 0, 1 }\nfog { fog_type 3 distance 3 }\n").rfind("2:16:", 0) == 0);
    const StagedScene b = build_sky("fog { distance 3 rgb 1 translate <0, 1, 0> }\n");
    CHECK(all_messages(b.warnings).find("cannot be translated") != std::string::npos);
}

TEST_CASE("export-pov writes fogs back", "[dsl][fog]") {
    const StagedScene a = build_sky("fog { fog_type 2 distance 5 rgbft <0.3, 0.4, 0.5, 0.2, 0.1> fog_alt 2 fog_offset 1 "
                                    "up <1, 1, 0> turbulence 0.5 turb_depth 0.3 }\nfog { distance 9 rgb 0.5 }\n");
    const auto b = dsl::build<double>(dsl::parse_string(dsl::export_pov(a.desc), "exported.pov"));
    REQUIRE(b.scene.fogs().size() == 2);
    for (std::size_t i = 0; i < 2; ++i) {
        const auto& x = a.scene.fogs()[i];
        const auto& y = b.scene.fogs()[i];
        CHECK(x.kind == y.kind);
        CHECK(x.distance == Approx(y.distance));
        CHECK(x.transmit == Approx(y.transmit));
        CHECK(glm::length(x.up - y.up) < 1e-9);
        CHECK(x.turbulence.has_value() == y.turbulence.has_value());
        if (x.turbulence) CHECK(x.turbulence->depth == Approx(y.turbulence->depth));
    }
}
