// SPDX-License-Identifier: MIT
// Image files read as pixel grids (io/image_file.hpp): files this test writes through
// OpenImageIO, read back with POV-Ray 3.7's default decoding (sRGB for PNG, none for PPM), with
// `gamma` given, with alpha, grey and 16 bits.

#include <catch2/catch.hpp>

#include <OpenImageIO/imageio.h>

#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

#include <photon/io/image_file.hpp>

#if defined(PHOTON_HAS_PNG) && PHOTON_HAS_PNG
#include <png.h>
#endif
#include <cstdio>

using namespace photon;

namespace {

/// Writes `samples` (width * height * channels, row by row from the top) to `path` as `type`.
template <class T>
void write_test_image(const std::filesystem::path& path, int width, int height, int channels, const std::vector<T>& samples,
                      OIIO::TypeDesc type) {
    auto out = OIIO::ImageOutput::create(path.string());
    REQUIRE(out);
    OIIO::ImageSpec spec(width, height, channels, type);
    spec.attribute("oiio:UnassociatedAlpha", 1);  // the samples as given, not divided by alpha
    REQUIRE(out->open(path.string(), spec));
    REQUIRE(out->write_image(type, samples.data()));
    REQUIRE(out->close());
}

struct ScratchDir {
    std::filesystem::path path = std::filesystem::temp_directory_path() /
                                 ("photon-image-file-test-" + std::to_string(::getpid()));
    ScratchDir() { std::filesystem::create_directories(path); }
    ~ScratchDir() { std::filesystem::remove_all(path); }
};

float srgb_to_linear(float v) { return v <= 0.04045f ? v / 12.92f : std::pow((v + 0.055f) / 1.055f, 2.4f); }

}  // namespace

TEST_CASE("an 8-bit RGBA PNG reads back decoded from sRGB, its alpha as written", "[image_file]") {
    const ScratchDir dir;
    const auto file = dir.path / "rgba.png";
    // 2 x 1: (255, 128, 0, 255), (10, 20, 30, 64)
    write_test_image<unsigned char>(file, 2, 1, 4, {255, 128, 0, 255, 10, 20, 30, 64}, OIIO::TypeDesc::UINT8);
    const PixelGrid g = read_pixel_grid(file);
    REQUIRE(g.width() == 2);
    REQUIRE(g.height() == 1);
    CHECK(g.has_alpha);
    CHECK_FALSE(g.grayscale);
    CHECK(g.max_value == 255u);
    CHECK_THAT(g.at(0, 0)[0], Catch::WithinAbs(1.0, 1e-6));
    CHECK_THAT(g.at(0, 0)[1], Catch::WithinAbs(srgb_to_linear(128.0f / 255), 1e-6));
    CHECK_THAT(g.at(1, 0)[2], Catch::WithinAbs(srgb_to_linear(30.0f / 255), 1e-6));
    CHECK_THAT(g.at(1, 0)[3], Catch::WithinAbs(64.0 / 255, 1e-6));  // alpha is not decoded

    const PixelGrid raw = read_pixel_grid(file, {ImageGamma::Kind::none});
    CHECK_THAT(raw.at(0, 0)[1], Catch::WithinAbs(128.0 / 255, 1e-6));
    const PixelGrid power = read_pixel_grid(file, {ImageGamma::Kind::power, 2.2});
    CHECK_THAT(power.at(0, 0)[1], Catch::WithinAbs(std::pow(128.0 / 255, 2.2), 1e-5));
}

TEST_CASE("a 16-bit grey PNG reads as grey with its full range, rows from the top", "[image_file]") {
    const ScratchDir dir;
    const auto file = dir.path / "grey16.png";
    write_test_image<unsigned short>(file, 1, 2, 1, {65535, 1000}, OIIO::TypeDesc::UINT16);
    const PixelGrid g = read_pixel_grid(file, {ImageGamma::Kind::none});
    CHECK(g.grayscale);
    CHECK_FALSE(g.has_alpha);
    CHECK(g.max_value == 65535u);
    CHECK(g.at(0, 0)[0] == 1.0f);
    CHECK_THAT(g.at(0, 1)[0], Catch::WithinAbs(1000.0 / 65535, 1e-7));
    CHECK(g.at(0, 1)[1] == g.at(0, 1)[0]);
    CHECK(g.at(0, 1)[3] == 1.0f);
}

TEST_CASE("a PPM is not decoded by default, as POV-Ray 3.7 reads Netpbm files", "[image_file]") {
    const ScratchDir dir;
    const auto file = dir.path / "plain.ppm";
    write_test_image<unsigned char>(file, 1, 1, 3, {128, 64, 32}, OIIO::TypeDesc::UINT8);
    const PixelGrid g = read_pixel_grid(file);
    CHECK_THAT(g.at(0, 0)[0], Catch::WithinAbs(128.0 / 255, 1e-6));
    CHECK_THAT(g.at(0, 0)[2], Catch::WithinAbs(32.0 / 255, 1e-6));
}

TEST_CASE("a missing or unreadable file is an ImageError naming it", "[image_file]") {
    const ScratchDir dir;
    CHECK_THROWS_WITH(read_pixel_grid(dir.path / "none.png"), Catch::Contains("none.png"));
}

TEST_CASE("a file declaring more pixels than the limit is refused from its header", "[image_file]") {
    const ScratchDir dir;
    const auto small = dir.path / "small.png";
    write_test_image<unsigned char>(small, 4, 4, 3, std::vector<unsigned char>(48, 7), OIIO::TypeDesc::UINT8);
    CHECK(read_pixel_grid(small, {}, 16).width() == 4);
    CHECK_THROWS_WITH(read_pixel_grid(small, {}, 15),
                      Catch::Contains("small.png: the file declares 4 x 4 pixels of 3 channels; photon reads images of at "
                                      "most 15 pixels"));
    // A 20-byte file whose header declares 100,000 x 100,000 pixels: refused, nothing allocated.
    const auto huge = dir.path / "huge.ppm";
    std::FILE* f = std::fopen(huge.c_str(), "wb");
    REQUIRE(f);
    std::fputs("P6\n100000 100000\n255\nabc", f);
    std::fclose(f);
    CHECK_THROWS_WITH(read_pixel_grid(huge), Catch::Contains("declares 100000 x 100000 pixels"));
}

#if defined(PHOTON_HAS_PNG) && PHOTON_HAS_PNG
TEST_CASE("a palette PNG gives its colours and its indices", "[image_file]") {
    const ScratchDir dir;
    const auto file = dir.path / "palette.png";
    // 3 x 1 pixels of indices 2, 0, 1 into the palette red, green, blue (written with libpng).
    {
        std::FILE* f = std::fopen(file.c_str(), "wb");
        REQUIRE(f);
        png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
        png_infop info = png_create_info_struct(png);
        png_init_io(png, f);
        png_set_IHDR(png, info, 3, 1, 8, PNG_COLOR_TYPE_PALETTE, PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT,
                     PNG_FILTER_TYPE_DEFAULT);
        png_color palette[3] = {{255, 0, 0}, {0, 255, 0}, {0, 0, 255}};
        png_set_PLTE(png, info, palette, 3);
        png_write_info(png, info);
        png_byte row[3] = {2, 0, 1};
        png_write_row(png, row);
        png_write_end(png, nullptr);
        png_destroy_write_struct(&png, &info);
        std::fclose(f);
    }
    const PixelGrid g = read_pixel_grid(file);
    REQUIRE(g.indices.size() == 3);
    CHECK(g.indices[0] == 2);
    CHECK(g.indices[1] == 0);
    CHECK(g.indices[2] == 1);
    CHECK(g.at(0, 0)[2] == 1.0f);  // blue, index 2
    CHECK(g.at(1, 0)[0] == 1.0f);  // red, index 0
    // A PNG without a palette has no indices.
    write_test_image<unsigned char>(dir.path / "rgb.png", 1, 1, 3, {1, 2, 3}, OIIO::TypeDesc::UINT8);
    CHECK(read_pixel_grid(dir.path / "rgb.png").indices.empty());
}
#endif
