// SPDX-License-Identifier: MIT
// photon-image-io.so: photon/film/image_io.hpp (OpenImageIO) behind the C interface of
// image_io_abi.hpp, loaded at run time by the photon program and its tools.

#include <photon/film/image_io.hpp>
#include <photon/io/image_file.hpp>

#include <cstring>
#include <exception>
#include <string>
#include <utility>
#include <vector>

#include "image_io_abi.hpp"

namespace {

void copy_message(const char* message, char* error, std::size_t error_size) {
    if (error_size == 0) return;
    std::strncpy(error, message, error_size - 1);
    error[error_size - 1] = '\0';
}

/// Runs `work`, turning any exception into the interface's error return.
template <class Work>
int guarded(Work&& work, char* error, std::size_t error_size) noexcept {
    try {
        work();
        return 0;
    } catch (const std::exception& e) {
        copy_message(e.what(), error, error_size);
    } catch (...) {
        copy_message("unknown error in photon's image module", error, error_size);
    }
    return 1;
}

}  // namespace

extern "C" {

__attribute__((visibility("default"))) int photon_image_io_abi_version() { return photon_image_io_abi; }

__attribute__((visibility("default"))) int photon_check_writable_image(const char* path, char* error,
                                                                       std::size_t error_size) {
    return guarded([&] { photon::check_writable_image_path(path); }, error, error_size);
}

__attribute__((visibility("default"))) int photon_write_image(const char* path, const float* rgb, unsigned width,
                                                              unsigned height, float exposure,
                                                              const char* const* metadata,
                                                              std::size_t metadata_pairs, char* error,
                                                              std::size_t error_size) {
    return guarded(
        [&] {
            photon::Film film(width, height);
            for (std::size_t i = 0; i < film.pixels().size(); ++i)
                film.pixels()[i] = photon::Rgb<float>(rgb[3 * i], rgb[3 * i + 1], rgb[3 * i + 2]);
            photon::ImageWriteOptions options;
            options.exposure = exposure;
            for (std::size_t i = 0; i < metadata_pairs; ++i) options.metadata.emplace_back(metadata[2 * i], metadata[2 * i + 1]);
            photon::write_image(path, film, options);
        },
        error, error_size);
}

__attribute__((visibility("default"))) int photon_read_image(const char* path, photon_image_allocate_fn allocate,
                                                             void* context, char* error, std::size_t error_size) {
    return guarded(
        [&] {
            const photon::Film film = photon::read_image(path);
            float* out = allocate(context, film.width(), film.height());
            for (std::size_t i = 0; i < film.pixels().size(); ++i)
                for (int c = 0; c < 3; ++c) out[3 * i + c] = film.pixels()[i][c];
        },
        error, error_size);
}

__attribute__((visibility("default"))) int photon_read_pixel_grid(const char* path, int gamma_kind, double gamma,
                                                                  photon_image_allocate_fn allocate, void* context,
                                                                  unsigned* flags, unsigned* max_value, char* error,
                                                                  std::size_t error_size) {
    return guarded(
        [&] {
            const photon::PixelGrid grid =
                photon::read_pixel_grid(path, photon::ImageGamma{photon::ImageGamma::Kind(gamma_kind), gamma});
            float* out = allocate(context, grid.width(), grid.height());
            for (std::size_t i = 0; i < grid.pixels().size(); ++i) {
                for (std::size_t c = 0; c < 4; ++c) out[5 * i + c] = grid.pixels()[i][c];
                out[5 * i + 4] = grid.indices.empty() ? 0.0f : float(grid.indices[i]);
            }
            *flags = (grid.has_alpha ? 1u : 0u) | (grid.grayscale ? 2u : 0u) | (grid.indices.empty() ? 0u : 4u);
            *max_value = grid.max_value;
        },
        error, error_size);
}

}  // extern "C"
