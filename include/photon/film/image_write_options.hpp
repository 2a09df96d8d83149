// SPDX-License-Identifier: MIT
#pragma once
// What image writers share without OpenImageIO: the options of a write, the error it raises, and
// the naming of the temporary file a write goes through. film/image_io.hpp writes through
// OpenImageIO; programs that load it at run time (src/image_io_module) see only this header.

#include <atomic>
#include <chrono>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <unistd.h>
#include <utility>
#include <vector>

namespace photon {

struct ImageWriteOptions {
    float exposure = 1.0f;  ///< multiplies radiance before sRGB encoding (8-bit formats only)
    std::vector<std::pair<std::string, std::string>> metadata;  ///< string attributes stored in the file
};

/// Error raised by image input and output, naming the file.
class ImageError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

namespace detail {

inline bool is_float_format(const std::string& format) {
    return format == "openexr" || format == "hdr" || format == "pfm" || format == "tiff" || format == "fits";
}

/// A unique temporary path next to `path`, keeping its extension (OpenImageIO picks the format
/// from it).
inline std::filesystem::path temporary_sibling(const std::filesystem::path& path) {
    static std::atomic<unsigned> counter{0};
    const auto stamp = std::chrono::steady_clock::now().time_since_epoch().count();
    std::filesystem::path tmp = path;
    tmp.replace_filename("." + path.stem().string() + ".tmp-" + std::to_string(::getpid()) + "-" +
                         std::to_string(stamp % 1000000) + "-" + std::to_string(counter++) +
                         path.extension().string());
    return tmp;
}

}  // namespace detail

}  // namespace photon
