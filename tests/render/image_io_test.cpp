// SPDX-License-Identifier: MIT
// Nothing lost: images are written to a temporary file and renamed into place, so an old image
// survives a failed write; a path that cannot be written is found before a render starts.

#include <catch2/catch.hpp>

#include <photon/film/image_io.hpp>

#include <OpenImageIO/imageio.h>  // reads back what was written, beside photon's reader
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

using namespace photon;
namespace fs = std::filesystem;

namespace {

fs::path fresh_dir(const std::string& name) {
    const fs::path dir = fs::temp_directory_path() / ("photon-image-io-" + name + "-" + std::to_string(::getpid()));
    fs::remove_all(dir);
    fs::create_directories(dir);
    return dir;
}

std::size_t files_in(const fs::path& dir) {
    std::size_t n = 0;
    for ([[maybe_unused]] const auto& e : fs::directory_iterator(dir)) ++n;
    return n;
}

Film gray(float v) {
    Film f(4, 3);
    for (auto& p : f.pixels()) p = Rgb<float>(v);
    return f;
}

}  // namespace

TEST_CASE("an image is written whole, with its metadata, and no temporary file is left", "[image_io]") {
    const fs::path dir = fresh_dir("write");
    const fs::path png = dir / "a.png";
    write_image(png, gray(0.5f), {.exposure = 1.0f, .metadata = {{"photon:partial", "true"}}});
    write_image(dir / "a.exr", gray(0.25f));
    CHECK(files_in(dir) == 2);
    const Film back = read_image(dir / "a.exr");
    CHECK(back.pixels()[0].x == 0.25f);
    auto in = OIIO::ImageInput::open(png.string());
    REQUIRE(in);
    CHECK(in->spec().get_string_attribute("photon:partial") == "true");
    in->close();
    // Replacing goes through a rename: the new content, still one file.
    write_image(png, gray(0.0f));
    CHECK(files_in(dir) == 2);
    CHECK(read_image(png).pixels()[0].x == 0.0f);
    fs::remove_all(dir);
}

TEST_CASE("a failed write leaves the old image untouched", "[image_io]") {
    const fs::path dir = fresh_dir("fail");
    const fs::path png = dir / "keep.png";
    write_image(png, gray(1.0f));
    const auto size = fs::file_size(png);
    // A 0 x 0 film is refused by the writer after the temporary file was opened.
    CHECK_THROWS_AS(write_image(png, Film(0, 0)), ImageError);
    CHECK(fs::file_size(png) == size);
    CHECK(read_image(png).pixels()[0].x == Approx(1.0f));
    CHECK(files_in(dir) == 1);
    fs::remove_all(dir);
}

TEST_CASE("unwritable output paths are reported before rendering", "[image_io]") {
    const fs::path dir = fresh_dir("check");
    CHECK_THROWS_WITH(check_writable_image_path(dir / "no" / "such" / "x.png"), Catch::Contains("does not exist"));
    CHECK_THROWS_WITH(check_writable_image_path(dir / "x.unknownformat"), Catch::Contains("no image format"));
    fs::create_directory(dir / "d.png");
    CHECK_THROWS_WITH(check_writable_image_path(dir / "d.png"), Catch::Contains("is a directory"));
    CHECK_THROWS_AS(check_writable_image_path(""), ImageError);
    CHECK_NOTHROW(check_writable_image_path(dir / "ok.png"));
    CHECK(files_in(dir) == 1);  // the probe file is removed
    // /proc accepts no new files, even from root (for whom access() says every directory is writable).
    if (fs::is_directory("/proc"))
        CHECK_THROWS_WITH(check_writable_image_path("/proc/photon-test.png"), Catch::Contains("cannot create a file"));
    fs::remove_all(dir);
}
