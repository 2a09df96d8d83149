// SPDX-License-Identifier: MIT
// POV-Ray's interior fade in the scene language: fade_distance, fade_power and fade_color become
// the material's Absorption exactly as POV-Ray 3.7 computes it, silently; values that would make
// light grow are reported at their place and brought into range; export_pov writes them back.

#include <catch2/catch.hpp>

#include "dsl_test_util.hpp"

#include <cmath>

using namespace dsl_test;
using namespace photon;
using Catch::Matchers::Contains;

namespace {

/// The absorption of `sphere { 0, 1 pigment { rgbf 1 } INTERIOR }` after `prelude`, with the warnings.
Absorption<double> interior_absorption_of(const std::string& interior, std::vector<dsl::Diagnostic>& warnings,
                                          const std::string& prelude = "") {
    const std::string staging = prelude + stage;
    StagedScene b = build_staged("sphere { 0, 1 pigment { rgbf 1 } " + interior + " }\n", {}, staging.c_str());
    warnings.insert(warnings.end(), b.warnings.begin(), b.warnings.end());
    return b.scene.material_of(0).params().absorption;
}

bool mentions_fade(const std::vector<dsl::Diagnostic>& ws) { return all_messages(ws).find("fade") != std::string::npos; }

}  // namespace

TEST_CASE("interior fade_power 1000 and above is Beer-Lambert with sigma = (1 - fade_color) / fade_distance, silently",
          "[dsl][interior]") {
    std::vector<dsl::Diagnostic> w;
    const auto a = interior_absorption_of(
        "interior { ior 1.5 fade_distance 2 fade_power 1001 fade_color rgb <0.2, 0.5, 1> }", w);
    CHECK_FALSE(mentions_fade(w));
    REQUIRE(a.law() == Absorption<double>::Law::beer_lambert);
    CHECK(a.sigma().x == Approx(0.4));
    CHECK(a.sigma().y == Approx(0.25));
    CHECK(a.sigma().z == Approx(0.0).margin(1e-15));
    CHECK(a.transmittance(1.0).x == Approx(std::exp(-0.4)));
}

TEST_CASE("interior fade_power below 1000 is POV-Ray's rational fade, and fade_colour and declared interiors carry over",
          "[dsl][interior]") {
    std::vector<dsl::Diagnostic> w;
    const auto a = interior_absorption_of("interior { I fade_power 2 }", w,
                                          "#declare I = interior { ior 1.33 fade_distance 3 fade_colour rgb 0.25 }\n");
    CHECK_FALSE(mentions_fade(w));
    REQUIRE(a.law() == Absorption<double>::Law::pov_fade);
    CHECK(a.fade_distance() == 3);
    CHECK(a.fade_power() == 2);
    CHECK(a.fade_color().y == 0.25);
    CHECK(a.transmittance(3).x == Approx(0.25 + 0.75 / 2));
    // Only fade_distance: POV-Ray's fade_power 0, half of what fade_color does not keep.
    std::vector<dsl::Diagnostic> w2;
    CHECK(interior_absorption_of("interior { fade_distance 5 }", w2).transmittance(0.1).x == Approx(0.5));
    CHECK_FALSE(mentions_fade(w2));
    // fade_distance 0 (the default) is clear glass, whatever else is written.
    std::vector<dsl::Diagnostic> w3;
    CHECK_FALSE(interior_absorption_of("interior { fade_power 1001 fade_color rgb 0.5 }", w3).absorbs());
    CHECK_FALSE(mentions_fade(w3));
}

TEST_CASE("interior fade values that make light grow inside are reported at their place and brought into range",
          "[dsl][interior]") {
    std::vector<dsl::Diagnostic> w;
    const auto a = interior_absorption_of("interior {\n fade_distance 1 fade_power 1001\n fade_color rgb <1.5, 0.5, -1> }", w);
    REQUIRE(a.law() == Absorption<double>::Law::beer_lambert);
    CHECK(a.sigma().x == Approx(0.0).margin(1e-15));  // clamped to 1: no absorption, no gain
    CHECK(a.sigma().z == Approx(1.0));                // clamped to 0
    CHECK(places(w, "approximated interior") == std::vector<std::string>{"5:2 fade_color"});
    CHECK_THAT(all_messages(w), Contains("fade_color"));
    std::vector<dsl::Diagnostic> w2;
    CHECK_FALSE(interior_absorption_of("interior { fade_distance -2 }", w2).absorbs());
    CHECK_THAT(all_messages(w2), Contains("negative `fade_distance`"));
    // What is still ignored keeps its warning.
    std::vector<dsl::Diagnostic> w3;
    (void)interior_absorption_of("interior { ior 1.5 caustics 1 dispersion 1.1 }", w3);
    CHECK_THAT(all_messages(w3), Contains("interior `caustics` is ignored"));
    CHECK_THAT(all_messages(w3), Contains("interior `dispersion` is ignored"));
}

TEST_CASE("one texture under different interiors makes different materials", "[dsl][interior]") {
    const auto b = build_staged("#declare G = texture { pigment { rgbf 1 } }\n"
                                "sphere { -x, 0.5 texture { G } interior { ior 1.5 fade_distance 0.2 fade_power 1001 } }\n"
                                "sphere { x, 0.5 texture { G } interior { ior 1.5 fade_distance 0.8 fade_power 1001 } }\n");
    const Absorption<double>& left = b.scene.material_of(0).params().absorption;
    const Absorption<double>& right = b.scene.material_of(1).params().absorption;
    CHECK(left.sigma().x == Approx(5.0));
    CHECK(right.sigma().x == Approx(1.25));
}

TEST_CASE("export_pov writes the interior fade back, and reading it again gives the same absorption", "[dsl][interior]") {
    const Parsed p = parse("sphere { 0, 1 pigment { rgbf 1 } interior { ior 1.5 fade_distance 0.5 fade_power 1001 "
                           "fade_color rgb <0.8, 0.3, 0.1> } }\n");
    const std::string pov = dsl::export_pov(p.desc);
    CHECK_THAT(pov, Contains("fade_distance 0.5"));
    CHECK_THAT(pov, Contains("fade_power 1001"));
    const Parsed again = parse(pov);
    REQUIRE(again.desc.objects.size() == 1);
    const dsl::Interior& in = *again.desc.objects[0].interior;
    CHECK(in.ior == 1.5);
    CHECK(in.fade_distance == 0.5);
    CHECK(in.fade_power == 1001);
    CHECK(in.fade_color == dsl::Vector3(0.8, 0.3, 0.1));
}
