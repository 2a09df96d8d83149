// SPDX-License-Identifier: MIT
#pragma once
// photon/film/image_io.hpp's three functions, for programs that load OpenImageIO only when they
// touch an image (image_io_abi.hpp says why), PNG files excepted where libpng is linked
// (png_output.hpp, photon/io/png_file.hpp): the first call loads photon-image-io.so, looked for
//   1. at $PHOTON_IMAGE_MODULE, if set (a file);
//   2. next to the program (the build directory);
//   3. at PHOTON_IMAGE_MODULE_FROM_BIN relative to the program's folder (the installed layout,
//      set by CMake, e.g. ../lib/photon).
// A module that cannot be found or loaded is an ImageError naming every place tried.

#include <photon/film/film.hpp>
#include <photon/film/image_write_options.hpp>
#include <photon/texture/pixel_grid.hpp>

#include <dlfcn.h>

#include <cstdlib>
#include <filesystem>
#include <string>
#include <system_error>
#include <vector>

#include <photon/io/png_file.hpp>

#include "image_io_abi.hpp"
#include "png_output.hpp"

#ifndef PHOTON_IMAGE_MODULE_FROM_BIN
#define PHOTON_IMAGE_MODULE_FROM_BIN "../lib/photon"
#endif

namespace photon::image_module {

inline constexpr const char* module_file = "photon-image-io.so";

class ImageIoModule {
public:
    /// The module, loaded on first use (thread-safe); throws ImageError if it cannot be.
    static const ImageIoModule& get() {
        static const ImageIoModule loaded;
        return loaded;
    }

    photon_check_writable_image_fn check_writable = nullptr;
    photon_write_image_fn write = nullptr;
    photon_read_image_fn read = nullptr;
    photon_read_pixel_grid_fn read_pixels = nullptr;

private:
    ImageIoModule() {
        namespace fs = std::filesystem;
        std::vector<fs::path> places;
        if (const char* env = std::getenv("PHOTON_IMAGE_MODULE"); env && *env) places.emplace_back(env);
        std::error_code ec;
        const fs::path program = fs::read_symlink("/proc/self/exe", ec);
        if (!ec) {
            places.push_back(program.parent_path() / module_file);
            places.push_back((program.parent_path() / PHOTON_IMAGE_MODULE_FROM_BIN / module_file).lexically_normal());
        }
        std::string tried;
        for (const fs::path& place : places) {
            if (!fs::exists(place, ec)) {
                tried += "\n  " + place.string() + ": no such file";
                continue;
            }
            void* handle = ::dlopen(place.c_str(), RTLD_NOW | RTLD_LOCAL);
            if (!handle) {
                const char* why = ::dlerror();
                tried += "\n  " + place.string() + ": " + (why ? why : "cannot be loaded");
                continue;
            }
            const auto version = symbol<photon_image_io_abi_version_fn>(handle, "photon_image_io_abi_version");
            check_writable = symbol<photon_check_writable_image_fn>(handle, "photon_check_writable_image");
            write = symbol<photon_write_image_fn>(handle, "photon_write_image");
            read = symbol<photon_read_image_fn>(handle, "photon_read_image");
            read_pixels = symbol<photon_read_pixel_grid_fn>(handle, "photon_read_pixel_grid");
            if (version && check_writable && write && read && read_pixels && version() == photon_image_io_abi)
                return;  // kept loaded
            tried += "\n  " + place.string() + ": not photon's image module of this version";
            ::dlclose(handle);
        }
        throw ImageError("cannot load photon's image module " + std::string(module_file) +
                         " (it writes and reads images through OpenImageIO; it is built and installed with the "
                         "photon program). Tried:" + tried);
    }

    template <class Fn>
    static Fn symbol(void* handle, const char* name) {
        return reinterpret_cast<Fn>(::dlsym(handle, name));
    }
};

/// photon::check_writable_image_path, through the module (a PNG file with libpng, without it).
inline void check_writable_image_path(const std::filesystem::path& path) {
#if defined(PHOTON_HAS_PNG) && PHOTON_HAS_PNG
    if (is_png_path(path)) return detail::check_writable_location(path);
#endif
    char error[1024] = "";
    if (ImageIoModule::get().check_writable(path.c_str(), error, sizeof error) != 0) throw ImageError(error);
}

/// photon::write_image, through the module (a PNG file with libpng, without it).
inline void write_image(const std::filesystem::path& path, const Film& film, const ImageWriteOptions& options = {}) {
#if defined(PHOTON_HAS_PNG) && PHOTON_HAS_PNG
    if (is_png_path(path)) return write_png(path, film, options);
#endif
    std::vector<float> rgb;
    rgb.reserve(3 * film.pixels().size());
    for (const auto& p : film.pixels()) rgb.insert(rgb.end(), {p[0], p[1], p[2]});
    std::vector<const char*> metadata;
    for (const auto& [key, value] : options.metadata) metadata.insert(metadata.end(), {key.c_str(), value.c_str()});
    char error[1024] = "";
    if (ImageIoModule::get().write(path.c_str(), rgb.data(), film.width(), film.height(), options.exposure,
                                   metadata.data(), options.metadata.size(), error, sizeof error) != 0)
        throw ImageError(error);
}

/// photon::read_image, through the module.
inline Film read_image(const std::filesystem::path& path) {
    Film film;
    std::vector<float> rgb;
    struct Target {
        Film* film;
        std::vector<float>* rgb;
    } target{&film, &rgb};
    const photon_image_allocate_fn allocate = [](void* context, unsigned width, unsigned height) -> float* {
        auto* t = static_cast<Target*>(context);
        *t->film = Film(width, height);
        t->rgb->assign(3 * std::size_t(width) * height, 0.0f);
        return t->rgb->data();
    };
    char error[1024] = "";
    if (ImageIoModule::get().read(path.c_str(), allocate, &target, error, sizeof error) != 0) throw ImageError(error);
    for (std::size_t i = 0; i < film.pixels().size(); ++i)
        film.pixels()[i] = Rgb<float>(rgb[3 * i], rgb[3 * i + 1], rgb[3 * i + 2]);
    return film;
}

/// photon::read_pixel_grid (photon/io/image_file.hpp), through the module (a PNG file with
/// libpng, without it: photon/io/png_file.hpp).
inline PixelGrid read_pixel_grid(const std::filesystem::path& path, ImageGamma gamma = {}) {
#if defined(PHOTON_HAS_PNG) && PHOTON_HAS_PNG
    if (auto grid = read_png_pixel_grid(path, gamma, max_image_file_pixels)) return std::move(*grid);
#endif
    struct Target {
        unsigned width = 0, height = 0;
        std::vector<float> rgba;
    } target;
    const photon_image_allocate_fn allocate = [](void* context, unsigned width, unsigned height) -> float* {
        auto* t = static_cast<Target*>(context);
        t->width = width, t->height = height;
        t->rgba.assign(5 * std::size_t(width) * height, 0.0f);
        return t->rgba.data();
    };
    unsigned flags = 0, max_value = 0;
    char error[1024] = "";
    if (ImageIoModule::get().read_pixels(path.c_str(), int(gamma.kind), gamma.gamma, allocate, &target, &flags,
                                         &max_value, error, sizeof error) != 0)
        throw ImageError(error);
    std::vector<PixelGrid::Pixel> pixels(std::size_t(target.width) * target.height);
    for (std::size_t i = 0; i < pixels.size(); ++i)
        pixels[i] = {target.rgba[5 * i], target.rgba[5 * i + 1], target.rgba[5 * i + 2], target.rgba[5 * i + 3]};
    PixelGrid grid(target.width, target.height, std::move(pixels));
    if (flags & 4u) {
        grid.indices.resize(grid.pixels().size());
        for (std::size_t i = 0; i < grid.indices.size(); ++i) grid.indices[i] = std::uint8_t(target.rgba[5 * i + 4]);
    }
    grid.has_alpha = (flags & 1u) != 0;
    grid.grayscale = (flags & 2u) != 0;
    grid.max_value = max_value;
    return grid;
}

}  // namespace photon::image_module
