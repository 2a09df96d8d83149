// SPDX-License-Identifier: MIT
#pragma once
// 8-bit PNG output through libpng, for programs that would otherwise load OpenImageIO only to
// write a PNG (load_image_io.hpp): loading the image module costs about a third of a CPU-second
// (OpenImageIO brings some 260 shared libraries), more than a small render. The file is what the
// module writes: RGB, exposure * radiance sRGB encoded (tone_map.hpp), the sRGB and gAMA chunks,
// the metadata as tEXt chunks, through a temporary file renamed into place.

#if defined(PHOTON_HAS_PNG) && PHOTON_HAS_PNG

#include <photon/film/film.hpp>
#include <photon/film/image_write_options.hpp>
#include <photon/film/tone_map.hpp>

#include <png.h>

#include <cctype>
#include <csetjmp>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

namespace photon::image_module {

/// Whether `path` names a PNG file (by its extension, as the module decides).
[[nodiscard]] inline bool is_png_path(const std::filesystem::path& path) {
    std::string ext = path.extension().string();
    for (char& c : ext) c = char(std::tolower(static_cast<unsigned char>(c)));
    return ext == ".png";
}

/// Writes `film` to the PNG file `path`. Throws ImageError; on failure the file at `path`, if
/// any, is untouched.
inline void write_png(const std::filesystem::path& path, const Film& film, const ImageWriteOptions& options) {
    detail::check_writable_location(path);
    const std::filesystem::path tmp = detail::temporary_sibling(path);
    auto fail = [&](const std::string& why) {
        std::error_code ec;
        std::filesystem::remove(tmp, ec);
        throw ImageError(path.string() + ": " + why);
    };
    std::vector<png_byte> rows(std::size_t(film.width()) * film.height() * 3);
    for (std::size_t i = 0; i < film.pixels().size(); ++i)
        for (int c = 0; c < 3; ++c) rows[3 * i + c] = to_display_8bit(film.pixels()[i][c], options.exposure);
    // Everything with a destructor is made before setjmp: libpng reports errors by longjmp.
    std::vector<std::pair<std::string, std::string>> text = {{"Software", "photon"}, {"oiio:ColorSpace", "sRGB"}};
    text.insert(text.end(), options.metadata.begin(), options.metadata.end());
    std::vector<png_text> chunks(text.size());
    for (std::size_t i = 0; i < text.size(); ++i) {
        chunks[i].compression = PNG_TEXT_COMPRESSION_NONE;
        chunks[i].key = text[i].first.data();
        chunks[i].text = text[i].second.data();
        chunks[i].text_length = text[i].second.size();
    }
    std::FILE* file = std::fopen(tmp.c_str(), "wb");
    if (!file) fail("cannot create the file");
    png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
    png_infop info = png ? png_create_info_struct(png) : nullptr;
    volatile bool ok = png && info;
    if (ok && setjmp(png_jmpbuf(png)) == 0) {
        png_init_io(png, file);
        png_set_IHDR(png, info, film.width(), film.height(), 8, PNG_COLOR_TYPE_RGB, PNG_INTERLACE_NONE,
                     PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
        png_set_sRGB_gAMA_and_cHRM(png, info, PNG_sRGB_INTENT_PERCEPTUAL);
        png_set_text(png, info, chunks.data(), int(chunks.size()));
        png_write_info(png, info);
        for (unsigned y = 0; y < film.height(); ++y) png_write_row(png, &rows[std::size_t(y) * film.width() * 3]);
        png_write_end(png, nullptr);
    } else {
        ok = false;
    }
    png_destroy_write_struct(png ? &png : nullptr, info ? &info : nullptr);
    if (std::fclose(file) != 0) ok = false;
    if (!ok) fail("libpng could not write the image");
    std::error_code ec;
    std::filesystem::rename(tmp, path, ec);
    if (ec) fail("cannot move the finished image into place: " + ec.message());
}

}  // namespace photon::image_module

#endif
