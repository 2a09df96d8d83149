// SPDX-License-Identifier: MIT
// CSG in the scene language: difference, intersection and merge with their children's own
// modifiers, inverse and hollow (POV-Ray 3.7), built into one library Csg object whose leaves keep
// their textures; children without an inside warn; inside() and trace() answer for CSG; export
// writes it back for POV-Ray; clipped_by, placed as POV-Ray places it.

#include <catch2/catch.hpp>

#include "dsl_test_util.hpp"

using namespace dsl_test;
using Catch::Matchers::Contains;

namespace {

const char* const csg_stage = "camera { location <0, 0, -5> look_at 0 }\nlight_source { <0, 5, -5>, 1 }\n";

struct CsgScene {
    dsl::SceneDescription desc;
    std::vector<dsl::Diagnostic> warnings;
    photon::DefaultScene<double> scene;
};
CsgScene build_csg(const std::string& text) {
    CsgScene b;
    dsl::ParseOptions po;
    po.diagnostics = collect(b.warnings);
    b.desc = dsl::parse_string(std::string(csg_stage) + text, "test.pov", po);
    dsl::BuildOptions bo;
    bo.diagnostics = collect(b.warnings);
    auto built = dsl::build<double>(b.desc, bo);
    b.scene = std::move(built.scene);
    b.scene.commit();
    return b;
}

using DslCsg = photon::DefaultCsg<double>;

const DslCsg& only_csg(const CsgScene& b) {
    REQUIRE(b.scene.objects().size() == 1);
    const auto* c = std::get_if<DslCsg>(&b.scene.objects()[0].shape);
    REQUIRE(c != nullptr);
    return *c;
}

photon::Ray<double> ray(photon::Vec3<double> o, photon::Vec3<double> d) { return {o, d}; }

}  // namespace

TEST_CASE("difference, intersection and merge build one CSG object, children keep their own textures", "[dsl][csg]") {
    const CsgScene b = build_csg("difference {\n"
                               "  box { -1, 1 pigment { rgb <1, 0, 0> } }\n"
                               "  sphere { 0, 0.5 pigment { rgb <0, 1, 0> } }\n"
                               "  sphere { <0, 1, 0>, 0.25 }\n"
                               "  pigment { rgb <0, 0, 1> }\n"
                               "  translate <0, 0, 3>\n"
                               "}\n");
    CHECK(places(b.warnings, "approximated object").empty());
    CHECK(places(b.warnings, "skipped object").empty());
    const DslCsg& c = only_csg(b);
    CHECK(c.op() == photon::CsgOp::difference);
    CHECK(c.leaves().size() == 3);
    CHECK(c.bounds().min.z == Approx(2));  // the first child's box, translated
    // The outer face is the red box's; the hole's wall the green sphere's (normal into the hole).
    auto hit = b.scene.intersect(ray({0, 0, -5}, {0, 0, 1}));
    REQUIRE(hit);
    CHECK(hit->hit.point.z == Approx(2));
    CHECK(hit->material->params().diffuse.x > 0);
    CHECK(hit->material->params().diffuse.y == 0);
    hit = b.scene.intersect(ray({0, 0, 3}, {0, 0, 1}));
    REQUIRE(hit);
    CHECK(hit->hit.point.z == Approx(3.5));
    CHECK(hit->hit.normal.z == Approx(-1));
    CHECK(hit->material->params().diffuse.y > 0);
    CHECK(hit->material->params().diffuse.x == 0);
    // The third child has no texture: it takes the difference's blue (its cut in the box's top).
    hit = b.scene.intersect(ray({0, 5, 3}, {0, -1, 0}));
    REQUIRE(hit);
    CHECK(hit->hit.point.y == Approx(0.75));
    CHECK(hit->material->params().diffuse.z > 0);
    CHECK(hit->material->params().diffuse.x == 0);

    const CsgScene i = build_csg("intersection { sphere { <0, 0, 0.5>, 1 } sphere { <0, 0, -0.5>, 1 } }\n");
    CHECK(only_csg(i).op() == photon::CsgOp::intersection);
    hit = i.scene.intersect(ray({0, 0, -5}, {0, 0, 1}));
    REQUIRE(hit);
    CHECK(hit->hit.point.z == Approx(-0.5));

    const CsgScene m = build_csg("merge { sphere { 0, 1 } sphere { x, 1 } pigment { rgb 1 } }\n");
    CHECK(only_csg(m).op() == photon::CsgOp::merge);
    CHECK(m.scene.objects()[0].part_materials.empty());  // one texture: no per-part materials
    hit = m.scene.intersect(ray({0.5, 0, 0}, {1, 0, 0}));  // from inside: no inner wall at x = 1
    REQUIRE(hit);
    CHECK(hit->hit.point.x == Approx(2));
}

TEST_CASE("inverse and hollow as POV-Ray reads them", "[dsl][csg]") {
    // intersection with an inverse is a difference.
    const CsgScene b = build_csg("intersection { box { -1, 1 } sphere { 0, 0.5 inverse } }\n");
    auto hit = b.scene.intersect(ray({0, 0, 0}, {1, 0, 0}));
    REQUIRE(hit);
    CHECK(hit->hit.point.x == Approx(0.5));
    CHECK(hit->hit.normal.x == Approx(-1));
    // A solid alone with inverse: a CSG of one leaf, its inside out (an air bubble in glass).
    const CsgScene bubble = build_csg("sphere { 0, 1 inverse hollow pigment { rgbf 1 } interior { ior 1.5 } }\n");
    const DslCsg& c = only_csg(bubble);
    CHECK(c.inverted());
    hit = bubble.scene.intersect(ray({0, 0, -5}, {0, 0, 1}));
    REQUIRE(hit);
    CHECK(hit->hit.normal.z == Approx(1));  // out of the glass, which is everything outside the ball
    CHECK(bubble.desc.objects[1].hollow == true);
    CHECK(places(bubble.warnings, "ignored effect").empty());
    // Twice is none.
    CHECK_FALSE(build_csg("intersection { sphere { 0, 1 inverse inverse } box { -2, 2 } }\n").desc.objects[1].inverse);
    const CsgScene tri = build_csg("triangle { 0, x, y inverse }\n");
    CHECK(places(tri.warnings, "ignored effect") == std::vector<std::string>{"3:1 inverse"});
    CHECK(tri.scene.objects().size() == 1);
}

TEST_CASE("CSG children without an inside, skipped children and lights", "[dsl][csg]") {
    CsgScene b = build_csg("merge { sphere { 0, 1 } triangle { 0, x, y } light_source { <0, 3, 0>, 1 } }\n");
    CHECK(places(b.warnings, "approximated object") == std::vector<std::string>{"3:25 merge"});
    CHECK(b.scene.objects().size() == 2);  // the sphere as a CSG leaf, the triangle on its own
    CHECK(b.scene.lights().size() == 2);
    b = build_csg("intersection { sphere { 0, 1 } mesh { triangle { 0, x, y } } }\n");
    CHECK(places(b.warnings, "skipped object") == std::vector<std::string>{"3:32 intersection"});
    CHECK(b.scene.objects().empty());
    b = build_csg("difference { box { -1, 1 } triangle { 0, x, y } }\n");
    CHECK(places(b.warnings, "approximated object") == std::vector<std::string>{"3:28 difference"});
    CHECK(b.scene.objects().size() == 1);
    // A child photon cannot read yet: cut away, it is missing (warned where it is); deciding, the
    // whole CSG is skipped.
    b = build_csg("difference { box { -1, 1 } ovus { 1, 0.5 } }\n");
    CHECK(places(b.warnings, "skipped object") == std::vector<std::string>{"3:28 ovus"});
    CHECK(b.scene.objects().size() == 1);
    b = build_csg("intersection { box { -1, 1 } ovus { 1, 0.5 } }\n");
    CHECK(places(b.warnings, "skipped object") == std::vector<std::string>{"3:30 ovus", "3:1 intersection"});
    CHECK(b.scene.objects().empty());
    b = build_csg("intersection { sphere { -3*x, 1 } sphere { 3*x, 1 } }\n");
    CHECK_THAT(all_messages(b.warnings), Contains("is empty (its objects do not overlap): nothing renders"));
    CHECK_THAT(error_of("difference { }"), Contains("1:14: expected an object in `difference`"));
    CHECK(error_of("merge { sphere { 0, 1 } pigment { rgb 1 } sphere { 0, 2 } }") ==
          "1:43: objects in `merge` must come before its modifiers: found `sphere` after a modifier");
    const Parsed one = parse("intersection { sphere { 0, 1 } }");
    CHECK_THAT(all_messages(one.warnings), Contains("`intersection` with one object is that object alone"));
}

TEST_CASE("inside() and trace() answer for CSG, export writes it back", "[dsl][csg]") {
    dsl::ParseOptions with_geometry;
    with_geometry.geometry = dsl::library_object_geometry();
    const Parsed p = parse("#declare Holed = difference { box { -1, 1 } sphere { 0, 0.5 } translate x }\n"
                           "#declare A = inside(Holed, <1, 0, 0>);\n"
                           "#declare B = inside(Holed, <1.8, 0, 0>);\n"
                           "#declare N = <0, 0, 0>;\n"
                           "#declare P = trace(Holed, <1, 0, 0>, x, N);\n"
                           "sphere { <A, B, P.x + N.x>, 1 }\n",
                           with_geometry);
    const auto& s = std::get<dsl::SphereShape>(p.desc.objects.back().shape);
    CHECK(s.center.x == 0);               // in the hole
    CHECK(s.center.y == 1);               // in the box
    CHECK(s.center.z == Approx(1.5 - 1));  // the hole's wall at x = 1.5, its normal facing the origin: -x

    const Parsed q = parse("merge { sphere { 0, 1 } sphere { x, 1 inverse } hollow }\n"
                           "intersection { box { -1, 1 } plane { y, 0 } }\n");
    const std::string pov = dsl::export_pov(q.desc);
    CHECK_THAT(pov, Contains("merge {"));
    CHECK_THAT(pov, Contains("inverse"));
    CHECK_THAT(pov, Contains("hollow on"));
    CHECK_THAT(pov, Contains("intersection {"));
    const Parsed again = parse(pov);
    REQUIRE(again.desc.objects.size() == 2);
    CHECK(std::get<dsl::CsgShape>(again.desc.objects[0].shape).children[1]->inverse);
}

TEST_CASE("clipped_by as POV-Ray places it: in the object's space where written, moved by what follows", "[dsl][csg]") {
    // The clip is written after `translate 5*x` (it stays where written: the plane x = 5 keeps
    // the sphere's half towards -x), then both move up by 1.
    const CsgScene b = build_csg("sphere { 0, 1 translate 5*x clipped_by { plane { x, 5 } } translate y }\n");
    CHECK(b.warnings.empty());
    const DslCsg& c = only_csg(b);
    CHECK(c.op() == photon::CsgOp::clip);
    // From +x: through the cut (nothing there) to the inside of the far wall at x = 4.
    auto h = b.scene.intersect(ray({10, 1, 0}, {-1, 0, 0}));
    REQUIRE(h);
    CHECK(h->hit.point.x == Approx(4));
    // From -x: the outside of the kept half; from above at x = 5.5: nothing (clipped away).
    h = b.scene.intersect(ray({-10, 1, 0}, {1, 0, 0}));
    REQUIRE(h);
    CHECK(h->hit.point.x == Approx(4));
    CHECK_FALSE(b.scene.intersect(ray({5.5, 10, 0}, {0, -1, 0})));
    CHECK(b.scene.intersect(ray({4.5, 10, 0}, {0, -1, 0})));

    // A union's clip clips each of its objects; a CSG child's clip clips that child; several
    // clip objects must all hold a point; `clipped_by { bounded_by }` clips by the bound.
    const CsgScene u = build_csg("union { sphere { 0, 1 } sphere { 3*x, 1 } clipped_by { plane { y, 0 } } }\n"
                                 "difference { box { <-1, -1, 5>, <1, 1, 7> } sphere { <0, 0, 5>, 0.5 clipped_by { plane { -z, -5 } } } }\n"
                                 "sphere { <0, 0, 10>, 1 clipped_by { plane { y, 0 } plane { x, 0 } } }\n"
                                 "sphere { <0, 0, 20>, 1 bounded_by { box { <-2, -2, 19>, <2, 0, 21> } } clipped_by { bounded_by } }\n");
    CHECK(u.warnings.empty());
    REQUIRE(u.scene.objects().size() == 5);
    for (const double x : {0.0, 3.0}) {  // through the cut to the bottom
        h = u.scene.intersect(ray({x, 10, 0}, {0, -1, 0}));
        REQUIRE(h);
        CHECK(h->hit.point.y == Approx(-1));
    }
    // The difference's sphere is clipped to z > 5: a ray along z from in front meets the box face at 5.
    h = u.scene.intersect(ray({0, 0, 4}, {0, 0, 1}));
    REQUIRE(h);
    CHECK(h->hit.point.z == Approx(5.5));  // the hemisphere's hole wall, not the box face at 5
    CHECK_FALSE(u.scene.intersect(ray({0.5, 10, 10}, {0, -1, 0})));
    CHECK(u.scene.intersect(ray({-0.5, 10, 10}, {0, -1, 0})));
    CHECK_FALSE(u.scene.intersect(ray({0, 0.5, 15}, {0, 0, 1})));  // clipped by the bound
    h = u.scene.intersect(ray({0, -0.5, 15}, {0, 0, 1}));
    REQUIRE(h);
    CHECK(h->hit.point.z == Approx(20 - std::sqrt(0.75)));

    // A mesh has no inside: its clip is ignored, with a warning at `clipped_by`.
    const CsgScene m = build_csg("mesh { triangle { 0, x, y } clipped_by { plane { y, 0.5 } } }\n");
    CHECK(places(m.warnings, "ignored effect") == std::vector<std::string>{"3:29 clipped_by"});

    // Export writes the clip where the object's transformation put it, and reads back the same.
    const Parsed p = parse("sphere { 0, 1 translate 5*x clipped_by { plane { x, 5 } } translate y }\n");
    const std::string pov = dsl::export_pov(p.desc);
    CHECK_THAT(pov, Contains("clipped_by {"));
    const CsgScene again = build_csg(pov.substr(pov.find("sphere {")));
    h = again.scene.intersect(ray({10, 1, 0}, {-1, 0, 0}));
    REQUIRE(h);
    CHECK(h->hit.point.x == Approx(4));
}

TEST_CASE("examples/scenes/csg.pov builds without warnings: four CSG objects, the cut in its cutter's red",
          "[dsl][csg][scenes]") {
    std::vector<dsl::Diagnostic> warnings;
    dsl::ParseOptions po;
    po.diagnostics = collect(warnings);
    dsl::BuildOptions bo;
    bo.diagnostics = collect(warnings);
    const auto b = dsl::load_scene<float>(std::filesystem::path(PHOTON_SCENES_DIR) / "csg.pov", po, bo);
    CHECK(warnings.empty());
    std::size_t csg = 0, targets = 0, with_parts = 0;
    for (std::uint32_t i = 0; i < b.scene.objects().size(); ++i) {
        csg += std::holds_alternative<photon::DefaultCsg<float>>(b.scene.objects()[i].shape);
        targets += b.scene.is_caustic_target(i);
        with_parts += !b.scene.objects()[i].part_materials.empty();
    }
    CHECK(b.scene.objects().size() == 9);
    CHECK(csg == 4);
    CHECK(targets == 2);     // the lens and the merged spheres
    CHECK(with_parts == 1);  // the cube cut by the red sphere
}
