// SPDX-License-Identifier: MIT
// The scene's render settings read from the file: #default textures, assumed_gamma, POV-Ray's
// global_settings keywords and photon's own, the command line's overrides, render_mode sppm, the
// render-mode headers, and the area lights of examples/scenes/area_lights.pov.

#include <catch2/catch.hpp>

#include "dsl_test_util.hpp"

using namespace dsl_test;
using namespace photon;
using Catch::Matchers::Contains;

TEST_CASE("#default changes the texture of objects written after it", "[dsl][texture]") {
    const auto b = built(std::string(stage) +
                         "sphere { 0, 1 pigment { rgb 1 } finish { ambient 0 } }\n"
                         "#default { finish { ambient 0 diffuse 1 } }\n"
                         "sphere { 0, 1 pigment { rgb 0.5 } }\n");
    CHECK(b.scene.material_of(0).diffuse() == Rgb<double>(0.6));
    CHECK(b.scene.material_of(1).diffuse() == Rgb<double>(0.5));
}

TEST_CASE("assumed_gamma and #version set the working space the image is decoded from, as POV-Ray 3.7's gamma modes",
          "[dsl][settings]") {
    using Curve = WorkingSpace::Curve;
    std::vector<dsl::Diagnostic> w;
    const std::string v37 = "#version 3.7;\n", v36 = "#version 3.6;\n";
    const auto space = [&](const std::string& text) { return built(text + std::string(stage) + "sphere { 0, 1 }\n", &w).working_space; };
    CHECK(space(v37) == WorkingSpace{Curve::power, 1.0f});  // 3.7 without assumed_gamma: linear
    CHECK(space(v37 + "global_settings { assumed_gamma 2.2 }\n") == WorkingSpace{Curve::power, 2.2f});
    CHECK(space(v36 + "global_settings { assumed_gamma 2.2 }\n") == WorkingSpace{Curve::power, 2.2f});
    CHECK(space(v36 + "global_settings { assumed_gamma 1 }\n") == WorkingSpace{Curve::power, 1.0f});
    // Older than 3.7 without assumed_gamma: gamma handling off, numbers written as they are.
    CHECK(space(v36).curve == Curve::srgb);
    CHECK(space("").curve == Curve::srgb);  // no #version reads as 3.62
    // The last #version counts: an include's `#version 3.5` restored to the 3.7 it found.
    CHECK(space("#declare Saved = version;\n#version 3.5;\n#version Saved;\n") == WorkingSpace{Curve::power, 1.0f});
    CHECK(space(v37 + "#version 3.6;\n").curve == Curve::srgb);
    CHECK(w.empty());
    CHECK_THROWS_WITH(built(std::string(stage) + "global_settings { assumed_gamma 0 }\nsphere { 0, 1 }\n"),
                      Contains("test.pov:") && Contains("`assumed_gamma` must be a positive number, found 0"));
}

TEST_CASE("render settings: POV-Ray's keywords, photon's own, then overrides", "[dsl][settings]") {
    std::vector<dsl::Diagnostic> w;
    const std::string text =
        std::string(stage) +
        "sphere { 0, 1 finish { ambient 0 } }\n"
        "global_settings { assumed_gamma 1.0 max_trace_level 6\n"
        "  photons { count 5000 gather 20, 80 radius 0.02 max_trace_level 7 } }\n"
        "#ifdef (photon_version)\n"
        "global_settings { width 320 height 200 render_mode rt global_photons 1234\n"
        "  global_estimate { count 50 radius 0.5 flatten 4 probes 8 } caustic_estimate { count 30 }\n"
        "  max_photon_depth 9 final_gather 8 shadow_samples 4 samples_per_pixel 9 irradiance_stride 2 seed 42 }\n"
        "#end\n";
    const auto b = built(text, &w);
    const RenderSettings& s = b.settings;
    CHECK(w.empty());
    CHECK(s.max_ray_depth == 6);
    CHECK(s.caustic_photons == 5000);
    CHECK(s.caustic_estimate.k == 30);
    CHECK(s.caustic_estimate.max_radius == 0.02f);
    CHECK(s.max_photon_depth == 9);
    CHECK(s.width == 320);
    CHECK(s.height == 200);
    CHECK(s.mode == RenderMode::rt);
    CHECK(s.global_photons == 1234);
    CHECK(s.global_estimate.k == 50);
    CHECK(s.global_estimate.max_radius == 0.5f);
    CHECK(s.global_estimate.flatten == 4.0f);
    CHECK(s.global_estimate.boundary_probes == 8);
    CHECK(s.final_gather_rays == 8);
    CHECK(s.shadow_samples == 4);
    CHECK(s.samples_per_pixel == 9);
    CHECK(s.irradiance_stride == 2);
    CHECK(s.seed == 42);

    dsl::SettingsOverrides o;
    o = {{"width", 40u}, {"mode", "pm"}, {"global_photons", 10u}, {"seed", 7u}, {"caustic_estimate.max_radius", 0.1}};
    const auto b2 = built(text, nullptr, o);
    CHECK(b2.settings.width == 40);
    CHECK(b2.settings.height == 200);
    CHECK(b2.settings.mode == RenderMode::pm);
    CHECK(b2.settings.global_photons == 10);
    CHECK(b2.settings.seed == 7);
    CHECK(b2.settings.caustic_estimate.max_radius == 0.1f);

    SECTION("photon's own settings outside #ifdef (photon_version) warn: POV-Ray would stop there") {
        std::vector<dsl::Diagnostic> w2;
        built(std::string(stage) + "sphere { 0, 1 finish { ambient 0 } }\nglobal_settings { global_photons 10 }\n",
              &w2);
        REQUIRE(w2.size() == 1);
        CHECK_THAT(w2[0].message, Contains("`global_photons` is photon's own setting"));
        CHECK(w2[0].location.line == 4);
        CHECK(w2[0].location.column == 19);
        std::vector<dsl::Diagnostic> w3;
        built(std::string(stage) +
                  "sphere { 0, 1 finish { ambient 0 } }\n"
                  "#if (defined(photon_version)) global_settings { seed 3 } #end\n",
              &w3);
        CHECK(w3.empty());
    }
}

TEST_CASE("render_mode sppm and its passes: from the file, the command line, and exported", "[dsl][settings]") {
    const std::string text = std::string(stage) +
                             "sphere { 0, 1 finish { ambient 0 } }\n"
                             "#ifdef (photon_version)\n"
                             "global_settings { render_mode sppm sppm_passes 12 sppm_photons 3456 }\n"
                             "#end\n";
    std::vector<dsl::Diagnostic> w;
    const auto b = built(text, &w);
    CHECK(w.empty());
    CHECK(b.settings.mode == RenderMode::sppm);
    CHECK(b.settings.sppm_passes == 12);
    CHECK(b.settings.sppm_photons_per_pass == 3456);
    dsl::SettingsOverrides o;
    o = {{"sppm_passes", 5u}, {"sppm_photons_per_pass", 77u}};
    const auto b2 = built(text, nullptr, o);
    CHECK(b2.settings.sppm_passes == 5);
    CHECK(b2.settings.sppm_photons_per_pass == 77);
    const std::string exported = dsl::export_pov(dsl::parse_string(text, "test.pov"));
    CHECK_THAT(exported, Contains("render_mode sppm") && Contains("sppm_passes 12") && Contains("sppm_photons 3456"));
    CHECK_THROWS_WITH(built(std::string(stage) + "#ifdef (photon_version) global_settings { sppm_passes 0 } #end\n"),
                      Contains("sppm_passes"));
}

TEST_CASE("POV-Ray's render-mode headers parse: radiosity is skipped, photons map to caustic settings",
          "[dsl][settings]") {
    for (const char* mode : {"rt", "rad", "rad_hq", "radphot", "radphot_hq"}) {
        INFO(mode);
        std::vector<dsl::Diagnostic> w;
        dsl::ParseOptions po;
        po.diagnostics = collect(w);
        po.include_paths = {std::filesystem::path(PHOTON_SCENES_DIR) / "povray"};
        const auto desc = dsl::parse_string(
            std::string("#include \"") + mode + ".inc\"\n" + stage + "sphere { 0, 1 finish { ambient 0 } }\n",
            "test.pov", po);
        dsl::BuildOptions bo;
        bo.diagnostics = collect(w);
        const auto b = dsl::build<float>(desc, bo);
        const bool photons = std::string(mode).find("phot") != std::string::npos;
        CHECK(desc.settings.radiosity == (std::string(mode) != "rt"));
        CHECK(desc.settings.photons.has_value() == photons);
        if (photons) {
            CHECK(b.settings.caustic_estimate.k == 100);
            CHECK(b.settings.caustic_estimate.max_radius == 0.01f);
            CHECK(b.settings.max_photon_depth == 10);
            REQUIRE(w.size() == 1);
            CHECK_THAT(w[0].message, Contains("`spacing` has no photon equivalent"));
        } else {
            CHECK(w.empty());
        }
    }
}

TEST_CASE("examples/scenes/area_lights.pov builds without a warning into POV-Ray's two grids", "[dsl][light][scenes]") {
    std::vector<dsl::Diagnostic> w;
    dsl::ParseOptions po;
    po.diagnostics = collect(w);
    dsl::BuildOptions bo;
    bo.diagnostics = collect(w);
    const auto b = dsl::build<float>(dsl::parse_file(std::string(PHOTON_SCENES_DIR) + "/area_lights.pov", po), bo);
    CHECK(w.empty());
    REQUIRE(b.scene.lights().size() == 2);
    const auto& warm = std::get<AreaLight<float>>(b.scene.lights()[0]);
    CHECK((warm.size1 == 8 && warm.size2 == 2 && warm.jitter && warm.axis1 == Vec3<float>(2, 0, 0)));
    const auto& cool = std::get<AreaLight<float>>(b.scene.lights()[1]);
    CHECK((cool.size1 == 4 && cool.size2 == 1 && !cool.jitter && cool.axis2 == Vec3<float>(0)));
    CHECK(b.settings.shadow_samples == 16);  // the largest grid, 8 x 2
}
