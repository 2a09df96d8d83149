// SPDX-License-Identifier: MIT
#pragma once
// The C interface of photon's image module (photon-image-io.so), shared by the module and the
// programs that load it (load_image_io.hpp). OpenImageIO pulls in hundreds of shared libraries
// whose loading and static initialisation cost a program time at every start (bench/README.md),
// for `photon --version` as for a render; the
// photon program and its tools load the module, and with it OpenImageIO, only when they read
// or write an image. Plain C types only, so the two sides need not agree on a C++ ABI.
// Every function returns 0 on success; otherwise it writes a NUL-terminated message of at most
// `error_size` bytes into `error` and returns non-zero.

#include <cstddef>

extern "C" {

/// Must equal photon_image_io_abi_version() of the module loaded.
inline constexpr int photon_image_io_abi = 2;

using photon_image_io_abi_version_fn = int (*)();

/// photon::check_writable_image_path: the extension names an image format and the directory
/// takes a new file.
using photon_check_writable_image_fn = int (*)(const char* path, char* error, std::size_t error_size);

/// photon::write_image of a width x height film of linear RGB triples (row-major, top row
/// first); `metadata` holds `metadata_pairs` key, value string pairs one after another.
using photon_write_image_fn = int (*)(const char* path, const float* rgb, unsigned width, unsigned height,
                                      float exposure, const char* const* metadata, std::size_t metadata_pairs,
                                      char* error, std::size_t error_size);

/// photon::read_image: calls `allocate(context, width, height)` for a buffer of width x height
/// RGB triples it then fills with linear radiance.
using photon_image_allocate_fn = float* (*)(void* context, unsigned width, unsigned height);
using photon_read_image_fn = int (*)(const char* path, photon_image_allocate_fn allocate, void* context,
                                     char* error, std::size_t error_size);

/// photon::read_pixel_grid: `gamma_kind` is photon::ImageGamma::Kind as an int (0 file, 1 none,
/// 2 power, 3 srgb), `gamma` its power. Calls `allocate(context, width, height)` for a buffer of
/// width x height RGBA quadruples plus a palette index each (5 floats, top row first) it then
/// fills; sets `*flags` (1: the file has alpha, 2: it is grey, 4: it is a palette image whose
/// indices are given) and `*max_value` (255, 65535, or 0 for floating point).
using photon_read_pixel_grid_fn = int (*)(const char* path, int gamma_kind, double gamma,
                                          photon_image_allocate_fn allocate, void* context, unsigned* flags,
                                          unsigned* max_value, char* error, std::size_t error_size);

}  // extern "C"
