// SPDX-License-Identifier: MIT
#pragma once
// photon/film/image_io.hpp's three functions, for programs that load OpenImageIO only when they
// touch an image (image_io_abi.hpp says why): the first call loads photon-image-io.so, looked for
//   1. at $PHOTON_IMAGE_MODULE, if set (a file);
//   2. next to the program (the build directory);
//   3. at PHOTON_IMAGE_MODULE_FROM_BIN relative to the program's folder (the installed layout,
//      set by CMake, e.g. ../lib/photon).
// A module that cannot be found or loaded is an ImageError naming every place tried.

#include <photon/film/film.hpp>
#include <photon/film/image_write_options.hpp>

#include <dlfcn.h>

#include <cstdlib>
#include <filesystem>
#include <string>
#include <system_error>
#include <vector>

#include "image_io_abi.hpp"

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
            if (version && check_writable && write && read && version() == photon_image_io_abi) return;  // kept loaded
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

/// photon::check_writable_image_path, through the module.
inline void check_writable_image_path(const std::filesystem::path& path) {
    char error[1024] = "";
    if (ImageIoModule::get().check_writable(path.c_str(), error, sizeof error) != 0) throw ImageError(error);
}

/// photon::write_image, through the module.
inline void write_image(const std::filesystem::path& path, const Film& film, const ImageWriteOptions& options = {}) {
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

}  // namespace photon::image_module
