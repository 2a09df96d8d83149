// SPDX-License-Identifier: MIT
// POV-Ray's finish terms in the scene language: specular/roughness, metallic, brilliance, ambient
// (with ambient_light, radiosity and #version as POV-Ray 3.7 decides) and emission read into the
// material as POV-Ray computes them, without the warnings they used to raise; bad values are
// errors at their place.

#include <catch2/catch.hpp>

#include "dsl_test_util.hpp"

#include <cmath>

using namespace dsl_test;
using namespace photon;
using Catch::Matchers::Contains;

namespace {

/// The material of `sphere { 0, 1 MODIFIERS }` after `prelude` (global settings, #version),
/// with the warnings of parsing and building.
MaterialParams<double> finish_material(const std::string& modifiers, std::vector<dsl::Diagnostic>& warnings,
                                       const std::string& prelude = "#version 3.7;\n") {
    const std::string staging = prelude + stage;
    StagedScene b = build_staged("sphere { 0, 1 " + modifiers + " }\n", {}, staging.c_str());
    warnings.insert(warnings.end(), b.warnings.begin(), b.warnings.end());
    return b.scene.material_of(0).params();
}

MaterialParams<double> finish_material(const std::string& modifiers, const std::string& prelude = "#version 3.7;\n") {
    std::vector<dsl::Diagnostic> w;
    return finish_material(modifiers, w, prelude);
}

bool finish_near(const Rgb<double>& a, const Rgb<double>& b) { return glm::length(a - b) < 1e-12; }

}  // namespace

TEST_CASE("specular, roughness, metallic and brilliance become the material's POV-Ray terms, silently", "[dsl][finish]") {
    std::vector<dsl::Diagnostic> w;
    const auto p = finish_material(
        "pigment { rgb <1, 0.5, 0.25> } finish { ambient 0 specular 0.6 roughness 0.02 metallic 0.5 brilliance 2 }", w);
    CHECK(w.empty());
    CHECK(p.blinn == 0.6);
    CHECK(p.blinn_exponent == Approx(50));  // 1 / roughness
    CHECK(p.metallic == 0.5);
    CHECK(p.highlight_color == Rgb<double>(1, 0.5, 0.25));  // the pigment, not the albedo (diffuse * pigment)
    CHECK(p.brilliance == 2);
    CHECK(p.diffuse == Rgb<double>(0.6, 0.3, 0.15));  // Lambertian albedo unchanged: photons stay Lambertian
    // POV-Ray's defaults: roughness 0.05, and `metallic` alone is metallic 1.
    const auto d = finish_material("finish { ambient 0 specular 1 metallic }");
    CHECK(d.blinn_exponent == Approx(20));
    CHECK(d.metallic == 1);
    // `albedo` scales the strength as POV-Ray 3.7 does: phong * (size + 1) / 2, specular *
    // (e + 2) / (4 (2 - 2^(-e/2))) with e = 1 / roughness.
    const auto a = finish_material("finish { ambient 0 phong albedo 0.5 phong_size 9 specular albedo 0.5 roughness 0.1 }");
    CHECK(a.phong == Approx(2.5));
    CHECK(a.blinn == Approx(0.5 * 12 / (4 * (2 - std::pow(2.0, -5.0)))));
}

TEST_CASE("ambient is POV-Ray 3.7's: pigment * opacity * ambient * ambient_light, off under radiosity", "[dsl][finish]") {
    const std::string pigment = "pigment { rgbt <1, 0.5, 0.25, 0.2> } ";  // opacity 0.8
    SECTION("without radiosity, ambient times ambient_light, silently") {
        std::vector<dsl::Diagnostic> w;
        CHECK(finish_near(finish_material(pigment, w).ambient, Rgb<double>(0.08, 0.04, 0.02)));  // POV-Ray's default 0.1
        CHECK(w.empty());
        CHECK(finish_near(finish_material(pigment + "finish { ambient rgb <0.5, 1, 2> }").ambient,
                          Rgb<double>(0.4, 0.4, 0.4)));
        CHECK(finish_near(finish_material(pigment, "#version 3.7;\nglobal_settings { ambient_light 2 }\n").ambient,
                          Rgb<double>(0.16, 0.08, 0.04)));
        CHECK(finish_material(pigment, "#version 3.7;\nglobal_settings { ambient_light 0 }\n").ambient == Rgb<double>(0));
    }
    SECTION("radiosity in a 3.7 scene switches ambient off; in an older scene (or one without #version) it stays") {
        std::vector<dsl::Diagnostic> w;
        CHECK(finish_material(pigment + "finish { ambient 1 }", w, "#version 3.7;\nglobal_settings { radiosity { } }\n")
                  .ambient == Rgb<double>(0));
        CHECK(w.empty());
        CHECK(finish_near(finish_material(pigment, "#version 3.6;\nglobal_settings { radiosity { } }\n").ambient,
                          Rgb<double>(0.08, 0.04, 0.02)));
        CHECK(finish_near(finish_material(pigment, "global_settings { radiosity { } }\n").ambient,
                          Rgb<double>(0.08, 0.04, 0.02)));
    }
    SECTION("emission adds, also under radiosity, where it warns that it lights nothing else") {
        std::vector<dsl::Diagnostic> w;
        CHECK(finish_near(finish_material(pigment + "finish { ambient 0 emission 0.5 }", w).ambient,
                          Rgb<double>(0.4, 0.2, 0.1)));
        CHECK(w.empty());
        const std::string mods = pigment + "finish { ambient 0.3 emission 0.5 }";
        CHECK(finish_near(finish_material(mods, w, "#version 3.7;\nglobal_settings { radiosity { } }\n").ambient,
                          Rgb<double>(0.4, 0.2, 0.1)));
        REQUIRE(w.size() == 1);
        CHECK_THAT(w[0].message, Contains("POV-Ray's `emission` also lights other surfaces"));
        CHECK(w[0].location.line == 5);
        CHECK(w[0].location.column == std::string("sphere { 0, 1 ").size() + mods.find("emission") + 1);
    }
    SECTION("a patterned pigment: the ambient factor, times the pattern's colours where it is evaluated") {
        const auto p = finish_material("pigment { checker rgb 1, rgb <0, 0, 1> } finish { ambient 0.5 }");
        CHECK(p.ambient == Rgb<double>(0.5));
        CHECK(p.highlight_color == Rgb<double>(1));
    }
    SECTION("negative ambient (POV-Ray darkens) is read as 0, with a warning at its place") {
        std::vector<dsl::Diagnostic> w;
        CHECK(finish_material(pigment + "finish { ambient -0.2 }", w).ambient == Rgb<double>(0));
        CHECK(places(w, "approximated finish") ==
              std::vector<std::string>{std::to_string(4) + ":" + std::to_string(std::string("sphere { 0, 1 ").size() +
                                                                                   pigment.size() + 10) +
                                       " ambient"});
    }
}

TEST_CASE("diffuse albedo warns where it would change POV-Ray's render: with brilliance", "[dsl][finish]") {
    std::vector<dsl::Diagnostic> w;
    (void)finish_material("finish { ambient 0 diffuse albedo 0.5 }", w);
    CHECK(w.empty());
    const std::string mods = "finish { ambient 0 diffuse albedo 0.5 brilliance 3 }";
    (void)finish_material(mods, w);
    CHECK(places(w, "approximated finish") ==
          std::vector<std::string>{"4:" + std::to_string(std::string("sphere { 0, 1 ").size() + mods.find("diffuse") + 1) +
                                   " diffuse"});
    REQUIRE(w.size() == 1);
    CHECK_THAT(w[0].message, Contains("(brilliance + 1) / 2 = 2"));
}

TEST_CASE("brilliance warns only where POV-Ray passes it on: radiosity and photons", "[dsl][finish]") {
    std::vector<dsl::Diagnostic> w;
    (void)finish_material("finish { ambient 0 brilliance 3 }", w, "#version 3.7;\nglobal_settings { radiosity { } }\n");
    REQUIRE(w.size() == 1);
    CHECK_THAT(w[0].message, Contains("`brilliance 3` shapes the direct light the camera sees"));
    w.clear();
    (void)finish_material("finish { ambient 0 brilliance 3 }", w);
    CHECK(w.empty());
}

TEST_CASE("bad finish values are errors at their place", "[dsl][finish][errors]") {
    const std::string s = "sphere { 0, 1 finish { ";
    const auto col = [&](const std::string& mods, const std::string& at) {
        return "1:" + std::to_string(s.size() + mods.find(at) + 1) + ": ";
    };
    CHECK(error_of(s + "roughness 0 } }") == col("roughness 0", "0") +
                                                  "`roughness` must be > 0 and finite (the Blinn exponent is 1 / "
                                                  "roughness), found 0");
    CHECK(error_of(s + "metallic 1.5 } }") == col("metallic 1.5", "1.5") + "`metallic` must be between 0 and 1, found 1.5");
    CHECK(error_of(s + "specular -1 } }") == col("specular -1", "-") + "`specular` must be >= 0, found -1");
    CHECK(error_of(s + "brilliance -2 } }") == col("brilliance -2", "-") + "`brilliance` must be >= 0, found -2");
    CHECK(error_of(s + "brilliance 0 metallic } }").empty());
}

TEST_CASE("a scene without lights shows its ambient, and says so", "[dsl][finish]") {
    const auto warning_of = [](const std::string& finish) {
        std::vector<dsl::Diagnostic> w;
        dsl::ParseOptions po;
        po.diagnostics = collect(w);
        const auto desc = dsl::parse_string("#version 3.7;\ncamera { location -5*z look_at 0 }\nsphere { 0, 1 pigment { rgb 1 } " +
                                                finish + " }\n",
                                            "test.pov", po);
        dsl::BuildOptions bo;
        bo.diagnostics = collect(w);
        (void)dsl::build<double>(desc, bo);
        return all_messages(w);
    };
    CHECK_THAT(warning_of(""), Contains("no light_source: only its surfaces' ambient and emission will show"));
    // What shows is what POV-Ray shows: a note; a black image is a warning.
    {
        std::vector<dsl::Diagnostic> w;
        dsl::BuildOptions bo;
        bo.diagnostics = collect(w);
        (void)dsl::build<double>(dsl::parse_string("camera { location -5*z look_at 0 }\nsphere { 0, 1 pigment { rgb 1 } }\n"), bo);
        REQUIRE(w.size() == 1);
        CHECK(w[0].severity == dsl::Severity::note);
    }
    CHECK_THAT(warning_of("finish { ambient 0 }"), Contains("no light_source: the image will be black"));
}
