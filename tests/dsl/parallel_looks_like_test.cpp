// SPDX-License-Identifier: MIT
// POV-Ray's `parallel` lights and `looks_like` objects in the scene language: a parallel light
// builds photon's ParallelLight with no warning (its irradiance from POV-Ray's colour, its cone
// ignored as POV-Ray 3.7 ignores it, its fade of the plane distance), export_pov writes it back;
// a looks_like object sits at the light, casts no shadow and lets photons through, so the floor
// under it is lit as without it while the camera sees it.

#include <catch2/catch.hpp>

#include "dsl_test_util.hpp"

#include <cmath>

using namespace dsl_test;
using namespace photon;
using Catch::Matchers::Contains;

namespace {

constexpr double pll_pi = 3.14159265358979323846;

dsl::BuiltScene<double> build_pov(const std::string& text, std::vector<dsl::Diagnostic>& warnings) {
    dsl::ParseOptions po;
    po.diagnostics = collect(warnings);
    const auto desc = dsl::parse_string(text, "test.pov", po);
    dsl::BuildOptions bo;
    bo.diagnostics = collect(warnings);
    return dsl::build<double>(desc, bo);
}

}  // namespace

TEST_CASE("a parallel light builds photon's ParallelLight with no warning", "[dsl][light][parallel]") {
    std::vector<dsl::Diagnostic> w;
    const auto b = build_pov("camera { location <0, 2, -5> look_at 0 }\n"
                             "light_source { <0, 10, 0>, rgb <1, 0.5, 0.25> parallel point_at <3, 6, 0> translate x }\n"
                             "box { <-2, -0.1, -2>, <2, 0, 2> }\n",
                             w);
    CHECK(w.empty());
    REQUIRE(b.scene.lights().size() == 1);
    const auto* light = std::get_if<ParallelLight<double>>(&b.scene.lights()[0]);
    REQUIRE(light);
    CHECK(light->position == Vec3<double>(1, 10, 0));
    CHECK(glm::length(light->direction - glm::normalize(Vec3<double>(3, -4, 0))) < 1e-12);
    // pi colour: a white Lambertian surface facing it shows the colour, as in POV-Ray.
    CHECK(light->irradiance.x == Approx(pll_pi));
    CHECK(light->irradiance.y == Approx(0.5 * pll_pi));
    CHECK(light->beam_radius > 2.8);  // covers the box (half-diagonal 2.83)
    CHECK(light->casts_shadows);

    // A parallel spotlight: POV-Ray 3.7's cone has no effect on it; with a fade, 2 pi colour
    // and POV-Ray's 1 / (1 + (d / D)^p) of the plane distance.
    std::vector<dsl::Diagnostic> w2;
    const auto s = build_pov("camera { location <0, 2, -5> look_at 0 }\n"
                             "light_source { <0, 10, 0>, 1 spotlight radius 5 falloff 8 parallel point_at 0\n"
                             "  fade_distance 4 fade_power 2 shadowless }\n"
                             "box { <-2, -0.1, -2>, <2, 0, 2> }\n",
                             w2);
    CHECK(w2.empty());
    const auto& spot = std::get<ParallelLight<double>>(s.scene.lights()[0]);
    CHECK(spot.irradiance.x == Approx(2 * pll_pi));
    CHECK_FALSE(spot.casts_shadows);
    CHECK_FALSE(light_cone(s.scene.lights()[0]).has_value());
    // At the floor, 10 below the plane: 2 pi / (1 + (10 / 4)^2), at its edge (x = 2) too.
    for (const double x : {0.0, 2.0}) {
        const auto in = sample_incident(s.scene.lights()[0], Vec3<double>(x, 0, 0), Vec2<double>(0.5));
        REQUIRE(in);
        CHECK(in->irradiance.x == Approx(2 * pll_pi / (1 + 6.25)));
    }

    // An area light with it is approximated, and says so.
    std::vector<dsl::Diagnostic> w3;
    build_pov("light_source { <0, 10, 0>, 1 area_light x, z, 3, 3 parallel point_at 0 }\nsphere { 0, 1 }\n", w3);
    CHECK(places(w3, "approximated light") == std::vector<std::string>{"1:30 area_light"});

    // export_pov writes it back as POV-Ray reads it.
    const Parsed p = parse("light_source { <0, 10, 0>, 1 parallel point_at <1, 2, 3> }\n");
    const std::string pov = dsl::export_pov(p.desc);
    CHECK_THAT(pov, Contains("parallel point_at <1, 2, 3>"));
    const Parsed again = parse(pov);
    const auto& l = std::get<dsl::LightSource>(again.desc.objects.at(0).shape);
    CHECK(l.parallel);
    CHECK(l.point_at == dsl::Vector3(1, 2, 3));
}

TEST_CASE("looks_like: the object at the light, casting no shadow, photons passing through", "[dsl][light][looks_like]") {
    const std::string lamp =
        "camera { location <0, 2, -6> look_at <0, 2, 0> }\n"
        "light_source { <0, 0, 0>, rgb 1 translate <0, 2, 0>\n"
        "  looks_like { sphere { 0, 0.3 pigment { rgb <1, 0, 0> } finish { ambient 1 diffuse 0 } } } }\n"
        "box { <-3, -0.1, -3>, <3, 0, 3> pigment { rgb 0.8 } }\n"
        "box { <-3, 0, 3>, <3, 4, 3.1> pigment { rgb 0.8 } }\n";
    const std::string bare =
        "camera { location <0, 2, -6> look_at <0, 2, 0> }\n"
        "light_source { <0, 2, 0>, rgb 1 }\n"
        "box { <-3, -0.1, -3>, <3, 0, 3> pigment { rgb 0.8 } }\n"
        "box { <-3, 0, 3>, <3, 4, 3.1> pigment { rgb 0.8 } }\n";
    std::vector<dsl::Diagnostic> w, w_bare;
    const auto b = build_pov(lamp, w);
    const auto c = build_pov(bare, w_bare);
    CHECK(w.empty());
    REQUIRE(b.scene.objects().size() == 3);
    const auto& object = b.scene.objects()[0];  // the light comes first in the file
    CHECK_FALSE(object.options.casts_shadow);
    CHECK(object.options.passes_photons);
    // Where POV-Ray puts it: moved to the light's position, then by the light's translate.
    const Ball<double> ball = b.scene.object_bounding_ball(0);
    CHECK(glm::length(ball.center - Vec3<double>(0, 2, 0)) < 1e-9);
    CHECK(ball.radius == Approx(0.3));

    RenderSettings s = b.settings;
    s.width = 40, s.height = 30;
    s.mode = RenderMode::pm;
    s.seed = 5;
    const RenderResult with = render(b.scene, b.camera, s);
    const RenderResult without = render(c.scene, c.camera, s);
    const auto pixel = [](const RenderResult& r, unsigned x, unsigned y) { return Rgb<double>(r.film.pixels()[y * r.film.width() + x]); };
    const auto at = [&](const RenderResult& r, unsigned x, unsigned y) { return pixel(r, x, y).x; };
    // The camera sees the red sphere where the light is (image centre; the white wall without it).
    CHECK(pixel(with, 20, 15).x > 0.9);
    CHECK(pixel(with, 20, 15).y < 0.02);
    CHECK(pixel(without, 20, 15).y > 0.3);
    // The floor, lit through the sphere by direct light and by photons (the light bounced off
    // the wall, which the sphere would absorb if it stopped them), as without it: the mean of
    // the bottom rows within 2% (the noise of 40 x 8 pixels at the default photons).
    double floor_with = 0, floor_without = 0;
    for (unsigned y = 22; y < 30; ++y)
        for (unsigned x = 0; x < 40; ++x) floor_with += at(with, x, y), floor_without += at(without, x, y);
    INFO("floor with looks_like " << floor_with << ", without " << floor_without);
    CHECK(floor_without > 0);
    CHECK(floor_with == Approx(floor_without).epsilon(0.02));
}
