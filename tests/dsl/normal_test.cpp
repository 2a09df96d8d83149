// SPDX-License-Identifier: MIT
// `normal { ... }` in the scene language: read with its pattern, bump size and modifiers, moved
// with its texture and object as POV-Ray moves it, built into the material's normal field (the
// library's NormalPerturbation, compared at points), without warnings where photon evaluates it,
// and errors at their file:line:column.

#include <catch2/catch.hpp>

#include "dsl_test_util.hpp"

using namespace dsl_test;
using Catch::Matchers::Contains;
using photon::Vec3;

namespace {

/// build_staged with POV-Ray's default ambient turned off, whose warning is not under test here.
StagedScene build_normals(const std::string& text) { return build_staged("#default { finish { ambient 0 } }\n" + text); }

/// The largest difference between object 0's shading normal and `expected`'s, at a few points
/// of a unit sphere centred at `center`.
double normal_field_gap(const StagedScene& b, const photon::NormalPerturbation<double>& expected,
                        const Vec3<double>& center) {
    const auto& m = b.scene.material_of(0);
    REQUIRE(m.has_normal_field());
    double gap = 0;
    for (const Vec3<double>& d : {Vec3<double>(0, 1, 0), Vec3<double>(0.6, 0, -0.8), Vec3<double>(-0.48, 0.6, 0.64)}) {
        const Vec3<double> p = center + d;
        gap = std::max(gap, double(glm::length(m.shading_normal(p, d) - expected(p, d))));
    }
    return gap;
}

}  // namespace

TEST_CASE("normal patterns are read with their bump size and modifiers, without warnings", "[dsl][normal]") {
    const auto b = build_normals(
        "sphere { 0, 1 normal { bumps 0.4 scale 0.2 turbulence 0.3 octaves 4 } }\n"
        "sphere { 0, 1 normal { ripples bump_size 0.7 frequency 3 phase 0.25 } }\n"
        "sphere { 0, 1 normal { gradient x, 0.5 } }\n"
        "sphere { 0, 1 texture { pigment { rgb 1 } normal { marble 0.6 turbulence 0.5 sine_wave accuracy 0.01 } } }\n"
        "sphere { 0, 1 normal { dents } }\n"
        "sphere { 0, 1 normal { waves 1 } }\n"
        "sphere { 0, 1 normal { wrinkles 2 } }\n");
    INFO(all_messages(b.warnings));
    CHECK(b.warnings.empty());
    const auto& o = b.desc.objects;
    REQUIRE(o.size() == 8);  // the light and seven spheres
    const dsl::Normal& bumps = *o[1].texture->normal;
    CHECK(bumps.pattern->name == "bumps");
    CHECK(bumps.amount == 0.4);
    CHECK(bumps.pattern->turbulence == dsl::Vector3(0.3));
    CHECK(bumps.pattern->octaves == 4);
    CHECK(bumps.transform.linear[0][0] == Approx(0.2));
    const dsl::Normal& ripples = *o[2].texture->normal;
    CHECK(ripples.amount == 0.7);
    CHECK(ripples.pattern->frequency == 3);
    CHECK(ripples.pattern->phase == 0.25);
    const dsl::Normal& gradient = *o[3].texture->normal;
    CHECK(gradient.pattern->gradient == dsl::Vector3(1, 0, 0));
    CHECK(gradient.amount == 0.5);
    const dsl::Normal& marble = *o[4].texture->normal;
    CHECK(marble.pattern->wave == "sine_wave");
    CHECK(marble.accuracy == 0.01);
    CHECK(o[5].texture->normal->amount == 0.5);  // POV-Ray's default bump size
    for (std::uint32_t i = 0; i < 7; ++i) CHECK(b.scene.material_of(i).has_normal_field());
}

TEST_CASE("a declared normal is used and modified, and #default gives one to every texture", "[dsl][normal]") {
    const auto b = build_normals(
        "#declare N = normal { wrinkles 0.3 scale 0.2 }\n"
        "#default { normal { bump_size 1.5 } }\n"
        "sphere { 0, 1 normal { N bump_size 0.9 } }\n"
        "sphere { 0, 1 normal { bumps } }\n"
        "sphere { 0, 1 pigment { rgb 1 } }\n");
    INFO(all_messages(b.warnings));
    CHECK(b.warnings.empty());
    const auto& o = b.desc.objects;
    REQUIRE(o.size() == 4);
    CHECK(o[1].texture->normal->pattern->name == "wrinkles");
    CHECK(o[1].texture->normal->amount == 0.9);
    CHECK(o[1].texture->normal->transform.linear[1][1] == Approx(0.2));
    CHECK(o[2].texture->normal->amount == 1.5);  // the default texture's bump size
    CHECK(b.scene.material_of(0).has_normal_field());
    CHECK(b.scene.material_of(1).has_normal_field());
    CHECK_FALSE(b.scene.material_of(2).has_normal_field());  // a bump size alone is no normal
}

TEST_CASE("a normal moves with its texture and object, as the built normal field shows", "[dsl][normal]") {
    using photon::Affine;
    const auto b = build_normals("sphere { 0, 1 texture { normal { bumps 0.8 scale 0.1 } rotate <0, 30, 0> } "
                                "scale 2 translate <5, 0, 0> }\n");
    INFO(all_messages(b.warnings));
    CHECK(b.warnings.empty());
    photon::NormalPattern np;
    np.amount = 0.8;
    const auto placement = Affine<double>::scale({0.1, 0.1, 0.1})
                               .then(Affine<double>::rotate_xyz({0, 30, 0}))
                               .then(Affine<double>::scale({2, 2, 2}))
                               .then(Affine<double>::translate({5, 0, 0}));
    const photon::NormalPerturbation<double> expected(np, placement);
    CHECK(normal_field_gap(b, expected, {5, 0, 0}) < 1e-9);
    // Not where the normal would be had it stayed at the origin.
    const photon::NormalPerturbation<double> unmoved(np, Affine<double>::scale({0.1, 0.1, 0.1}));
    CHECK(normal_field_gap(b, unmoved, {5, 0, 0}) > 1e-3);
}

TEST_CASE("the slope of a pigment pattern and its modifiers build the library's slope normal", "[dsl][normal]") {
    const auto b = build_normals("sphere { 0, 1 normal { agate 0.7 agate_turb 0.5 frequency 2 accuracy 0.05 } }\n");
    INFO(all_messages(b.warnings));
    CHECK(b.warnings.empty());
    photon::NormalPattern np;
    np.kind = photon::NormalKind::slope;
    np.pattern = photon::Pattern::of(photon::PatternKind::agate);
    np.pattern.agate_turb = 0.5;
    np.pattern.wave.frequency = 2;
    np.amount = 0.7;
    np.accuracy = 0.05;
    CHECK(normal_field_gap(b, photon::NormalPerturbation<double>(np), {0, 0, 0}) < 1e-12);
}

TEST_CASE("normals photon cannot evaluate are ignored with a warning at the pattern", "[dsl][normal]") {
    const auto b = build_normals(
        "sphere { 0, 1 normal { facets 0.5 } }\n"
        "sphere { 0, 1 normal { bumps 0.5 warp { turbulence 0.2 } } }\n"
        "sphere { 0, 1 normal { bumps no_bump_scale } }\n");
    const auto ignored = places(b.warnings, "ignored effect");
    CHECK(ignored == std::vector<std::string>{"4:24 normal", "5:24 normal"});
    CHECK_THAT(all_messages(b.warnings), Contains("`normal { facets }` is ignored: photon does not evaluate this pattern"));
    CHECK_THAT(all_messages(b.warnings), Contains("`normal { bumps }` is ignored: photon does not evaluate `warp` (at"));
    CHECK_THAT(all_messages(b.warnings), Contains("`no_bump_scale` is ignored"));
    CHECK_FALSE(b.scene.material_of(0).has_normal_field());
    CHECK_FALSE(b.scene.material_of(1).has_normal_field());
    CHECK(b.scene.material_of(2).has_normal_field());  // bumps, with POV-Ray's default scaling
}

TEST_CASE("a bump size after any pattern, with or without a comma, is read", "[dsl][normal]") {
    // The forms of POV-Ray's sample scenes (balcony's water.inc, brick.pov, densfile.pov, fractals1.pov).
    const auto b = build_normals(
        "#declare A = 0.3;\n"
        "sphere { 0, 1 normal { bumps, A } }\n"
        "sphere { 0, 1 normal { function { x * y } 0.8 scale 0.3 } }\n"
        "sphere { 0, 1 normal { pigment_pattern { brick color rgb 1 color rgb 0.5 scale 0.1 } , 0.5 } }\n"
        "sphere { 0, 1 normal { magnet 1 mandel 50 .2 } }\n");
    CHECK(b.desc.objects[1].texture->normal->amount == 0.3);
    CHECK(b.scene.material_of(0).has_normal_field());
    CHECK(places(b.warnings, "ignored effect") == std::vector<std::string>{"6:24 normal", "7:24 normal", "8:24 normal"});
}

TEST_CASE("errors in a normal name their file, line and column", "[dsl][normal][errors]") {
    CHECK_THAT(error_of("sphere { 0, 1 normal { bumps accuracy 0 } }"), Contains("1:39: accuracy must be positive"));
    CHECK_THAT(error_of("#declare P = pigment { rgb 1 }\nsphere { 0, 1 normal { P } }"),
               Contains("2:24: expected a normal identifier or a normal pattern, found `P` (a pigment"));
    CHECK_THAT(error_of("sphere { 0, 1 normal { bumps noise_generator 7 } }"),
               Contains("1:24: `noise_generator 7` is not 1, 2 or 3"));
    CHECK_THAT(error_of("sphere { 0, 1 normal { bumps 0.5 "), Contains("1:"));
}

TEST_CASE("examples/scenes/normals.pov builds without warnings, and exported it builds the same normals",
          "[dsl][normal]") {
    std::vector<dsl::Diagnostic> warnings;
    dsl::ParseOptions po;
    po.diagnostics = collect(warnings);
    const auto desc = dsl::parse_file(std::filesystem::path(PHOTON_SCENES_DIR) / "normals.pov", po);
    dsl::BuildOptions bo;
    bo.diagnostics = collect(warnings);
    const auto a = dsl::build<double>(desc, bo);
    INFO(all_messages(warnings));
    CHECK(warnings.empty());
    std::size_t bumpy = 0;
    for (std::uint32_t i = 0; i < a.scene.objects().size(); ++i) bumpy += a.scene.material_of(i).has_normal_field();
    CHECK(bumpy == 8);  // the floor, the back wall, five balls and the checker ball
    const auto b = dsl::build<double>(dsl::parse_string(dsl::export_pov(desc), "exported.pov"));
    REQUIRE(b.scene.objects().size() == a.scene.objects().size());
    const Vec3<double> n = glm::normalize(Vec3<double>(0.3, 1, -0.2));
    for (std::uint32_t i = 0; i < a.scene.objects().size(); ++i)
        for (const Vec3<double>& p : {Vec3<double>(0.3, 0.01, -0.7), Vec3<double>(-0.88, 0.4, 0.2), Vec3<double>(0.6, 0.3, 1.2)}) {
            INFO("object " << i);
            const Vec3<double> x = a.scene.material_of(i).shading_normal(p, n), y = b.scene.material_of(i).shading_normal(p, n);
            CHECK(glm::length(x - y) < 1e-9);
        }
}
