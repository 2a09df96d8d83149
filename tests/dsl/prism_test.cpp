// SPDX-License-Identifier: MIT
// prism in the scene language: POV-Ray 3.7's points for each spline type (extra control points of
// quadratic and cubic splines, four points per Bezier curve, sub-outlines closed by their first
// point), both sweeps, open, built as a Transformed library Prism, in CSG, located errors, skipped
// with a warning where POV-Ray draws nothing, written back by export-pov, and min_extent,
// max_extent and inside() with POV-Ray's numbers (from povray 3.7 with #debug).

#include <catch2/catch.hpp>

#include "dsl_test_util.hpp"

#if defined(PHOTON_HAS_FREETYPE) && PHOTON_HAS_FREETYPE
#include <ft2build.h>
#include FT_FREETYPE_H
#include FT_OUTLINE_H
#endif

using namespace dsl_test;
using namespace photon;
using Catch::Matchers::Contains;

namespace {

dsl::Vector3 prism_query(const std::string& declare, const std::string& expression) {
    dsl::ParseOptions o;
    o.geometry = dsl::library_object_geometry();
    const auto p = parse(declare + "\nsphere { " + expression + ", 1 }", o);
    return std::get<dsl::SphereShape>(p.desc.objects.at(0).shape).center;
}

bool prism_close(const dsl::Vector3& a, const dsl::Vector3& b, double eps = 1e-6) { return glm::length(a - b) <= eps; }

}  // namespace

TEST_CASE("prism: each spline type's points, with POV-Ray's extents", "[dsl][prism]") {
    // Values printed by POV-Ray 3.7 (min_extent | max_extent) for the same declarations.
    const std::string q = "#declare Q = prism { quadratic_spline 0, 1, 6, <0,-1>, <1,0>, <0,1>, <-1,0>, <0,-1>, <1,0> }";
    CHECK(prism_close(prism_query(q, "min_extent(Q)"), {-1, 0, -1}));
    CHECK(prism_close(prism_query(q, "max_extent(Q)"), {1, 1, 1}));
    const std::string c =
        "#declare C = prism { cubic_spline -1, 2, 7, <0,-1>, <1,0>, <0,1>, <-1,0>, <0,-1>, <1,0>, <0,1> }";
    CHECK(prism_close(prism_query(c, "min_extent(C)"), {-1, -1, -1}));
    CHECK(prism_close(prism_query(c, "max_extent(C)"), {1, 2, 1}));
    const std::string k = "#declare K = prism { conic_sweep linear_spline 1, 0.5, 4, <-1,-1>, <2,-1>, <0,1>, <-1,-1> }";
    CHECK(prism_close(prism_query(k, "min_extent(K)"), {-1, 0.5, -1}));
    CHECK(prism_close(prism_query(k, "max_extent(K)"), {2, 1, 1}));
    // The quadratic spline passes through its points (not its first, a control point): the
    // diamond's corner <1, 0> is on the surface, and the side between corners bulges out.
    CHECK(prism_query(q, "<inside(Q, <0.99, 0.5, 0>), inside(Q, <0.55, 0.5, 0.55>), inside(Q, <1.01, 0.5, 0>)>") ==
          dsl::Vector3(1, 1, 0));
    // Conic: inside at height 0.75 is the outline scaled by 0.75.
    CHECK(prism_query(k, "<inside(K, <1.4, 0.75, -0.7>), inside(K, <1.6, 0.75, -0.7>), inside(K, <0, 0.4, 0>)>") ==
          dsl::Vector3(1, 0, 0));
    // Two sub-outlines (a square with a square hole) in a linear prism, rendered.
    const StagedScene b = build_staged("prism { linear_sweep linear_spline 0, 1, 10, <-2,-2>, <2,-2>, <2,2>, <-2,2>, <-2,-2>,"
                                       " <-1,-1>, <1,-1>, <1,1>, <-1,1>, <-1,-1> translate y }\n");
    CHECK(b.warnings.empty());
    only<Transformed<Prism<double>>>(b);
    auto h = shoot(b, {1.5, 5, 0}, {0, -1, 0});
    REQUIRE(h);
    CHECK(h->t == Approx(3));
    CHECK(h->normal.y == Approx(1));
    CHECK_FALSE(shoot(b, {0, 5, 0}, {0, -1, 0}));
    h = shoot(b, {0, 1.5, 0}, {1, 0, 0});  // from the hole: its wall, facing in
    REQUIRE(h);
    CHECK(h->t == Approx(1));
    CHECK(h->normal.x == Approx(-1));
    // A Bezier prism: four points per curve, <1, 0> to <0, 1> to <1, 0>.
    const StagedScene z = build_staged("prism { bezier_spline 0, 1, 8, <1,0>, <1,0.5>, <0.5,1>, <0,1>,"
                                       " <0,1>, <-1,1>, <-1,-1>, <1,0> open }\n");
    CHECK(z.warnings.empty());
    CHECK_FALSE(shoot(z, {0.3, 5, 0.3}, {0, -1, 0}));  // open: no caps
    h = shoot(z, {5, 0.5, 0.25}, {-1, 0, 0});
    REQUIRE(h);
    CHECK(h->normal.x > 0.5);
}

TEST_CASE("prism: closing, errors and skips as POV-Ray", "[dsl][prism][errors]") {
    CHECK_THAT(error_of("prism { 0, 1, 2, <0,0>, <1,0> }"), Contains("1:15: a prism with linear splines needs at least 3 points"));
    CHECK_THAT(error_of("prism { quadratic_spline 0, 1, 4, <0,0>, <1,0>, <1,1>, <0,0> }"),
               Contains("1:32: a prism with quadratic splines needs at least 5 points"));
    CHECK_THAT(error_of("prism { bezier_spline 0, 1, 6, <0,0>, <1,0>, <1,1>, <0,0>, <0,0>, <0,0> }"),
               Contains("1:29: a prism with Bezier splines needs 4 points per segment"));
    CHECK_THAT(error_of("prism { 0, 1, 4, <0,0>, <1,0>, <1,1> }"), Contains("expected point 4 of the prism"));
    // A linear outline left open is closed, as POV-Ray closes it; a curved one is skipped.
    const StagedScene b = build_staged("prism { 0, 1, 3, <0,0>, <1,0>, <0,1> }\n"
                                       "prism { cubic_spline 0, 1, 6, <0,0>, <1,0>, <1,1>, <0,1>, <0,2>, <3,3> }\n"
                                       "prism { 1, 1, 4, <0,0>, <1,0>, <0,1>, <0,0> }\n");
    REQUIRE(b.scene.objects().size() == 1);
    CHECK(b.scene.object_bounds(0).max.x == Approx(1));
    CHECK(places(b.warnings, "skipped object") == std::vector<std::string>{"4:28 prism", "5:9 prism"});
    CHECK_THAT(all_messages(b.warnings), Contains("its outline is not closed"));
}

TEST_CASE("prism: in CSG, transformed, exported, no longer skipped", "[dsl][prism][csg][export]") {
    // Engraving: a slab minus a prism reaching into it from above.
    const StagedScene b = build_staged("difference { box { <-2, 0, -2>, <2, 1, 2> }"
                                       " prism { 0.5, 2, 4, <-1,-1>, <1,-1>, <0,1>, <-1,-1> } pigment { rgb 1 } }\n");
    REQUIRE(b.scene.objects().size() == 1);
    auto h = shoot(b, {0, 5, -0.5}, {0, -1, 0});
    REQUIRE(h);
    CHECK(h->t == Approx(4.5));  // the engraving's floor
    h = shoot(b, {1.5, 5, 1.5}, {0, -1, 0});
    REQUIRE(h);
    CHECK(h->t == Approx(4));  // the slab's top beside it
    // Rotated and scaled like any object: lying along z, twice as wide.
    const StagedScene r = build_staged("prism { 0, 1, 4, <0,0>, <1,0>, <0,1>, <0,0> rotate -90*x scale <2, 1, 1> }\n");
    h = shoot(r, {0.5, 0.25, -5}, {0, 0, 1});
    REQUIRE(h);
    CHECK(h->t == Approx(4));  // the cap at y = 1, turned to z = -1 (rotate -90*x takes y to -z)
    CHECK(h->normal.z == Approx(-1));
    // export-pov writes a Bezier prism that reads back to the same outline.
    const std::string text = std::string(stage) +
                             "prism { conic_sweep quadratic_spline 0.5, 1, 6, <0,-1>, <1,0>, <0,1>, <-1,0>, <0,-1>, <1,0> open }\n";
    const std::string exported = dsl::export_pov(dsl::parse_string(text, "p.pov"));
    CHECK_THAT(exported, Contains("prism { bezier_spline conic_sweep 0.5, 1, 16, <1, 0>"));
    CHECK_THAT(exported, Contains(" open"));
    const std::string twice = dsl::export_pov(dsl::parse_string(exported, "exported.pov"));
    CHECK(twice.substr(twice.find('\n')) == exported.substr(exported.find('\n')));
    CHECK_THAT(all_messages(build_staged("prism { 0, 1, 4, <0,0>, <1,0>, <0,1>, <0,0> }\n").warnings), !Contains("prism"));
}

#if defined(PHOTON_HAS_FREETYPE) && PHOTON_HAS_FREETYPE

TEST_CASE("text: glyphs of a TrueType font, placed as POV-Ray places them", "[dsl][text]") {
    dsl::ParseOptions o;
    o.include_paths = {"/usr/share/povray-3.7/include"};
    o.geometry = dsl::library_object_geometry();
    const auto extent = [&](const std::string& text, const char* which) {
        const auto p = parse("#declare T = " + text + "\nsphere { " + which + "(T), 1 }", o);
        return std::get<dsl::SphereShape>(p.desc.objects.at(0).shape).center;
    };
    // POV-Ray 3.7 with #debug: min_extent | max_extent. Kerning pulls V under A (-0.187 em) and o
    // under T; POV-Ray's boxes are padded by up to about 1e-4 (float boxes and a tolerance).
    const std::string t = "text { ttf \"timrom.ttf\" \"AVTo W\" 1, 0 }";
    CHECK(prism_close(extent(t, "min_extent"), {-0.000012147, -0.016017454, -0.000063046}, 2e-4));
    CHECK(prism_close(extent(t, "max_extent"), {3.539017677, 0.696061730, 1.000013113}, 2e-4));
    // Commas between the items are optional, and `.ttf` is added to a name without an extension.
    const std::string u = "text { ttf \"crystal\", \"Photon 3.7\", 0.25, <0.1, 0.05, 0> }";
    CHECK(prism_close(extent(u, "min_extent"), {-0.000020108, -0.000980926, -0.000104869}, 2e-4));
    CHECK(prism_close(extent(u, "max_extent"), {5.950297356, 1.152252316, 0.250021100}, 2e-4));

    // Hits lie on the glyphs: a ray along -z through the middle of the l of "l" hits its front
    // face at z = 0; between the two stems of "H" it misses.
    const StagedScene b = build_staged("text { ttf \"timrom.ttf\" \"lH\" 0.5, 0 }\n", o);
    REQUIRE(b.scene.objects().size() == 1);
    const auto box = b.scene.object_bounds(0);
    const auto& text_solid = only<Transformed<Prism<double>>>(b);
    CHECK(box.min.z == Approx(0).margin(1e-9));
    CHECK(box.max.z == Approx(0.5).margin(1e-9));
    int front = 0, rays = 0;
    for (double x = box.min.x; x < box.max.x; x += 0.01) {
        const auto h = shoot(b, {x, 0.3, -5}, {0, 0, 1});
        ++rays;
        if (!h) continue;
        ++front;
        CHECK(h->point.z == Approx(0).margin(1e-9));
        CHECK(h->normal.z == Approx(-1));
        // Just behind the front face is inside the glyph's solid; in front of it is not.
        CHECK(text_solid.contains({x, 0.3, 0.25}));
        CHECK_FALSE(text_solid.contains({x, 0.3, -0.01}));
    }
    CHECK(front > 5);
    CHECK(front < rays);  // gaps between the stems
    CHECK(b.warnings.empty());
}

TEST_CASE("text: a glyph's hits are where FreeType's own rasterizer fills its pixels", "[dsl][text]") {
    // FreeType renders "g" (curves, a closed bowl, a hole) unhinted at 200 pixels per em; every
    // pixel it fills wholly must be hit at its centre by a ray along +z, every pixel it leaves
    // empty missed. photon's glyph starts at x = -xMin (POV-Ray's first-glyph rule).
    const char* font_path = "/usr/share/povray-3.7/include/timrom.ttf";
    FT_Library library = nullptr;
    FT_Face face = nullptr;
    REQUIRE(FT_Init_FreeType(&library) == 0);
    REQUIRE(FT_New_Face(library, font_path, 0, &face) == 0);
    const int ppem = 200;
    REQUIRE(FT_Set_Pixel_Sizes(face, 0, ppem) == 0);
    const FT_UInt glyph = FT_Get_Char_Index(face, 'g');
    REQUIRE(FT_Load_Glyph(face, glyph, FT_LOAD_NO_HINTING | FT_LOAD_NO_BITMAP) == 0);
    FT_BBox box;
    FT_Outline_Get_CBox(&face->glyph->outline, &box);  // 26.6 pixels
    REQUIRE(FT_Render_Glyph(face->glyph, FT_RENDER_MODE_NORMAL) == 0);
    const FT_Bitmap& bitmap = face->glyph->bitmap;
    const double x_min = double(box.xMin) / 64.0;  // pixels
    dsl::ParseOptions o;
    o.include_paths = {"/usr/share/povray-3.7/include"};
    const StagedScene b = build_staged("text { ttf \"timrom.ttf\" \"g\" 1, 0 }\n", o);
    int full = 0, empty = 0, wrong = 0;
    for (unsigned row = 0; row < bitmap.rows; ++row)
        for (unsigned col = 0; col < bitmap.width; ++col) {
            const unsigned char coverage = bitmap.buffer[row * unsigned(bitmap.pitch) + col];
            if (coverage != 0 && coverage != 255) continue;  // an edge pixel
            const double px = double(face->glyph->bitmap_left) + double(col) + 0.5;
            const double py = double(face->glyph->bitmap_top) - double(row) - 0.5;
            const bool hit = shoot(b, {(px - x_min) / ppem, py / ppem, -5}, {0, 0, 1}).has_value();
            (coverage == 255 ? full : empty) += 1;
            wrong += hit != (coverage == 255);
        }
    FT_Done_Face(face);
    FT_Done_FreeType(library);
    CHECK(full > 3000);
    CHECK(empty > 3000);
    CHECK(wrong == 0);
}

TEST_CASE("text: a missing font is a located error, text in CSG engraves", "[dsl][text][errors]") {
    CHECK_THAT(error_of("text { ttf \"no-such-font.ttf\" \"x\" 1, 0 }"),
               Contains("1:12: cannot find the font file \"no-such-font.ttf\""));
    CHECK_THAT(error_of("text { \"timrom.ttf\" \"x\" 1, 0 }"), Contains("1:8: expected `ttf` or `internal` and a font"));
    const StagedScene internal = build_staged("text { internal 1 \"POV-Ray\" 1, 0 }\n");
    CHECK(internal.scene.objects().empty());
    CHECK(places(internal.warnings, "skipped object") == std::vector<std::string>{"3:8 text"});
    dsl::ParseOptions o;
    o.include_paths = {"/usr/share/povray-3.7/include"};
    // An "I" cut 0.1 deep into the front of a slab: a ray down its stem meets the engraving's floor.
    const StagedScene b = build_staged("difference { box { <-1, -1, 0>, <2, 2, 1> }"
                                       " text { ttf \"timrom.ttf\" \"I\" 0.2, 0 translate -0.1*z } }\n",
                                       o);
    REQUIRE(b.scene.objects().size() == 1);
    const auto floor = shoot(b, {0.15, 0.3, -5}, {0, 0, 1});
    REQUIRE(floor);
    CHECK(floor->point.z == Approx(0.1));
    const auto top = shoot(b, {1.5, 0.3, -5}, {0, 0, 1});
    REQUIRE(top);
    CHECK(top->point.z == Approx(0).margin(1e-9));
    const std::string exported = dsl::export_pov(
        dsl::parse_string(std::string(stage) + "text { ttf \"timrom.ttf\" \"a\\\"b\" 1, 0 }\n", "t.pov", o));
    CHECK_THAT(exported, Contains("timrom.ttf\" \"a\\\"b\" 1, <0, 0, 0>"));
}

TEST_CASE("examples/scenes/prism_text.pov reads and builds with no warning", "[dsl][prism][text][scenes]") {
    std::vector<dsl::Diagnostic> warnings;
    dsl::ParseOptions po;
    po.diagnostics = collect(warnings);
    po.include_paths = dsl::standard_include_paths();
    dsl::BuildOptions bo;
    bo.diagnostics = collect(warnings);
    const auto built = dsl::build<float>(dsl::parse_file(std::string(PHOTON_SCENES_DIR) + "/prism_text.pov", po), bo);
    CHECK(all_messages(warnings).empty());
    int prisms = 0, csg = 0;
    for (const auto& o : built.scene.objects()) {
        prisms += std::holds_alternative<Transformed<Prism<float>>>(o.shape);
        csg += std::holds_alternative<DefaultCsg<float>>(o.shape);
    }
    CHECK(prisms == 5);  // four prisms and the word
    CHECK(csg == 1);     // the engraved slab
}

#endif
