// SPDX-License-Identifier: MIT
// The scene language read into the expected description and library objects: expressions and
// directives, camera vectors in POV-Ray's order, light power from the unit rule, materials from
// finishes, transforms, unions with inherited textures, meshes (render settings: settings_test.cpp).

#include <catch2/catch.hpp>

#include "dsl_test_util.hpp"

#include <algorithm>
#include <cmath>

using namespace dsl_test;
using namespace photon;
using Catch::Matchers::Contains;

namespace {

constexpr double pi_d = 3.14159265358979323846;

Vec3<double> translation_of(const std::string& expr, const std::string& prelude = {}) {
    const auto p = parse(prelude + "sphere { <0,0,0>, 1 translate " + expr + " }\n");
    const auto& t = p.desc.objects.at(0).transform.translation;
    return {t.x, t.y, t.z};
}

double float_of(const std::string& expr, const std::string& prelude = {}) {
    const auto p = parse(prelude + "sphere { <0,0,0>, " + expr + " }\n");
    return std::get<dsl::SphereShape>(p.desc.objects.at(0).shape).radius;
}

MaterialParams<double> material_of(const std::string& modifiers, std::vector<dsl::Diagnostic>* warnings = nullptr) {
    const auto b = built(std::string(stage) + "sphere { 0, 1 " + modifiers + " }\n", warnings);
    return b.scene.material_of(0).params();
}

bool near(const Vec3<double>& a, const Vec3<double>& b, double eps = 1e-12) { return glm::length(a - b) <= eps; }

}  // namespace

TEST_CASE("numbers, operators, constants and functions evaluate as in POV-Ray", "[dsl][expr]") {
    CHECK(float_of("1 + 2 * 3") == 7);
    CHECK(float_of("(1 + 2) * 3") == 9);
    CHECK(float_of("-2 + 5") == 3);
    CHECK(float_of("--2") == 2);
    CHECK(float_of("10 / 4") == 2.5);
    CHECK(float_of("2 * pi") == Approx(2 * pi_d));
    CHECK(float_of("sqrt(16) + abs(-1) + pow(2, 3)") == 13);
    CHECK(float_of("max(1, 5, 3) - min(4, 2)") == 3);
    CHECK(float_of("sin(pi / 2) + cos(0)") == Approx(2));
    CHECK(float_of("degrees(atan2(1, 1))") == Approx(45));
    CHECK(float_of("int(2.7) + floor(-0.5) + ceil(0.2) + mod(7, 3)") == Approx(2 - 1 + 1 + 1));
    CHECK(float_of("1e-3 * 1000") == Approx(1));
    CHECK(float_of(".5 + 1.") == 1.5);
    CHECK(float_of("(2 < 3) + (2 = 2) + (3 != 3) + (1 & 0) + (1 | 0) + !0") == 4);
    CHECK(float_of("(2 > 1 ? 4 : 8)") == 4);  // a parameter takes comparisons in parentheses, as POV-Ray
    CHECK(float_of("vlength(<3, 4, 0>)") == 5);
    CHECK(float_of("vdot(x, y) + vlength(vcross(x, y))") == 1);
    CHECK(float_of("<1, 2, 3>.y + (x + 2*z).z") == 4);
    CHECK(float_of("R * 2", "#declare R = 0.25;\n") == 0.5);
    CHECK(float_of("select(-1, 1, 2)") == 1);
    CHECK(float_of("photon_version") == dsl::photon_version);
    CHECK(float_of("image_width / image_height") == Approx(4.0 / 3.0));
}

TEST_CASE("vectors: literals, x y z, float promotion and component-wise arithmetic", "[dsl][expr]") {
    CHECK(translation_of("<1, 2, 3>") == Vec3<double>(1, 2, 3));
    CHECK(translation_of("x*4/3") == Vec3<double>(4.0 / 3.0, 0, 0));
    CHECK(translation_of("2") == Vec3<double>(2, 2, 2));  // a float promotes to <f, f, f>
    CHECK(translation_of("<1, 2, 3> * 2 - 1") == Vec3<double>(1, 3, 5));
    CHECK(translation_of("<1, 2, 3> * <2, 0, 1>") == Vec3<double>(2, 0, 3));
    CHECK(translation_of("-<1, 2, 3>") == Vec3<double>(-1, -2, -3));
    CHECK(translation_of("<2*L, 0, -L>", "#declare L = 0.1;\n") == Vec3<double>(0.2, 0, -0.1));
    CHECK(translation_of("V + y", "#declare V = <1, 1, 1>;\n") == Vec3<double>(1, 2, 1));
    CHECK(translation_of("<1, 2>") == Vec3<double>(1, 2, 0));
    CHECK(near(translation_of("vnormalize(<0, 3, 4>)"), {0, 0.6, 0.8}));
    CHECK(near(translation_of("vrotate(x, <0, 90, 0>)"), {0, 0, -1}, 1e-15));
    CHECK(translation_of("<1 2 3>") == Vec3<double>(1, 2, 3));  // commas are optional, as in POV-Ray
    CHECK(translation_of("<1 2 -3>") == Vec3<double>(1, -1, 0));  // ... and `2 -3` is a difference there too
    // Parameters are read at the level of sums, so back-to-back vectors are two parameters
    // (POV-Ray's radiosity Cornell box writes `box { <21.3,54.87,33.2><34.3,54.88,22.7> }`).
    const auto d = dsl::parse_string("box { <0, 0, 0><1, 2, 3> }");
    const auto& b = std::get<dsl::BoxShape>(d.objects.at(0).shape);
    CHECK(b.corner2 == dsl::Vector3(1, 2, 3));
}

TEST_CASE("colours: rgb, rgbf, rgbt, rgbft, keywords and POV-Ray's float promotion", "[dsl][expr]") {
    auto pigment = [](const std::string& p, const std::string& prelude = {}) {
        const auto r = parse(prelude + "sphere { 0, 1 pigment { " + p + " } }\n");
        return r.desc.objects.at(0).texture->pigment.color;
    };
    CHECK(pigment("rgb <0.75, 0.25, 0.5>") == dsl::Color{{0.75, 0.25, 0.5}, 0, 0});
    CHECK(pigment("color rgb 0.5") == dsl::Color{{0.5, 0.5, 0.5}, 0, 0});
    CHECK(pigment("colour rgbf <1, 1, 1, 0.9>") == dsl::Color{{1, 1, 1}, 0.9, 0});
    CHECK(pigment("rgbt <1, 0, 0, 0.5>") == dsl::Color{{1, 0, 0}, 0, 0.5});
    CHECK(pigment("rgbft <1, 1, 1, 0.2, 0.3>") == dsl::Color{{1, 1, 1}, 0.2, 0.3});
    CHECK(pigment("rgb <1, 1, 1> * 0.5") == dsl::Color{{0.5, 0.5, 0.5}, 0, 0});
    CHECK(pigment("color red 1 green 0.5 filter 0.25") == dsl::Color{{1, 0.5, 0}, 0.25, 0});
    CHECK(pigment("White", "#declare White = rgb 0.75;\n") == dsl::Color{{0.75, 0.75, 0.75}, 0, 0});
    CHECK(pigment("color White transmit 0.5", "#declare White = rgb 1;\n") == dsl::Color{{1, 1, 1}, 0, 0.5});
    CHECK(pigment("color 0.5") == dsl::Color{{0.5, 0.5, 0.5}, 0.5, 0.5});  // POV-Ray fills all five
    CHECK(pigment("P", "#declare P = pigment { rgb x }\n") == dsl::Color{{1, 0, 0}, 0, 0});
}

TEST_CASE("comments, #version, #declare, #local, #undef and #ifdef", "[dsl][directives]") {
    const auto p = parse(
        "#version 3.7; // a line comment\n"
        "/* a block /* nested */ comment */\n"
        "#declare A = 1;\n"
        "#local B = A + 1;\n"
        "#declare A = A * 10;\n"
        "#ifdef (A) sphere { 0, A } #end\n"
        "#undef A\n"
        "#ifndef (A) sphere { 0, B } #else sphere { 0, 100 } #end\n");
    REQUIRE(p.desc.objects.size() == 2);
    CHECK(p.desc.version == 3.7);
    CHECK(std::get<dsl::SphereShape>(p.desc.objects[0].shape).radius == 10);
    CHECK(std::get<dsl::SphereShape>(p.desc.objects[1].shape).radius == 2);
}

TEST_CASE("#if, #elseif, #else and #while, also inside blocks", "[dsl][directives]") {
    const auto p = parse(
        "#declare N = 2;\n"
        "#if (N = 1) sphere { 0, 1 } #elseif (N = 2) sphere { 0, 2 } #else sphere { 0, 3 } #end\n"
        "#declare I = 0;\n"
        "#while (I < 3)\n"
        "  sphere { <I, 0, 0>, 0.25 #if (I = 1) no_shadow #end }\n"
        "  #declare I = I + 1;\n"
        "#end\n"
        "#if (0) this is skipped: /* even nested #if (1) #end */ #if (1) #end #end\n");
    REQUIRE(p.desc.objects.size() == 4);
    CHECK(std::get<dsl::SphereShape>(p.desc.objects[0].shape).radius == 2);
    for (int i = 0; i < 3; ++i) {
        CHECK(std::get<dsl::SphereShape>(p.desc.objects[std::size_t(i) + 1].shape).center.x == i);
        CHECK(p.desc.objects[std::size_t(i) + 1].no_shadow == (i == 1));
    }
}

TEST_CASE("#include reads a file relative to the including file, with its own #local scope", "[dsl][directives]") {
    ScratchDir dir;
    dir.write("lib/materials.inc",
              "#declare Red = texture { pigment { rgb <0.75, 0.25, 0.25> } finish { ambient 0 diffuse 1 } }\n"
              "#local Hidden = 1;\n"
              "#include \"more.inc\"\n");
    dir.write("lib/more.inc", "#declare Size = 0.5;\n");
    const auto main = dir.write("scene.pov",
                                "#include \"lib/materials.inc\"\n"
                                "#ifdef (Hidden) #error \"#local leaked\" #end\n"
                                "box { -Size, Size texture { Red } }\n");
    std::vector<dsl::Diagnostic> warnings;
    dsl::ParseOptions o;
    o.diagnostics = collect(warnings);
    const auto desc = dsl::parse_file(main, o);
    REQUIRE(desc.objects.size() == 1);
    CHECK(desc.files.size() == 3);
    CHECK(std::get<dsl::BoxShape>(desc.objects[0].shape).corner2 == dsl::Vector3(0.5));
    CHECK(desc.objects[0].texture->pigment.color.rgb == dsl::Vector3(0.75, 0.25, 0.25));
    CHECK(desc.objects[0].texture->finish.at.file_name() == desc.files[1]->name);
    CHECK(warnings.empty());

    // ParseOptions::include_paths are searched after the including file's directory.
    const auto other = dir.write("other/scene.pov", "#include \"more.inc\"\nsphere { 0, Size }\n");
    o.include_paths = {dir.path() / "lib"};
    CHECK(std::get<dsl::SphereShape>(dsl::parse_file(other, o).objects.at(0).shape).radius == 0.5);
}

TEST_CASE("ParseOptions::defines declare floats before the scene (POV-Ray's Declare=)", "[dsl][directives]") {
    dsl::ParseOptions o;
    o.defines["Quality"] = 2;
    const auto p = parse("#if (Quality > 1) sphere { 0, Quality } #end\n", o);
    CHECK(std::get<dsl::SphereShape>(p.desc.objects.at(0).shape).radius == 2);
}

TEST_CASE("the camera follows POV-Ray's order: up/right, angle, look_at, transforms", "[dsl][camera]") {
    SECTION("the paper's camera") {
        const auto p = parse(
            "camera { location <0, 0.9, -3.5> look_at <0, 0.9, 0> up y right x*4/3 angle 53.13 }\n"
            "sphere { 0, 1 }");
        const auto c = dsl::resolve_camera(*p.desc.camera, 4.0 / 3.0);
        const double focal = 0.5 * (4.0 / 3.0) / std::tan(53.13 * pi_d / 360.0);
        CHECK(near(c.location, {0, 0.9, -3.5}));
        CHECK(near(c.direction, {0, 0, focal}, 1e-12));
        CHECK(near(c.right, {4.0 / 3.0, 0, 0}));
        CHECK(near(c.up, {0, 1, 0}));
    }
    SECTION("items apply in POV-Ray's order whatever their order in the file") {
        const auto a = parse("camera { angle 90 look_at <1, 0, 0> right x up y location <0, 0, 0> }\nsphere { 0, 1 }");
        const auto b = parse("camera { location <0, 0, 0> right x up y look_at <1, 0, 0> angle 90 }\nsphere { 0, 1 }");
        const auto ca = dsl::resolve_camera(*a.desc.camera, 1), cb = dsl::resolve_camera(*b.desc.camera, 1);
        CHECK(ca.direction == cb.direction);
        CHECK(ca.right == cb.right);
        // Looking along +x in POV-Ray's left-handed frame, the right of the image is -z.
        CHECK(near(ca.direction, {0.5, 0, 0}, 1e-15));
        CHECK(near(ca.right, {0, 0, -1}));
        CHECK(near(ca.up, {0, 1, 0}));
    }
    SECTION("right defaults to the image aspect; a mirrored right keeps its sign; sky tilts the view") {
        const auto p = parse("camera { location 0 look_at z }\nsphere { 0, 1 }");
        CHECK(near(dsl::resolve_camera(*p.desc.camera, 2.0).right, {2, 0, 0}));
        const auto m = parse("camera { right -x location 0 look_at z }\nsphere { 0, 1 }");
        CHECK(near(dsl::resolve_camera(*m.desc.camera, 1).right, {-1, 0, 0}));
        const auto s = parse("camera { location 0 sky x look_at z }\nsphere { 0, 1 }");
        const auto cs = dsl::resolve_camera(*s.desc.camera, 1);
        CHECK(near(cs.up, {1, 0, 0}));
        CHECK(near(cs.right, {0, -1, 0}));
    }
    SECTION("looking along the sky, the camera keeps its right vector, as POV-Ray's does, and says so in a note") {
        std::vector<dsl::Diagnostic> notes;
        const auto down = built("camera { location 22*y up y right x look_at 0 }\nsphere { 0, 1 }", &notes);
        const auto cd = dsl::resolve_camera(*parse("camera { location 22*y up y right x look_at 0 }\nsphere { 0, 1 }").desc.camera, 1);
        CHECK(near(cd.direction, {0, -1, 0}));
        CHECK(near(cd.right, {1, 0, 0}));
        CHECK(near(cd.up, {0, 0, 1}));  // direction x right
        const auto said = std::find_if(notes.begin(), notes.end(), [](const dsl::Diagnostic& d) {
            return d.message.find("parallel to the viewing direction") != std::string::npos;
        });
        REQUIRE(said != notes.end());
        CHECK(said->severity == dsl::Severity::note);
        // A kept right that is not across the view gives a shorter up, as in POV-Ray (not normalised).
        const auto slanted = parse("camera { location 22*y right <1, 1, 0> look_at 0 }\nsphere { 0, 1 }");
        CHECK(near(dsl::resolve_camera(*slanted.desc.camera, 1).up, {0, 0, std::sqrt(0.5)}));
        // Right along the view too: no frame at all.
        const auto none = parse("camera { location 22*y right y look_at 0 }\nsphere { 0, 1 }");
        CHECK_THROWS_WITH(dsl::resolve_camera(*none.desc.camera, 1), Contains("parallel to both its sky and its right vector"));
    }
    SECTION("transformations move the resolved camera") {
        const auto p =
            parse("camera { translate <0, 0, 1> location <0, 0, -5> look_at 0 rotate <0, 90, 0> }\nsphere { 0, 1 }");
        const auto c = dsl::resolve_camera(*p.desc.camera, 1);
        CHECK(near(c.location, {-4, 0, 0}, 1e-12));  // (0, 0, -4) turned by 90 degrees about y
        CHECK(near(c.direction, {1, 0, 0}, 1e-12));
    }
    SECTION("the library camera gets the resolved vectors") {
        const auto b = built(
            "camera { location <0, 0, -5> look_at 0 up y right x*4/3 angle 60 }\n"
            "light_source { <0, 5, 0>, rgb 1 fade_distance 1 fade_power 2 }\n"
            "sphere { 0, 1 finish { ambient 0 } }\n");
        const Ray<double> centre = *b.camera.ray(0.5, 0.5);
        CHECK(near(centre.direction, {0, 0, 1}));
        const Ray<double> left = *b.camera.ray(0.0, 0.5);
        CHECK(left.direction.x < 0);  // u = 0 is the left edge: -x, as in POV-Ray
        CHECK(std::atan2(-left.direction.x, left.direction.z) * 360 / pi_d == Approx(60));
    }
}

TEST_CASE("light units: fade_power 2 makes the colour I / (2 pi D^2): oriented area lights become spheres", "[dsl][light]") {
    std::vector<dsl::Diagnostic> w;
    SECTION("a point light with the fade rule") {
        const auto b = built(
            "#declare I = 2.5; #declare D = 0.001;\n"
            "light_source { <0, 1.5, 0>, rgb I / (2*pi*D*D) fade_distance D fade_power 2 }\n"
            "camera { location -5 look_at 0 } sphere { 0, 1 finish { ambient 0 } }\n",
            &w);
        REQUIRE(b.scene.lights().size() == 1);
        const auto& l = std::get<PointLight<double>>(b.scene.lights()[0]);
        CHECK(l.position == Vec3<double>(0, 1.5, 0));
        CHECK(l.power.x == Approx(4 * pi_d * 2.5).epsilon(1e-12));
        CHECK(radiant_intensity(b.scene.lights()[0]).y == Approx(2.5).epsilon(1e-12));
        // POV-Ray's fade 2 / (1 + (d / D)^2), exactly: the physical I / d^2 far from the light.
        CHECK(l.falloff.kind == Falloff<double>::Kind::fade);
        CHECK(l.falloff.distance == 0.001);
        CHECK(l.falloff.power == 2);
        CHECK(l.casts_shadows);
        CHECK(w.empty());
    }
    SECTION("area_light ... circular orient with |A1| = |A2| = 2R is a sphere light of radius R") {
        const auto b = built(
            "light_source { <2.5, 4, 5>, rgb 1000 / (2*pi*0.001*0.001)\n"
            "  area_light <0.4, 0, 0>, <0, 0, 0.4>, 9, 9 circular orient jitter adaptive 1\n"
            "  fade_distance 0.001 fade_power 2 photons { refraction on reflection on } }\n"
            "camera { location -5 look_at 0 } sphere { 0, 1 finish { ambient 0 } }\n",
            &w);
        const auto& l = std::get<SphereLight<double>>(b.scene.lights()[0]);
        CHECK(l.center == Vec3<double>(2.5, 4, 5));
        CHECK(l.radius == Approx(0.2));
        CHECK(l.power.z == Approx(4 * pi_d * 1000).epsilon(1e-12));
        CHECK(b.settings.shadow_samples == 81);  // POV-Ray's 9 x 9 grid, as no shadow_samples is given
        CHECK(w.empty());
    }
    SECTION("a rectangular area_light is POV-Ray's grid, its axes turned and scaled with the light") {
        const auto b = built(
            "light_source { <1, 4, 0>, rgb 1 area_light <2, 0, 0>, <0, 0, 1>, 5, 3 jitter adaptive 1 area_illumination\n"
            "  scale 2 rotate y*90 }\n"
            "light_source { <0, 4, 0>, rgb 1 area_light x, z, 4, 4 circular }\n"
            "light_source { <0, 4, 0>, rgb 1 area_light x, z, 1, 1 }\n"
            "camera { location -5 look_at 0 } sphere { 0, 1 finish { ambient 0 } }\n",
            &w);
        REQUIRE(b.scene.lights().size() == 3);
        const auto& a = std::get<AreaLight<double>>(b.scene.lights()[0]);
        CHECK(near(a.center, {0, 8, -2}));
        CHECK(near(a.axis1, {0, 0, -4}));
        CHECK(near(a.axis2, {2, 0, 0}));
        CHECK((a.size1 == 5 && a.size2 == 3 && a.jitter && !a.circular));
        CHECK(radiant_intensity(b.scene.lights()[0]).x == Approx(pi_d));
        const auto& c = std::get<AreaLight<double>>(b.scene.lights()[1]);
        CHECK((c.circular && !c.jitter && c.size1 == 4));
        CHECK(std::holds_alternative<PointLight<double>>(b.scene.lights()[2]));  // a 1 x 1 grid is its centre
        CHECK(b.settings.shadow_samples == 16);  // the largest grid, as no shadow_samples is given
        CHECK(w.empty());
    }
    SECTION("an oriented grid without jitter is approximated by a sphere, and says so; a 1-wide circular grid is an error") {
        const auto b = built(
            "light_source { <0, 4, 0>, rgb 1 area_light x*2, z*3, 4, 4 orient }\n"
            "camera { location -5 look_at 0 } sphere { 0, 1 finish { ambient 0 } }\n",
            &w);
        CHECK(std::get<SphereLight<double>>(b.scene.lights()[0]).radius == Approx(1.0));  // |A1| / 2, as POV-Ray
        REQUIRE(w.size() == 1);
        CHECK(w[0].message.find("without `jitter`") != std::string::npos);
        CHECK_THROWS_WITH(built("light_source { <0, 4, 0>, rgb 1 area_light x, z, 1, 4 circular }\n"
                                "camera { location -5 look_at 0 } sphere { 0, 1 }\n"),
                          Catch::Contains("more than 1 light along each axis"));
    }
    SECTION("without a fade, POV-Ray's light does not fall off: intensity pi * colour, constant irradiance") {
        const auto b = built(
            "light_source { <0, 5, 0>, rgb <1, 2, 3> }\n"
            "camera { location -5 look_at 0 } sphere { 0, 1 finish { ambient 0 } }\n",
            &w);
        CHECK(radiant_intensity(b.scene.lights()[0]).z == Approx(3 * pi_d));
        const Falloff<double>& f = light_falloff(b.scene.lights()[0]);
        CHECK(f.kind == Falloff<double>::Kind::constant);
        CHECK(f.irradiance_per_intensity(40.0) == 1.0);
        CHECK(w.empty());
        const std::string line = "light_source { <0, 5, 0>, rgb 1 fade_distance 2 fade_power 1 }";
        const auto b1 = built(line + "\ncamera { location -5 look_at 0 } sphere { 0, 1 finish { ambient 0 } }\n", &w);
        CHECK(radiant_intensity(b1.scene.lights()[0]).x == Approx(2 * pi_d * 4));
        const Falloff<double>& f1 = light_falloff(b1.scene.lights()[0]);
        CHECK(f1.kind == Falloff<double>::Kind::fade);
        CHECK(f1.power == 1);
        // pi * colour * 2 / (1 + d / 2) at d = 6: pi / 2.
        CHECK(radiant_intensity(b1.scene.lights()[0]).x * f1.irradiance_per_intensity(6.0) == Approx(pi_d / 2));
        // fade_power 0 or fade_distance 0: POV-Ray does not fade.
        const auto b2 = built("light_source { <0, 5, 0>, rgb 1 fade_distance 2 }\n"
                              "camera { location -5 look_at 0 } sphere { 0, 1 finish { ambient 0 } }\n", &w);
        CHECK(light_falloff(b2.scene.lights()[0]).kind == Falloff<double>::Kind::constant);
        CHECK(w.empty());
    }
    SECTION("a spotlight with radius = falloff emits into that cone; others keep POV-Ray's soft profile") {
        const auto b = built(
            "light_source { <0, 5, 0>, rgb 1 / (2*pi) spotlight radius 30 falloff 30 tightness 0\n"
            "  point_at <0, 0, 0> fade_distance 1 fade_power 2 }\n"
            "camera { location -5 look_at 0 } sphere { 0, 1 finish { ambient 0 } }\n",
            &w);
        const auto& cone = light_cone(b.scene.lights()[0]);
        REQUIRE(cone);
        CHECK(near(cone->axis(), {0, -1, 0}));
        CHECK(cone->half_angle_degrees() == Approx(30));
        CHECK(radiant_intensity(b.scene.lights()[0]).x == Approx(1.0));
        CHECK(w.empty());
        const auto b2 = built(
            "light_source { <0, 5, 0>, rgb 1 spotlight point_at 0 fade_distance 1 fade_power 2 }\n"
            "camera { location -5 look_at 0 } sphere { 0, 1 finish { ambient 0 } }\n",
            &w);
        // POV-Ray's default profile: 1 inside 30 degrees, a smooth step to 0 at 45, whose power
        // over the axial intensity is 2 pi ((1 - cos 30) + (cos 30 - cos 45) / 2).
        const auto& cone2 = light_cone(b2.scene.lights()[0]);
        CHECK(cone2->half_angle_degrees() == Approx(45));
        CHECK(cone2->is_soft());
        CHECK(cone2->effective_solid_angle() ==
              Approx(2 * pi_d * ((1 - std::cos(pi_d / 6)) + (std::cos(pi_d / 6) - std::cos(pi_d / 4)) / 2)).epsilon(1e-9));
        const double c_mid = (std::cos(pi_d / 6) + std::cos(pi_d / 4)) / 2;  // halfway in cos: the step's 1/2
        CHECK(cone2->profile(Vec3<double>(std::sqrt(1 - c_mid * c_mid), -c_mid, 0)) == Approx(0.5).epsilon(1e-9));
        CHECK(w.empty());
        // POV-Ray's radiosity Cornell box: `radius -90 falloff 90 tightness 1` is a cosine lobe of power pi I.
        const auto b3 = built(
            "light_source { <0, 5, 0>, rgb 1 spotlight radius -90 falloff 90 tightness 1 point_at 0\n"
            "  fade_distance 1 fade_power 2 }\n"
            "camera { location -5 look_at 0 } sphere { 0, 1 finish { ambient 0 } }\n",
            &w);
        CHECK(light_cone(b3.scene.lights()[0])->effective_solid_angle() == Approx(pi_d).epsilon(1e-9));
    }
    SECTION("transforms move lights (and their looks_like object); shadowless casts no shadows") {
        const auto b = built(
            "light_source { <0, 1, 0>, rgb 1 fade_distance 1 fade_power 2 translate <1, 0, 0>\n"
            "  shadowless looks_like { sphere { 0, 0.1 } } }\n"
            "camera { location -5 look_at 0 } sphere { 0, 1 finish { ambient 0 } }\n",
            &w);
        CHECK(std::get<PointLight<double>>(b.scene.lights()[0]).position == Vec3<double>(1, 1, 0));
        CHECK_FALSE(std::get<PointLight<double>>(b.scene.lights()[0]).casts_shadows);
        CHECK_THAT(all_messages(w), !Contains("shadowless") && !Contains("looks_like"));
        REQUIRE(b.scene.objects().size() == 2);
        CHECK(glm::length(b.scene.object_bounding_ball(0).center - Vec3<double>(1, 1, 0)) < 1e-12);
        CHECK_FALSE(b.scene.objects()[0].options.casts_shadow);
    }
}

TEST_CASE("finishes become physical reflectances", "[dsl][material]") {
    std::vector<dsl::Diagnostic> w;
    SECTION("Lambertian: diffuse * pigment") {
        const auto p = material_of("pigment { rgb <0.75, 0.25, 0.5> } finish { ambient 0 diffuse 1 }", &w);
        CHECK(p.diffuse == Rgb<double>(0.75, 0.25, 0.5));
        CHECK(p.specular == Rgb<double>(0));
        CHECK(material_of("pigment { rgb 1 } finish { ambient 0 diffuse 0.5 }").diffuse == Rgb<double>(0.5));
        CHECK(material_of("pigment { rgb 1 } finish { ambient 0 }").diffuse == Rgb<double>(0.6));  // POV-Ray's default
        CHECK(w.empty());
    }
    SECTION("mirror: reflection { 1 } or reflection COLOR") {
        const auto p = material_of("pigment { rgb 0 } finish { ambient 0 diffuse 0 reflection { 1 } }", &w);
        CHECK(p.specular == Rgb<double>(1));
        CHECK(p.diffuse == Rgb<double>(0));
        CHECK(material_of("finish { ambient 0 diffuse 0 reflection rgb <0.9, 0.8, 0.7> }").specular ==
              Rgb<double>(0.9, 0.8, 0.7));
        CHECK(w.empty());
    }
    SECTION("glass: rgbf filter, reflection { 0, 1 fresnel on }, conserve_energy and ior") {
        const auto p = material_of(
            "pigment { rgbf <1, 1, 1, 1> } finish { ambient 0 diffuse 0 reflection { 0, 1 fresnel on } "
            "conserve_energy } interior { ior 1.5 }",
            &w);
        CHECK(p.fresnel);
        CHECK(p.ior == 1.5);
        CHECK(p.transmission == Rgb<double>(1));
        CHECK(p.specular == Rgb<double>(0));
        CHECK(p.diffuse == Rgb<double>(0));
        CHECK(w.empty());
    }
    SECTION("filter tints, transmit does not, and both take from the diffuse part") {
        const auto p = material_of("pigment { rgbft <1, 0.5, 0, 0.5, 0.25> } finish { ambient 0 diffuse 1 }");
        CHECK(near(p.diffuse, Rgb<double>(1, 0.5, 0) * 0.25));
        CHECK(near(p.transmission, {0.75, 0.5, 0.25}));
    }
    SECTION("conserve_energy without fresnel takes the reflection out of the transmission") {
        const auto p =
            material_of("pigment { rgbt <1, 1, 1, 1> } finish { ambient 0 diffuse 0 reflection 0.25 conserve_energy }");
        CHECK(near(p.transmission, Rgb<double>(0.75)));
        CHECK(near(p.specular, Rgb<double>(0.25)));
    }
    SECTION("phong and phong_size carry over") {
        const auto p = material_of("pigment { rgb 0.5 } finish { ambient 0 diffuse 1 phong 0.8 phong_size 60 }");
        CHECK(p.phong == 0.8);
        CHECK(p.phong_exponent == 60);
    }
    SECTION("what photon does not render is a warning naming it, at its place") {
        const std::string mods = "pigment { rgb 0.5 } finish { brilliance 2 crand 0.1 irid { 0.3 } }";
        material_of(mods, &w);
        const std::string all = all_messages(w);
        CHECK_THAT(all, Contains("`crand` is ignored"));
        CHECK_THAT(all, Contains("`irid` is ignored"));
        CHECK_THAT(all, !Contains("brilliance"));  // photon renders it (tests/dsl/finish_test.cpp)
        for (const auto& d : w) {
            if (d.message.find("crand") != std::string::npos) {
                CHECK(d.location.line == 3);
                CHECK(d.location.column == std::string("sphere { 0, 1 ").size() + mods.find("crand") + 1);
            }
        }
    }
    SECTION("identical materials are shared") {
        const auto b = built(std::string(stage) +
                             "#declare W = texture { pigment { rgb 0.75 } finish { ambient 0 diffuse 1 } }\n"
                             "sphere { 0, 1 texture { W } } box { 0, 1 texture { W } }\n"
                             "box { 1, 2 pigment { rgb 0.75 } finish { ambient 0 diffuse 1 } }\n");
        CHECK(b.scene.materials().size() == 1);
    }
}

TEST_CASE("transformations compose in the order written and fold into the shapes", "[dsl][transform]") {
    SECTION("rotate <0, 90, 0> takes +x to -z; rotate is x, then y, then z") {
        const auto t = dsl::Transform::rotate({0, 90, 0});
        CHECK(near(t.vector({1, 0, 0}), {0, 0, -1}, 1e-15));
        const auto xyz = dsl::Transform::rotate({90, 90, 0});
        const auto steps = dsl::Transform::rotate({90, 0, 0}).then(dsl::Transform::rotate({0, 90, 0}));
        CHECK(near(xyz.vector({0, 1, 0}), steps.vector({0, 1, 0}), 1e-15));
        // It agrees with the library's Affine::rotate_xyz.
        const auto a = Affine<double>::rotate_xyz({10, 20, 30});
        const auto d = dsl::Transform::rotate({10, 20, 30});
        CHECK(near(a.vector({0.3, -0.2, 0.9}), d.vector({0.3, -0.2, 0.9}), 1e-14));
    }
    SECTION("translate, scale and matrix") {
        const auto p = parse(
            "sphere { 0, 1 scale 2 translate <1, 0, 0> rotate <0, 0, 90> }\n"
            "sphere { 0, 1 matrix <1, 0, 0,  0, 1, 0,  0, 0, 1,  5, 6, 7> }\n");
        CHECK(near(p.desc.objects[0].transform.point({1, 0, 0}), {0, 3, 0}, 1e-15));
        CHECK(p.desc.objects[1].transform.translation == dsl::Vector3(5, 6, 7));
    }
    SECTION("similarities keep spheres and axis maps keep boxes; others are Transformed") {
        const auto b = built(std::string(stage) +
                             "sphere { <1, 0, 0>, 0.5 scale 2 rotate <0, 45, 0> translate y finish { ambient 0 } }\n"
                             "sphere { 0, 1 scale <1, 2, 1> finish { ambient 0 } }\n"
                             "box { <-0.25, 0, -0.25>, <0.25, 0.5, 0.25> rotate <0, 30, 0> translate <0.25, 0, 0.85> "
                             "finish { ambient 0 } }\n"
                             "box { 0, 1 scale <2, 1, -1> translate x finish { ambient 0 } }\n"
                             "plane { y, 1 translate <0, 2, 0> finish { ambient 0 } }\n");
        const auto& objects = b.scene.objects();
        const auto& s = std::get<Sphere<double>>(objects[0].shape);
        CHECK(s.radius() == Approx(1));
        CHECK(near(s.center(), {2 * std::cos(pi_d / 4), 1, -2 * std::sin(pi_d / 4)}, 1e-12));
        CHECK(std::holds_alternative<Transformed<Sphere<double>>>(objects[1].shape));
        const auto& cube = std::get<Transformed<Box<double>>>(objects[2].shape);
        CHECK(near(cube.to_world().point({0.25, 0, 0}),
                   {0.25 + 0.25 * std::cos(pi_d / 6), 0, 0.85 - 0.25 * std::sin(pi_d / 6)}, 1e-12));
        const auto& box = std::get<Box<double>>(objects[3].shape);
        CHECK(box.min() == Vec3<double>(1, 0, -1));
        CHECK(box.max() == Vec3<double>(3, 1, 0));
        const auto& plane = std::get<Plane<double>>(objects[4].shape);
        CHECK(near(plane.normal(), {0, 1, 0}));
        CHECK(plane.offset() == Approx(3));
    }
}

TEST_CASE("unions: textures apply to children without their own: transforms and options to all", "[dsl][union]") {
    const auto b =
        built(std::string(stage) +
              "#declare Red = texture { pigment { rgb <0.75, 0.25, 0.25> } finish { ambient 0 diffuse 1 } }\n"
              "union {\n"
              "  box { 0, 1 }\n"
              "  sphere { 0, 1 pigment { rgb 0.5 } finish { ambient 0 diffuse 1 } }\n"
              "  union { triangle { 0, x, y } }\n"
              "  texture { Red }\n"
              "  no_shadow\n"
              "  photons { target }\n"
              "  translate <0, 0, 10>\n"
              "}\n");
    const auto& objects = b.scene.objects();
    REQUIRE(objects.size() == 3);
    CHECK(b.scene.material_of(0).diffuse() == Rgb<double>(0.75, 0.25, 0.25));
    CHECK(b.scene.material_of(1).diffuse() == Rgb<double>(0.5));
    CHECK(b.scene.material_of(2).diffuse() == Rgb<double>(0.75, 0.25, 0.25));
    CHECK(std::get<Box<double>>(objects[0].shape).min() == Vec3<double>(0, 0, 10));
    CHECK(std::get<Triangle<double>>(objects[2].shape).vertex(1) == Vec3<double>(1, 0, 10));
    for (const auto& o : objects) {
        CHECK_FALSE(o.options.casts_shadow);
        CHECK(o.options.caustic_target == CausticTarget::on);
    }
}

TEST_CASE("declared objects are used with object { IDENT modifiers }", "[dsl][object]") {
    const auto b = built(std::string(stage) +
                         "#declare Ball = sphere { 0, 0.5 pigment { rgb 0.25 } finish { ambient 0 diffuse 1 } }\n"
                         "#declare Pair = union { object { Ball } object { Ball translate x } }\n"
                         "object { Pair translate <0, 2, 0> }\n"
                         "object { Ball scale 2 pigment { rgb 0.5 } }\n"
                         "#declare Lamp = light_source { <0, 0, 0>, rgb 1 fade_distance 1 fade_power 2 }\n"
                         "object { Lamp translate <0, 3, 0> }\n");
    const auto& objects = b.scene.objects();
    REQUIRE(objects.size() == 3);
    CHECK(std::get<Sphere<double>>(objects[0].shape).center() == Vec3<double>(0, 2, 0));
    CHECK(std::get<Sphere<double>>(objects[1].shape).center() == Vec3<double>(1, 2, 0));
    CHECK(std::get<Sphere<double>>(objects[2].shape).radius() == 1);
    CHECK(b.scene.material_of(2).diffuse() == Rgb<double>(0.5));
    REQUIRE(b.scene.lights().size() == 2);
    CHECK(light_center(b.scene.lights()[1]) == Vec3<double>(0, 3, 0));
}

TEST_CASE("a mesh becomes one TriangleMesh", "[dsl][mesh]") {
    const auto b = built(std::string(stage) +
                         "mesh {\n"
                         "  triangle { <0, 0, 0>, <1, 0, 0>, <0, 1, 0> }\n"
                         "  triangle { <1, 0, 0>, <1, 1, 0>, <0, 1, 0> }\n"
                         "  pigment { rgb 0.5 } finish { ambient 0 diffuse 1 }\n"
                         "  translate z\n"
                         "}\n");
    const auto& mesh = std::get<TriangleMesh<double>>(b.scene.objects()[0].shape);
    CHECK(mesh.triangle_count() == 2);
    CHECK(mesh.bounds().min == Vec3<double>(0, 0, 1));
    CHECK(mesh.bounds().max == Vec3<double>(1, 1, 1));
}

#if defined(PHOTON_HAS_OBJ) && PHOTON_HAS_OBJ
namespace {
/// Copies the OBJ fixture (a tetrahedron with corners (+-1, +-1, +-1)) into `dir` under `name`.
void copy_fixture(const ScratchDir& dir, const std::string& name) {
    std::filesystem::create_directories((dir.path() / name).parent_path());
    std::filesystem::copy_file(std::string(PHOTON_TEST_DATA_DIR) + "/tetrahedron.obj", dir.path() / name);
}
}  // namespace

TEST_CASE("mesh { obj \"file\" } reads an OBJ file relative to the scene file that names it", "[dsl][mesh][obj]") {
    ScratchDir dir;
    copy_fixture(dir, "meshes/tet.obj");
    copy_fixture(dir, "lib/parts/tet2.obj");
    dir.write("lib/part.inc", "#declare Part = mesh { obj \"parts/tet2.obj\" scale 2 }\n");  // next to lib/part.inc
    const auto scene = dir.write("scene.pov", std::string(stage) +
                                                  "#include \"lib/part.inc\"\n"
                                                  "mesh { obj \"meshes/tet.obj\" pigment { rgb 0.5 } finish { ambient 0 diffuse 1 }\n"
                                                  "       translate <0, 0, 10> }\n"
                                                  "object { Part }\n");
    std::vector<dsl::Diagnostic> warnings;
    dsl::ParseOptions po;
    po.diagnostics = collect(warnings);
    const auto desc = dsl::parse_file(scene, po);
    dsl::BuildOptions bo;
    bo.diagnostics = collect(warnings);
    const auto b = dsl::build<double>(desc, bo);
    CHECK(warnings.empty());  // Part has the default texture, with POV-Ray's ambient 0.1, which photon renders
    REQUIRE(b.scene.objects().size() == 2);
    const auto& mesh = std::get<TriangleMesh<double>>(b.scene.objects()[0].shape);
    CHECK(mesh.triangle_count() == 4);
    CHECK(mesh.bounds().min == Vec3<double>(-1, -1, 9));
    CHECK(mesh.bounds().max == Vec3<double>(1, 1, 11));
    CHECK(b.scene.material_of(0).diffuse() == Rgb<double>(0.5));
    CHECK(std::get<TriangleMesh<double>>(b.scene.objects()[1].shape).bounds().max == Vec3<double>(2));
    // The scene traces: on the z axis the tetrahedron spans z in [-1, 1], so [9, 11] moved.
    const auto hit = b.scene.intersect({{0, 0, 5}, {0, 0, 1}});
    REQUIRE(hit);
    CHECK(hit->hit.t == Approx(4));
    CHECK(hit->object == 0);

    // Errors point at the file name in the scene, and name the OBJ file's line. The build step
    // reads the file: parsing alone never opens it.
    auto error_in = [&](const std::string& text) {
        const auto f = dir.write("bad.pov", text);
        try {
            const auto d = dsl::parse_file(f);
            (void)dsl::build<double>(d);
        } catch (const dsl::Error& e) {
            return std::to_string(e.location().line) + ":" + std::to_string(e.location().column) + ": " + e.message();
        }
        return std::string("no error");
    };
    CHECK(error_in("\nmesh { obj \"meshes/none.obj\" }") ==
          "2:12: cannot find the mesh file \"meshes/none.obj\" (looked for " +
              (dir.path() / "meshes/none.obj").lexically_normal().string() + ")");
    dir.write("meshes/bad.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 4\n");
    CHECK_THAT(error_in("mesh { obj \"meshes/bad.obj\" }"),
               Catch::StartsWith("1:12: cannot read the mesh: ") &&
                   Catch::EndsWith("meshes/bad.obj:4: the face refers to vertex 4, but the file has 3 vertices before it"));
    dir.write("meshes/empty.obj", "v 0 0 0\n");
    CHECK_THAT(error_in("mesh { obj \"meshes/empty.obj\" }"), Catch::EndsWith("meshes/empty.obj has no faces"));
    CHECK(error_in("mesh { obj meshes }") == "1:12: expected a file name in double quotes after `obj`, found `meshes`");
    CHECK(error_in("mesh { pigment { rgb 1 } }") ==
          "1:8: expected `triangle` or `obj \"file.obj\"` in `mesh`, found `pigment`");
}
#endif
