// SPDX-License-Identifier: MIT
#pragma once
// What image writers share without OpenImageIO: the options of a write, the error it raises, and
// the naming of the temporary file a write goes through. film/image_io.hpp writes through
// OpenImageIO; programs that load it at run time (src/image_io_module) see only this header.

#include <atomic>
#include <cerrno>
#include <chrono>
#include <fcntl.h>
#include <filesystem>
#include <system_error>
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

/// Throws ImageError if no file can be written at `path`: missing directory, `path` a directory,
/// or a directory without write permission (the format is the writer's to check).
inline void check_writable_location(const std::filesystem::path& path) {
    namespace fs = std::filesystem;
    const fs::path dir = path.has_parent_path() ? path.parent_path() : fs::path(".");
    std::error_code ec;
    if (!fs::is_directory(dir, ec))
        throw ImageError(path.string() + ": output directory '" + dir.string() + "' does not exist");
    if (fs::is_directory(path, ec)) throw ImageError(path.string() + ": is a directory");
    if (::access(dir.c_str(), W_OK) != 0)
        throw ImageError(path.string() + ": output directory '" + dir.string() + "' is not writable");
    // access() says yes to root and knows nothing of read-only file systems: create and remove
    // the kind of temporary file a write will create.
    const fs::path probe_file = temporary_sibling(path);
    const int fd = ::open(probe_file.c_str(), O_WRONLY | O_CREAT | O_EXCL, 0600);
    if (fd < 0)
        throw ImageError(path.string() + ": cannot create a file in '" + dir.string() + "': " +
                         std::generic_category().message(errno));
    ::close(fd);
    ::unlink(probe_file.c_str());
}

}  // namespace detail

}  // namespace photon
