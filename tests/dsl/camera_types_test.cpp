// SPDX-License-Identifier: MIT
// POV-Ray's camera types and focal blur read into the library's camera: each keyword's
// projection, POV-Ray's angle rules per type (Parser::Parse_Camera), the orthographic camera's
// area, and blur_samples as the most samples a pixel takes.

#include <catch2/catch.hpp>

#include "dsl_test_util.hpp"

#include <cmath>

using namespace dsl_test;
using namespace photon;

namespace {

dsl::BuiltScene<double> camera_scene(const std::string& camera, std::vector<dsl::Diagnostic>* warnings = nullptr,
                                     dsl::SettingsOverrides overrides = {}) {
    std::vector<dsl::Diagnostic> local;
    auto& w = warnings ? *warnings : local;
    dsl::ParseOptions po;
    po.diagnostics = collect(w);
    const auto desc = dsl::parse_string("camera { " + camera + " }\n"
                                        "light_source { <0, 5, 0>, rgb 1 fade_distance 1 fade_power 2 }\n"
                                        "sphere { 0, 1 }\n",
                                        "test.pov", po);
    dsl::BuildOptions bo;
    bo.diagnostics = collect(w);
    bo.overrides = std::move(overrides);
    return dsl::build<double>(desc, bo);
}

}  // namespace

TEST_CASE("each camera keyword builds its projection, without a warning", "[dsl][camera]") {
    const std::pair<const char*, Projection> types[] = {
        {"perspective", Projection::perspective},     {"orthographic", Projection::orthographic},
        {"fisheye", Projection::fisheye},             {"ultra_wide_angle", Projection::ultra_wide_angle},
        {"omnimax", Projection::omnimax},             {"panoramic", Projection::panoramic},
        {"cylinder 1", Projection::cylinder_1},       {"cylinder 2", Projection::cylinder_2},
        {"cylinder 3", Projection::cylinder_3},       {"cylinder 4", Projection::cylinder_4},
        {"spherical", Projection::spherical}};
    for (const auto& [keyword, projection] : types) {
        std::vector<dsl::Diagnostic> w;
        const auto b = camera_scene(std::string(keyword) + " location <0, 0, -5> look_at 0", &w);
        INFO(keyword << ": " << all_messages(w));
        CHECK(b.camera.projection() == projection);
        CHECK(w.empty());
        CHECK_FALSE(b.camera.has_focal_blur());
        // Every one of them looks at the look_at point through the image's centre, but omnimax:
        // in a 4:3 image its dome's axis sits below the centre (the image shows more above it).
        const auto centre = b.camera.ray(0.5, 0.5);
        REQUIRE(centre);
        if (projection == Projection::omnimax)
            CHECK(centre->direction.y > 0.1);
        else
            CHECK(glm::length(centre->direction - Vec3<double>(0, 0, 1)) < 1e-12);
    }
}

TEST_CASE("angle: the direction's length for perspective and orthographic, the projection's own angle otherwise",
          "[dsl][camera]") {
    // The default image is 800 x 600: right <4/3, 0, 0>.
    const auto fish = camera_scene("fisheye location <0, 0, -5> look_at 0 angle 360");
    CHECK(fish.camera.frame().angle == 360);
    CHECK(glm::length(fish.camera.direction()) == Approx(1));  // untouched
    CHECK(camera_scene("fisheye").camera.frame().angle == 90);  // POV-Ray's default
    const auto persp = camera_scene("location <0, 0, -5> look_at 0 angle 90");
    CHECK(glm::length(persp.camera.direction()) == Approx(0.5 * 4.0 / 3.0));
    const auto sph = camera_scene("spherical angle 180");
    CHECK(sph.camera.frame().angle == 180);
    CHECK(sph.camera.frame().vertical_angle == 90);  // half the horizontal one when not given
    const auto sph2 = camera_scene("spherical angle 120, 100");
    CHECK(sph2.camera.frame().vertical_angle == 100);
    const auto sph0 = camera_scene("spherical");
    CHECK(sph0.camera.frame().angle == 360);
    CHECK(sph0.camera.frame().vertical_angle == 180);
    CHECK(camera_scene("cylinder 2 angle 150").camera.frame().angle == 150);
}

TEST_CASE("orthographic: without up and right, or with angle, it sees what a perspective camera sees at look_at",
          "[dsl][camera]") {
    // |look_at - location| = 5, |direction| = 1: right and up grow five times.
    const auto plain = camera_scene("orthographic location <0, 0, -5> look_at 0");
    CHECK(glm::length(plain.camera.right()) == Approx(5 * 4.0 / 3.0));
    CHECK(glm::length(plain.camera.up()) == Approx(5));
    // angle 90: the image is 2 x 5 x tan(45 degrees) = 10 wide at the look_at point.
    const auto angled = camera_scene("orthographic location <0, 0, -5> look_at 0 angle 90");
    CHECK(glm::length(angled.camera.right()) == Approx(10));
    CHECK(glm::length(angled.camera.up()) == Approx(7.5));
    // A bare `angle` (POV-Ray's 0) still asks for the rescaling, with the direction as given.
    CHECK(glm::length(camera_scene("orthographic location <0, 0, -5> look_at 0 angle").camera.right()) ==
          Approx(5 * 4.0 / 3.0));
    // Given up and right, no angle: the image is exactly that big.
    const auto given = camera_scene("orthographic location <0, 0, -5> look_at 0 up 3*y right 4*x");
    CHECK(glm::length(given.camera.right()) == Approx(4));
    CHECK(glm::length(given.camera.up()) == Approx(3));
    // No look_at: POV-Ray's default look_at <0, 0, 1>, 7 from this location.
    CHECK(glm::length(camera_scene("orthographic location <0, 0, -6>").camera.up()) == Approx(7));
    // Its rays are parallel and start across the image.
    const Ray<double> a = *given.camera.ray(0, 0), b = *given.camera.ray(1, 1);
    CHECK(a.direction == b.direction);
    CHECK(glm::length(b.origin - a.origin - Vec3<double>(4, -3, 0)) < 1e-12);
}

TEST_CASE("focal blur: aperture with blur_samples, the focal point's distance, samples per pixel", "[dsl][camera]") {
    const auto b = camera_scene("location <0, 0, -5> look_at 0 aperture 0.4 blur_samples 30 focal_point <3, 0, -1>");
    REQUIRE(b.camera.has_focal_blur());
    CHECK(b.camera.focal_blur().aperture == Approx(0.4));
    CHECK(b.camera.focal_blur().focal_distance == Approx(5));  // |<3, 0, -1> - <0, 0, -5>|
    // Rounds of 9 samples while the pixel is noisy, up to blur_samples (POV-Ray stops once its
    // samples agree), with no contrast test: every pixel under focal blur is noisy.
    CHECK(b.settings.samples_per_pixel == 9);
    CHECK(b.settings.aa_max_samples == 30);
    CHECK(b.settings.aa_contrast == 0.0f);
    CHECK(b.settings.aa_threshold > 0.0f);
    // blur_samples MIN, MAX: photon takes MAX as the most.
    const auto few = camera_scene("aperture 0.4 blur_samples 4, 6");
    CHECK(few.settings.samples_per_pixel == 6);
    CHECK(few.settings.aa_max_samples == 16);
    // No focal point: the direction's length when angle or look_at set it.
    CHECK(camera_scene("location <0, 0, -5> look_at 0 angle 90 aperture 1 blur_samples 9").camera.focal_blur().focal_distance ==
          Approx(0.5 * 4.0 / 3.0));
    // As in POV-Ray, an aperture without blur_samples (or blur_samples without aperture) is a pinhole.
    CHECK_FALSE(camera_scene("aperture 0.4").camera.has_focal_blur());
    CHECK_FALSE(camera_scene("blur_samples 9").camera.has_focal_blur());
    // Without focal blur, photon render's one sample per pixel (anti-aliasing by contrast adds more).
    CHECK(camera_scene("aperture 0.4").settings.samples_per_pixel == 1);
    // The command line's samples per pixel win.
    CHECK(camera_scene("aperture 0.4 blur_samples 30", nullptr, {{"samples_per_pixel", std::uint64_t(2)}})
              .settings.samples_per_pixel == 2);
}
