// SPDX-License-Identifier: MIT
// Image files read as pixel grids (io/image_file.hpp): files this test writes through
// OpenImageIO, read back with POV-Ray 3.7's default decoding (sRGB for PNG, none for PPM), with
// `gamma` given, with alpha, grey and 16 bits; and PNG files read by libpng alone
// (io/png_file.hpp) as OpenImageIO reads them.

#include <catch2/catch.hpp>

#include <OpenImageIO/imageio.h>

#include <cmath>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include <photon/io/image_file.hpp>
#include <photon/io/png_file.hpp>

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

#if defined(PHOTON_HAS_PNG) && PHOTON_HAS_PNG
namespace {

/// A PNG written with libpng: `type` and `depth` as libpng names them, the samples (row by row,
/// big-endian for 16 bits as the file holds them), optional gAMA, sRGB, tRNS and palette.
struct PngSpec {
    int width = 3, height = 2, type = PNG_COLOR_TYPE_RGB, depth = 8;
    std::vector<png_byte> data;
    std::optional<double> gama;
    bool srgb = false;
    std::vector<png_color> palette;
    std::vector<png_byte> trns;
};
void write_png_file(const std::filesystem::path& path, const PngSpec& s) {
    std::FILE* f = std::fopen(path.c_str(), "wb");
    REQUIRE(f);
    png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
    png_infop info = png_create_info_struct(png);
    png_init_io(png, f);
    png_set_IHDR(png, info, png_uint_32(s.width), png_uint_32(s.height), s.depth, s.type, PNG_INTERLACE_NONE,
                 PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
    if (!s.palette.empty()) png_set_PLTE(png, info, s.palette.data(), int(s.palette.size()));
    if (!s.trns.empty()) {
        if (s.type == PNG_COLOR_TYPE_PALETTE) {
            png_set_tRNS(png, info, s.trns.data(), int(s.trns.size()), nullptr);
        } else {
            png_color_16 key{};
            key.gray = key.red = 7;  // the colour made transparent
            png_set_tRNS(png, info, nullptr, 0, &key);
        }
    }
    if (s.gama) png_set_gAMA(png, info, *s.gama);
    if (s.srgb) png_set_sRGB(png, info, PNG_sRGB_INTENT_PERCEPTUAL);
    png_write_info(png, info);
    const std::size_t row = png_get_rowbytes(png, info);
    for (int y = 0; y < s.height; ++y) png_write_row(png, const_cast<png_bytep>(s.data.data() + std::size_t(y) * row));
    png_write_end(png, nullptr);
    png_destroy_write_struct(&png, &info);
    std::fclose(f);
}

void check_same_grid(const PixelGrid& a, const PixelGrid& b) {
    REQUIRE(a.width() == b.width());
    REQUIRE(a.height() == b.height());
    CHECK(a.has_alpha == b.has_alpha);
    CHECK(a.grayscale == b.grayscale);
    CHECK(a.max_value == b.max_value);
    CHECK(a.indices == b.indices);
    for (std::size_t i = 0; i < a.pixels().size(); ++i)
        for (std::size_t c = 0; c < 4; ++c) REQUIRE(a.pixels()[i][c] == Approx(b.pixels()[i][c]).margin(2e-6));
}

}  // namespace

TEST_CASE("libpng's reader gives OpenImageIO's grid for every kind of PNG, chunks and decodings",
          "[image_file][png]") {
    const ScratchDir dir;
    std::vector<png_byte> bytes(48);
    for (std::size_t i = 0; i < bytes.size(); ++i) bytes[i] = png_byte((i * 53 + 7) % 256);
    const std::vector<png_color> palette = {{255, 0, 0}, {0, 128, 0}, {10, 20, 250}, {7, 7, 7}};
    const std::vector<PngSpec> specs = {
        {.type = PNG_COLOR_TYPE_RGB, .data = bytes},
        {.type = PNG_COLOR_TYPE_RGB_ALPHA, .data = bytes},
        {.type = PNG_COLOR_TYPE_GRAY, .data = bytes},
        {.type = PNG_COLOR_TYPE_GRAY_ALPHA, .data = bytes},
        {.type = PNG_COLOR_TYPE_GRAY, .depth = 4, .data = bytes},
        {.type = PNG_COLOR_TYPE_GRAY, .depth = 1, .data = bytes},
        {.type = PNG_COLOR_TYPE_RGB, .depth = 16, .data = bytes},
        {.type = PNG_COLOR_TYPE_GRAY_ALPHA, .depth = 16, .data = bytes},
        {.type = PNG_COLOR_TYPE_RGB, .data = bytes, .gama = 1.0},
        {.type = PNG_COLOR_TYPE_RGB, .data = bytes, .gama = 0.45455},
        {.type = PNG_COLOR_TYPE_RGB, .data = bytes, .gama = 0.5},
        {.type = PNG_COLOR_TYPE_RGB, .data = bytes, .gama = 0.45455, .srgb = true},
        {.type = PNG_COLOR_TYPE_GRAY, .data = bytes, .trns = {1}},
        {.type = PNG_COLOR_TYPE_PALETTE, .data = {0, 1, 2, 3, 2, 1}, .palette = palette},
        {.type = PNG_COLOR_TYPE_PALETTE, .data = {0, 1, 2, 3, 2, 1}, .palette = palette, .trns = {255, 0, 128}},
        {.type = PNG_COLOR_TYPE_PALETTE, .depth = 2, .data = {0x1b, 0xe4}, .palette = palette},
    };
    const ImageGamma decodings[] = {{}, {ImageGamma::Kind::none}, {ImageGamma::Kind::srgb}, {ImageGamma::Kind::power, 1.8}};
    for (std::size_t i = 0; i < specs.size(); ++i) {
        const auto file = dir.path / ("kind" + std::to_string(i) + ".png");
        write_png_file(file, specs[i]);
        for (const ImageGamma& g : decodings) {
            INFO("png " << i << ", decoding " << int(g.kind));
            const auto by_libpng = read_png_pixel_grid(file, g, max_image_file_pixels);
            REQUIRE(by_libpng);
            check_same_grid(*by_libpng, read_pixel_grid(file, g));
        }
    }
    // POV-Ray's own PNGs, where povray-includes is installed.
    for (const char* name : {"Mount1.png", "bumpmap_.png", "plasma2.png", "povmap.png", "test.png"}) {
        const std::filesystem::path file = std::filesystem::path("/usr/share/povray-3.7/include") / name;
        if (!std::filesystem::exists(file)) continue;
        INFO(file);
        const auto by_libpng = read_png_pixel_grid(file, {}, max_image_file_pixels);
        REQUIRE(by_libpng);
        check_same_grid(*by_libpng, read_pixel_grid(file));
    }
    // Not a PNG: nothing, for the caller to read another way; a PNG too big: the header's error.
    write_test_image<unsigned char>(dir.path / "not.ppm", 1, 1, 3, {1, 2, 3}, OIIO::TypeDesc::UINT8);
    CHECK_FALSE(read_png_pixel_grid(dir.path / "not.ppm", {}, max_image_file_pixels).has_value());
    CHECK_THROWS_WITH(read_png_pixel_grid(dir.path / "kind0.png", {}, 5), Catch::Matchers::Contains("3 x 2 pixels"));
}
#endif
