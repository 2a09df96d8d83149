// SPDX-License-Identifier: MIT
// `media` in an interior and at scene level build the library's Medium (material/medium.hpp) as
// POV-Ray 3.7 reads them: coefficients (scattering scaled for photon's pi-scaled lights and its
// phase functions over 4 pi), densities moved with their media and object, declared media and
// densities, density_map entries that are densities, the lights' media flags; and export-pov
// writes them back.

#include <catch2/catch.hpp>

#include "dsl_test_util.hpp"

using namespace dsl_test;
using Catch::Matchers::Contains;
using photon::Rgb;
using photon::Vec3;

namespace {

const char* const media_stage = "camera { location <0, 0, -5> look_at 0 }\nlight_source { <0, 5, 0>, rgb 1 }\n";

StagedScene build_media_scene(const std::string& text) { return build_staged(text, {}, media_stage); }

/// The interior media of the scene's first object.
const std::vector<photon::Medium<double>>& media_of_first(const StagedScene& b) {
    REQUIRE(!b.scene.objects().empty());
    return b.scene.materials()[b.scene.objects()[0].material].params().media;
}

}  // namespace

TEST_CASE("interior media build the library's medium with POV-Ray's coefficients, and no warning", "[dsl][media]") {
    const StagedScene b = build_media_scene(
        "sphere { 0, 1 pigment { rgbt 1 } hollow interior { media { absorption <0.1, 0.2, 0.3> emission 0.5 "
        "scattering { 5, rgb 0.25 eccentricity 0.4 extinction 0.5 } intervals 3 samples 7, 9 jitter 0.3 ratio 0.7 } "
        "media { absorption 1 } } }\n");
    CHECK(all_messages(b.warnings).find("media") == std::string::npos);
    const auto& media = media_of_first(b);
    REQUIRE(media.size() == 2);
    const photon::Medium<double>& m = media[0];
    CHECK(m.absorption == Rgb<double>(0.1, 0.2, 0.3));
    CHECK(m.emission == Rgb<double>(0.5));
    // POV-Ray scatters k * 0.25 * C; photon's lights give E = pi C and its phase is k / (4 pi).
    CHECK(m.scattering == Rgb<double>(1.0));
    CHECK(m.extinction == Approx(0.125));
    CHECK(m.extinction_coefficient()[0] == Approx(0.1 + 0.5 * 0.25));  // POV-Ray's absorption + extinction * scattering
    CHECK(m.phase == photon::PhaseFunction::henyey_greenstein);
    CHECK(m.eccentricity == Approx(0.4));
    CHECK(m.sampling.intervals == 3);
    CHECK(m.sampling.samples == 7);
    CHECK(m.sampling.jitter == Approx(0.3));
    CHECK(m.sampling.ratio == Approx(0.7));
    CHECK(media[1].absorption == Rgb<double>(1.0));
    CHECK(media[1].sampling.samples == 10);  // POV-Ray's method 3 defaults
    CHECK(media[1].sampling.intervals == 1);
}

TEST_CASE("densities multiply, move with their media and object, and nest in density maps", "[dsl][media]") {
    const StagedScene b = build_media_scene(
        "#declare D = density { spherical color_map { [0 rgb 0] [1 rgb 1] } }\n"
        "#declare M = media { emission 1 density { D } }\n"
        "box { -1, 1 pigment { rgbt 1 } hollow interior { media { M density { rgb 0.5 } } } scale 2 translate x }\n");
    CHECK(all_messages(b.warnings).find("media") == std::string::npos);
    const auto& media = media_of_first(b);
    REQUIRE(media.size() == 1);
    const photon::Medium<double>& m = media[0];
    CHECK(m.emission == Rgb<double>(0.5));  // the constant density scales the coefficients
    REQUIRE(m.density.size() == 1);
    // spherical is 1 - |p| in the pattern's space, which the object's scale 2 and translate x moved.
    CHECK(m.density_at({1, 0, 0})[0] == Approx(1.0));
    CHECK(m.density_at({2, 0, 0})[0] == Approx(0.5));
    CHECK(m.density_at({1, 1.5, 0})[0] == Approx(0.25));

    // A density_map's entries are densities (POV-Ray's media5.pov): each evaluated where it lies.
    const StagedScene n = build_media_scene(
        "#declare A = density { rgb <1, 0, 0> }\n#declare B = density { gradient y color_map { [0 rgb 0] [1 rgb 1] } }\n"
        "sphere { 0, 3 pigment { rgbt 1 } interior { media { emission 1 density { gradient x "
        "density_map { [0.5 A] [0.5 B] } } } } }\n");
    CHECK(all_messages(n.warnings).find("density") == std::string::npos);
    const photon::Medium<double>& nm = media_of_first(n)[0];
    CHECK(nm.density_at({0.25, 0.7, 0}) == Rgb<double>(1, 0, 0));  // gradient x below 0.5: A
    CHECK(nm.density_at({0.75, 0.7, 0})[1] == Approx(0.7));         // above: B's gradient y
}

TEST_CASE("scene-level media are atmospheric, and lights' media flags carry over", "[dsl][media]") {
    const StagedScene b = build_media_scene(
        "media { scattering { 1, 0.02 } samples 5 method 3 }\n"
        "light_source { <1, 5, 0>, rgb 1 spotlight point_at 0 radius 10 falloff 15 media_attenuation on }\n"
        "light_source { <-1, 5, 0>, rgb 1 media_interaction off }\n"
        "sphere { 0, 1 }\n");
    CHECK(all_messages(b.warnings).find("media") == std::string::npos);
    REQUIRE(b.scene.media().size() == 1);
    CHECK(b.scene.media()[0].scattering == Rgb<double>(0.08));
    CHECK(b.scene.media()[0].sampling.samples == 5);
    const auto lights = b.scene.lights();
    REQUIRE(lights.size() == 3);
    CHECK(photon::light_media_interaction(lights[0]));
    CHECK_FALSE(photon::light_media_attenuation(lights[0]));
    CHECK(photon::light_media_attenuation(lights[1]));
    CHECK_FALSE(photon::light_media_interaction(lights[2]));
}

TEST_CASE("what photon samples differently from POV-Ray is said", "[dsl][media]") {
    const StagedScene b = build_media_scene("sphere { 0, 1 pigment { rgbt 1 } interior { media { emission 1 method 2 } } }\n"
                                            "media { scattering { 9, 0.1 } }\n");
    CHECK(places(b.warnings, "ignored effect") == std::vector<std::string>{"3:64 method"});
    CHECK_THAT(all_messages(b.warnings), Contains("unknown scattering type 9"));
    CHECK(error_of("sphere { 0, 1 interior { media { scattering { 1, 0.1 eccentricity 0.5 } } } }\n")
              .find("eccentricity") != std::string::npos);
    // Photons in media (POV-Ray's global photons `media`) are not traced: said where asked for.
    const StagedScene p = build_media_scene("global_settings { photons { count 1000 media 100 } }\nsphere { 0, 1 }\n");
    CHECK_THAT(all_messages(p.warnings), Contains("photons `media` is ignored"));
}

TEST_CASE("export-pov writes media back", "[dsl][media]") {
    const StagedScene a = build_media_scene(
        "media { scattering { 4, rgb <0.1, 0.2, 0.3> extinction 0.7 } intervals 2 jitter 0.5 }\n"
        "light_source { <0, 5, 0>, rgb 1 media_interaction off media_attenuation on }\n"
        "sphere { 0, 1 pigment { rgbt 1 } interior { ior 1.2 media { absorption 0.3 emission <1, 0, 0> "
        "density { spherical color_map { [0 rgb 0] [1 rgb 1] } scale 0.5 } density { rgb 0.8 } } } translate y }\n");
    const auto b = dsl::build<double>(dsl::parse_string(dsl::export_pov(a.desc), "exported.pov"));
    REQUIRE(b.scene.media().size() == 1);
    CHECK(b.scene.media()[0].scattering == a.scene.media()[0].scattering);
    CHECK(b.scene.media()[0].extinction == Approx(a.scene.media()[0].extinction));
    CHECK(b.scene.media()[0].phase == photon::PhaseFunction::rayleigh);
    CHECK(b.scene.media()[0].sampling.intervals == 2);
    CHECK_FALSE(photon::light_media_interaction(b.scene.lights()[1]));
    CHECK(photon::light_media_attenuation(b.scene.lights()[1]));
    const auto& ma = a.scene.materials()[a.scene.objects()[0].material].params().media;
    const auto& mb = b.scene.materials()[b.scene.objects()[0].material].params().media;
    REQUIRE(mb.size() == 1);
    CHECK(mb[0].absorption[0] == Approx(ma[0].absorption[0]));
    for (const Vec3<double> p : {Vec3<double>(0, 1, 0), Vec3<double>(0.2, 1.1, 0), Vec3<double>(0, 0.7, 0.1)})
        CHECK(mb[0].density_at(p)[0] == Approx(ma[0].density_at(p)[0]));
}

TEST_CASE("a hollow glass inside media is said to stay clear, and an emitting media lights a scene without lights",
          "[dsl][media]") {
    const StagedScene b = build_media_scene(
        "sphere { 0, 2 pigment { rgbf 1 } hollow interior { media { emission 0.1 } } }\n"
        "sphere { 0, 1 pigment { rgbt 0.9 } interior { ior 1.1 } hollow yes }\n"
        "sphere { 3*x, 1 pigment { rgbt 0.9 } interior { ior 1.1 } }\n");
    CHECK(places(b.warnings, "approximated media") == std::vector<std::string>{"4:1 hollow"});
    const StagedScene dark = build_staged("sphere { 0, 1 pigment { rgbt 1 } interior { media { emission 1 } } }\n", {},
                                          "camera { location <0, 0, -5> look_at 0 }\n");
    CHECK_THAT(all_messages(dark.warnings), Contains("only emission (of surfaces and media) and ambient will show"));
}
