// SPDX-License-Identifier: MIT
// The output transfer functions: the sRGB curve and POV-Ray's working gamma (assumed_gamma).

#include <catch2/catch.hpp>

#include <photon/film/tone_map.hpp>

#include <algorithm>
#include <cmath>

using namespace photon;

TEST_CASE("sRGB encode and decode are inverse and meet the standard's knots", "[film][tone_map]") {
    CHECK(srgb_encode(0.0f) == 0.0f);
    CHECK(srgb_encode(1.0f) == Approx(1.0f));
    CHECK(srgb_encode(0.0031308f) == Approx(0.04045f).epsilon(1e-3));
    CHECK(srgb_encode(0.18f) == Approx(0.4614f).epsilon(1e-3));  // middle grey
    for (float v : {0.001f, 0.01f, 0.2f, 0.5f, 0.9f}) CHECK(srgb_decode(srgb_encode(v)) == Approx(v).epsilon(1e-5));
    CHECK(to_display_8bit(0.18f, 1.0f) == 118);
    CHECK(to_display_8bit(2.0f, 1.0f) == 255);
    CHECK(to_display_8bit(-1.0f, 1.0f) == 0);
    CHECK(to_display_8bit(std::nanf(""), 1.0f) == 0);
}

TEST_CASE("a film rendered in a working space of gamma G is written as v^G", "[film][tone_map]") {
    Film film(3, 1);
    film.at(0, 0) = Rgb<float>(0.5f, 0.25f, 1.0f);
    film.at(1, 0) = Rgb<float>(2.0f, 0.0f, -0.5f);  // above 1 is kept (HDR); negative becomes 0
    film.at(2, 0) = Rgb<float>(0.73f);
    Film same = film;
    decode_working_space(same, WorkingSpace{});
    CHECK(same.pixels() == film.pixels());  // gamma 1: the identity, bit for bit

    decode_working_space(film, {WorkingSpace::Curve::power, 2.2f});
    CHECK(film.at(0, 0)[0] == Approx(std::pow(0.5f, 2.2f)));
    CHECK(film.at(0, 0)[1] == Approx(std::pow(0.25f, 2.2f)));
    CHECK(film.at(0, 0)[2] == 1.0f);
    CHECK(film.at(1, 0)[0] == Approx(std::pow(2.0f, 2.2f)));
    CHECK(film.at(1, 0)[1] == 0.0f);
    CHECK(film.at(1, 0)[2] == 0.0f);
    // POV-Ray's point: a colour written as 0.73 under assumed_gamma 2.2 shows as about 0.73 in an sRGB file.
    CHECK(srgb_encode(film.at(2, 0)[0]) == Approx(0.73f).epsilon(0.02));
}

TEST_CASE("a film rendered with gamma handling off (the sRGB working space) is written as it was rendered",
          "[film][tone_map]") {
    Film film(4, 1);
    film.at(0, 0) = Rgb<float>(0.3f, 0.02f, 1.0f);
    film.at(1, 0) = Rgb<float>(0.58f, 0.0f, -1.0f);
    film.at(2, 0) = Rgb<float>(2.0f, 0.999f, 0.001f);
    film.at(3, 0) = Rgb<float>(std::nanf(""));
    const Film rendered = film;
    decode_working_space(film, {WorkingSpace::Curve::srgb});
    for (unsigned x = 0; x < 3; ++x)
        for (int c = 0; c < 3; ++c) {
            const float v = rendered.at(x, 0)[c];
            // The sRGB file holds the number rendered (clamped to [0, 1]), as POV-Ray writes it.
            CHECK(srgb_encode(film.at(x, 0)[c]) == Approx(std::clamp(v, 0.0f, 1.0f)).margin(1e-5));
        }
    CHECK(film.at(2, 0)[0] > 1.0f);  // above 1 stays above 1 (HDR files), increasing
    CHECK(film.at(3, 0)[0] == 0.0f);
}
