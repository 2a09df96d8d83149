// SPDX-License-Identifier: MIT
// Image maps (texture/image_map.hpp): each of POV-Ray 3.7's mappings against texels worked out by
// hand, its interpolations, `once`, filter and transmit, and an image map as a layer.

#include <catch2/catch.hpp>

#include <memory>
#include <vector>

#include <photon/texture/bump_map.hpp>
#include <photon/texture/image_map.hpp>
#include <photon/texture/normal_field.hpp>
#include <photon/texture/layered.hpp>

using namespace photon;

namespace {

/// A 4 x 2 image whose pixel (x, y) has red x / 4, green y / 2, blue 0.5 and alpha 1, but
/// pixel (0, 1), whose alpha is `alpha01`.
std::shared_ptr<const PixelGrid> ramp_image(float alpha01 = 1.0f) {
    std::vector<PixelGrid::Pixel> px;
    for (unsigned y = 0; y < 2; ++y)
        for (unsigned x = 0; x < 4; ++x) px.push_back({float(x) / 4, float(y) / 2, 0.5f, x == 0 && y == 1 ? alpha01 : 1.0f});
    auto grid = std::make_shared<PixelGrid>(4u, 2u, std::move(px));
    grid->has_alpha = alpha01 != 1.0f;
    return grid;
}

void check_texel(const std::optional<ImageTexel>& t, double x, double y) {
    REQUIRE(t);
    CHECK_THAT(t->x, Catch::WithinAbs(x, 1e-9));
    CHECK_THAT(t->y, Catch::WithinAbs(y, 1e-9));
}

}  // namespace

TEST_CASE("planar image maps put the image on the unit square of x-y, top row at y = 1", "[texture][image_map]") {
    const ImageMap<double> m(ramp_image());
    // x 0.3 of width 4 is 1.2; y 0.8 of height 2 is 1.6, counted from the top: 2 - 1.6 = 0.4.
    check_texel(m.texel({0.3, 0.8, 5.0}), 1.2, 0.4);
    // Repeated: x 1.3 is x 0.3 again; y -0.25 is y 0.75 of the square below, 1.5 of height 2
    // from its bottom, 0.5 from its top.
    check_texel(m.texel({1.3, -0.25, 0.0}), 1.2, 0.5);
    // The texel picks the pixel it lies in: (1, 0) for the first point.
    const LayerColor<double> c = m.layer({0.3, 0.8, 5.0});
    CHECK_THAT(c.color.x, Catch::WithinAbs(0.25, 1e-12));
    CHECK_THAT(c.color.y, Catch::WithinAbs(0.0, 1e-12));
    CHECK(c.transmit == 0.0);
}

TEST_CASE("spherical, cylindrical and torus image maps follow POV-Ray's angles", "[texture][image_map]") {
    SECTION("spherical") {
        const ImageMap<double> m(ramp_image(), {.map_type = ImageMapType::spherical});
        // +z is a quarter turn from +x: u = 1; the equator is half way up: v = 1, from the top 1.
        check_texel(m.texel({0.0, 0.0, 2.0}), 1.0, 1.0);
        // 45 degrees north towards -x: longitude half a turn (u 2), latitude 0.75 (v 1.5, from the top 0.5).
        check_texel(m.texel({-1.0, 1.0, 0.0}), 2.0, 0.5);
        CHECK_FALSE(m.texel({0.0, 0.0, 0.0}));
    }
    SECTION("cylindrical") {
        const ImageMap<double> m(ramp_image(), {.map_type = ImageMapType::cylindrical});
        // -z is three quarters of a turn: u 3; y 0.25 of height 2 is 0.5, from the top 1.5.
        check_texel(m.texel({0.0, 0.25, -3.0}), 3.0, 1.5);
        CHECK_FALSE(m.texel({0.0, 0.5, 0.0}));  // on the axis
    }
    SECTION("torus") {
        const ImageMap<double> m(ramp_image(), {.map_type = ImageMapType::torus});
        // On the tube's outer equator at +z: a quarter turn round y (u 1); the tube angle is
        // acos(-1) = pi, half a turn: v 1, from the top 1.
        check_texel(m.texel({0.0, 0.0, 1.5}), 1.0, 1.0);
        // Above the tube's centre line at +x: tube angle 2 pi - pi / 2 (y > 0): v 1.5, from the top 0.5.
        check_texel(m.texel({1.0, 0.5, 0.0}), 0.0, 0.5);
    }
}

TEST_CASE("once shows the image a single time and is clear elsewhere", "[texture][image_map]") {
    const ImageMap<float> m(ramp_image(), {.once = true});
    CHECK(m.texel({0.5, 0.5, 0.0}));
    CHECK_FALSE(m.texel({1.5, 0.5, 0.0}));
    CHECK_FALSE(m.texel({0.5, -0.01, 0.0}));
    const LayerColor<float> outside = m.layer({-0.5f, 0.5f, 0.0f});
    CHECK(outside.color == Rgb<float>(1.0f));
    CHECK(outside.transmit == 1.0f);
    CHECK(m.upper_bound() == Rgb<float>(1.0f));
}

TEST_CASE("bilinear and normalized-distance interpolation blend the four nearest pixels", "[texture][image_map]") {
    const ImageMap<double> bilinear(ramp_image(), {.interpolate = ImageInterpolation::bilinear});
    // Pixel centres at (x + 0.5, y + 0.5): half way between the centres of pixels 1 and 2 of
    // the top row, red is (0.25 + 0.5) / 2.
    CHECK_THAT(bilinear.sample(2.0, 0.5).color.x, Catch::WithinAbs(0.375, 1e-12));
    // A quarter of the way from the centre of (1, 0) to (2, 1): red 0.25 + 0.25 * 0.25, green 0.25 * 0.5.
    const LayerColor<double> c = bilinear.sample(1.75, 0.75);
    CHECK_THAT(c.color.x, Catch::WithinAbs(0.3125, 1e-12));
    CHECK_THAT(c.color.y, Catch::WithinAbs(0.125, 1e-12));
    // Across the right edge the image repeats: between pixel 3 (red 0.75) and pixel 0 (red 0).
    CHECK_THAT(bilinear.sample(4.0, 0.5).color.x, Catch::WithinAbs(0.375, 1e-12));

    const ImageMap<double> norm(ramp_image(), {.interpolate = ImageInterpolation::normalized_distance});
    // Weights 1 / d^2 to the four centres: at (1.75, 0.75) the distances^2 to (1.5, 0.5),
    // (2.5, 0.5), (1.5, 1.5), (2.5, 1.5) are 1/8, 5/8, 5/8, 9/8 (POV-Ray's pairing of weights to
    // corners: the nearer pixel weighs more).
    const double w[4] = {8.0, 8.0 / 5, 8.0 / 5, 8.0 / 9};
    const double sum = w[0] + w[1] + w[2] + w[3];
    const double red = (w[0] * 0.25 + w[1] * 0.5 + w[2] * 0.25 + w[3] * 0.5) / sum;
    const LayerColor<double> n = norm.sample(1.75, 0.75);
    CHECK_THAT(n.color.x, Catch::WithinAbs(red, 1e-12));
    // On a pixel centre, that pixel.
    CHECK_THAT(norm.sample(1.5, 0.5).color.x, Catch::WithinAbs(0.25, 1e-12));
}

TEST_CASE("an image's alpha is transmit, and filter all and transmit all add to every pixel", "[texture][image_map]") {
    const ImageMap<double> m(ramp_image(0.25f), {.filter_all = 0.1, .transmit_all = 0.2});
    const LayerColor<double> corner = m.sample(0.5, 1.5);  // pixel (0, 1): alpha 0.25
    CHECK_THAT(corner.filter, Catch::WithinAbs(0.1, 1e-12));
    CHECK_THAT(corner.transmit, Catch::WithinAbs(0.75 + 0.2 - 0.05, 1e-7));  // kept to opacity >= 0
    const LayerColor<double> other = m.sample(2.5, 0.5);
    CHECK_THAT(other.transmit, Catch::WithinAbs(0.2, 1e-12));
    CHECK_THROWS_AS(ImageMap<double>(ramp_image(), {.transmit_all = 1.5}), std::invalid_argument);
}

TEMPLATE_TEST_CASE("an image map is a layer whose clear pixels show the layer below", "[texture][image_map]", float,
                   double) {
    using S = TestType;
    static_assert(ReflectanceField<ImageMap<S>, S>);
    auto image = std::make_shared<const ImageMap<S>>(ramp_image(0.0f), ImageMapOptions{});
    const PigmentLayer<S> below(LayerColor<S>{Rgb<S>(S(0.2), S(0.4), S(0.6)), S(0), S(0)}, Rgb<S>(S(1)));
    const LayeredPigment<S> stack({below, PigmentLayer<S>(image, Rgb<S>(S(1)))});
    // Pixel (0, 1) is fully clear (alpha 0): the layer below shows.
    const Rgb<S> clear = stack({S(0.1), S(0.2), S(0)});
    CHECK_THAT(double(clear.x), Catch::WithinAbs(0.2, 1e-6));
    CHECK_THAT(double(clear.z), Catch::WithinAbs(0.6, 1e-6));
    // Pixel (2, 0) is opaque: its own colour.
    const Rgb<S> opaque = stack({S(0.6), S(0.8), S(0)});
    CHECK_THAT(double(opaque.x), Catch::WithinAbs(0.5, 1e-6));
    CHECK_THAT(double(opaque.y), Catch::WithinAbs(0.0, 1e-6));
    // The bound holds everywhere on a grid of points.
    const Rgb<S> bound = stack.upper_bound();
    for (int i = 0; i < 40; ++i)
        for (int j = 0; j < 40; ++j) {
            const Rgb<S> c = stack({S(i) / S(17), S(j) / S(13), S(0)});
            for (int k = 0; k < 3; ++k) CHECK(c[k] <= bound[k] + S(1e-6));
        }
}

TEST_CASE("a bump map tilts the normal by its image's slope, as a finite difference of its heights says",
          "[texture][bump_map]") {
    // 16 x 8 grey pixels: along x a ramp of slope 0.03 per pixel, along y (down the rows) a
    // ramp of slope 0.05 per row.
    const unsigned w = 16, h = 8;
    std::vector<PixelGrid::Pixel> px;
    const auto grey = [](unsigned x, unsigned y) { return 0.1f + 0.03f * float(x) + 0.05f * float(y); };
    for (unsigned y = 0; y < h; ++y)
        for (unsigned x = 0; x < w; ++x) px.push_back({grey(x, y), grey(x, y), grey(x, y), 1.0f});
    const auto image = std::make_shared<const PixelGrid>(w, h, std::move(px));
    const double amount = 2.0;
    const ImageBumpMap<double> bumps(image, {}, amount);
    static_assert(NormalField<ImageBumpMap<double>, double>);
    // On a floor (normal +y) at the centre of pixel (5, 3): u = 5.5 / 16, rows from the top: y = 1 - 3.5 / 8.
    const Vec3<double> p(5.5 / w, 1.0 - 3.5 / h, 0.0);
    const Vec3<double> n = bumps(p, {0, 1, 0});
    // The heights' differences: left to right across two pixels, and from this row to the next.
    const double across = amount * (grey(6, 4) - grey(4, 4)) / 2.0;  // the next row's neighbours
    const double down = amount * (grey(5, 3) - grey(5, 4));
    // POV-Ray's triangle (0, h1, 0), (-1, h2, 1), (1, h3, 1): normal (-across, 1, down), and the
    // frame of a +y normal turns its z to -z.
    const Vec3<double> expected = glm::normalize(Vec3<double>(-across, 1.0, -down));
    CHECK(n.x == Approx(expected.x).margin(1e-6));
    CHECK(n.y == Approx(expected.y).margin(1e-6));
    CHECK(n.z == Approx(expected.z).margin(1e-6));
    CHECK(glm::length(n) == Approx(1.0));
    // A flat image leaves the normal as it was, on any surface.
    const auto flat = std::make_shared<const PixelGrid>(2u, 2u, std::vector<PixelGrid::Pixel>(4, {0.5f, 0.5f, 0.5f, 1.0f}));
    const ImageBumpMap<double> none(flat, {}, 1.0);
    const Vec3<double> slanted = glm::normalize(Vec3<double>(0.3, -0.4, 0.8));
    const Vec3<double> same = none({0.2, 0.7, 0.1}, slanted);
    CHECK(glm::length(same - slanted) < 1e-9);
    // Outside a `once` image, the normal is untouched.
    const ImageBumpMap<double> once(image, {.once = true}, amount);
    CHECK(once({1.5, 0.5, 0.0}, {0, 1, 0}) == Vec3<double>(0, 1, 0));
}
