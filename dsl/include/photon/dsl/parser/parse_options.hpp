// SPDX-License-Identifier: MIT
#pragma once
// What a caller sets for one read of a scene: include paths or a sandboxed reader, the files it
// may open, predefined identifiers, where warnings go, and the bounds that keep any input from
// crashing or hanging the parser or taking all memory.

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <map>
#include <memory>
#include <cstdlib>
#include <optional>
#include <string>
#include <string_view>
#include <system_error>
#include <vector>

#include <photon/version.hpp>

#include "../description.hpp"
#include "../diagnostics.hpp"
#include "../file_access.hpp"

namespace photon::dsl {

/// Value of the identifier `photon_version` that photon declares before reading a scene, so that
/// `#ifdef (photon_version)` selects photon's own settings (POV-Ray skips them).
inline constexpr double photon_version = double(PHOTON_VERSION_MAJOR) + double(PHOTON_VERSION_MINOR) / 10.0;

/// POV-Ray's animation identifiers. The defaults are POV-Ray's without animation options (a
/// still image): every value 0, clock_on false.
struct AnimationClock {
    double clock = 0, clock_delta = 0, initial_clock = 0, final_clock = 0;
    double frame_number = 0, initial_frame = 0, final_frame = 0;
    bool clock_on = false;
};

/// What POV-Ray's trace(), min_extent() and max_extent() ask of an object while the scene is
/// read. The parser holds no geometry: the library answers (object_geometry.hpp's
/// library_object_geometry(), which the CLI sets).
struct ObjectGeometry {
    struct Bounds {
        Vector3 min, max;
    };
    struct Hit {
        Vector3 point, normal;
    };
    std::function<Bounds(const Object&)> bounds;
    /// The first hit of the ray origin + t direction, t > 0; nullopt when it misses.
    std::function<std::optional<Hit>(const Object&, const Vector3& origin, const Vector3& direction)> trace;
};

struct ParseOptions {
    /// Searched for `#include` files after the including file's own directory.
    std::vector<std::filesystem::path> include_paths;
    /// When set, `#include "name"` reads the text this returns instead of a file (nullopt: not
    /// found), and the file system is never touched: a sandbox for untrusted scenes (the fuzzer)
    /// and for scenes held in memory. Names are compared as written, for include loops.
    std::function<std::optional<std::string>(const std::string& name)> read_include;
    /// Which files the scene may open (POV-Ray's I/O restrictions): the level and the folders
    /// permitted besides those every read permits (scene_file_access()).
    FileAccessRules file_access;
    /// Floats declared before the scene is read (POV-Ray's `Declare=NAME=VALUE`).
    std::map<std::string, double> defines;
    DiagnosticSink diagnostics;
    /// Answers trace(), min_extent() and max_extent(); without it they are an error.
    std::shared_ptr<const ObjectGeometry> geometry;
    /// Values of POV-Ray's `image_width` and `image_height`.
    unsigned image_width = 800, image_height = 600;
    /// Values of `clock`, `clock_delta`, `frame_number`, ... (POV-Ray's +K options).
    AnimationClock animation;

    std::size_t max_file_bytes = std::size_t(64) << 20;
    unsigned max_include_depth = 32;
    unsigned max_nesting = 128;  ///< blocks, unions and parentheses inside each other
    std::uint64_t max_tokens = 200'000'000;
    std::uint64_t max_loop_iterations = 1'000'000;  ///< per #while loop
    std::size_t max_primitives = 10'000'000;        ///< objects and mesh triangles in the scene
    unsigned max_macro_depth = 256;                 ///< macro calls running inside each other (recursion)
    /// Array elements made over the whole read (each array's size when it is made, or copied
    /// on a write to a shared copy): bounds the memory arrays can take.
    std::uint64_t max_array_elements = std::uint64_t(1) << 24;
    /// Bytes of the scene's own data made over the whole read: the text of every file read
    /// (each #include again), every string made, arrays at their full size and the files the
    /// scene writes. An upper bound on the memory they take, since nothing made is subtracted.
    std::uint64_t max_parse_bytes = std::uint64_t(1) << 30;
    /// Seconds the read may take (0: no limit): a bound a render service can rely on when the
    /// others (tokens, loop iterations) still allow hours.
    double max_parse_seconds = 300;
};

/// The rules a read of the scene file `scene` follows: `options.file_access` and the folders
/// every read permits, as a POV-Ray `restricted` configuration would list them: the scene's
/// folder and its subfolders for reading and writing (`read+write*`: the scene's own maps,
/// includes and data files), each include folder and its subfolders for reading (`read*`: -I,
/// PHOTON_INCLUDE_PATH, POV-Ray's include folder, and the folder of each file an include folder
/// links to: Debian links POV-Ray's fonts there from /usr/share/fonts/truetype/povray), and the
/// current folder for reading and writing without its subfolders (Debian's `read+write = .`).
/// Links in the scene's folder get no such grant: whoever wrote the scene may have made them.
[[nodiscard]] inline FileAccessRules scene_file_access(const ParseOptions& options, const std::filesystem::path& scene) {
    FileAccessRules rules = options.file_access;
    const std::filesystem::path folder = resolved_path(scene).parent_path();
    rules.permit(folder, true, true, "the scene's folder " + folder.string());
    std::error_code ec;
    for (const auto& dir : options.include_paths) {
        rules.permit(dir, true, false, "the include folder " + resolved_path(dir).string());
        for (const auto& entry : std::filesystem::directory_iterator(dir, ec))
            if (entry.is_symlink(ec) && entry.is_regular_file(ec)) {
                const std::filesystem::path target = resolved_path(entry.path()).parent_path();
                if (!rules.permits(target / "x", FileAccess::read))
                    rules.permit(target, false, false, "the folder " + target.string() + " that " + entry.path().string() + " links to");
            }
    }
    const std::filesystem::path current = std::filesystem::current_path(ec);
    if (!ec) rules.permit(current, false, true, "the current folder " + resolved_path(current).string());
    return rules;
}

/// Where POV-Ray's standard include files (colors.inc, textures.inc, ...) are looked for after
/// the scene's own directory and the caller's paths: each directory of the environment variable
/// PHOTON_INCLUDE_PATH (separated by `:`), then POV-Ray 3.7's install directories (Debian's
/// povray-includes package puts them in /usr/share/povray-3.7/include) when they exist. photon
/// ships no copies of them: POV-Ray's licence covers those files, and the installed ones match
/// the POV-Ray a user compares with.
[[nodiscard]] inline std::vector<std::filesystem::path> standard_include_paths() {
    std::vector<std::filesystem::path> dirs;
    if (const char* env = std::getenv("PHOTON_INCLUDE_PATH")) {
        std::string_view rest(env);
        while (!rest.empty()) {
            const std::size_t colon = rest.find(':');
            const std::string_view dir = rest.substr(0, colon);
            if (!dir.empty()) dirs.emplace_back(std::string(dir));
            rest = colon == std::string_view::npos ? std::string_view() : rest.substr(colon + 1);
        }
    }
    for (const char* dir : {"/usr/share/povray-3.7/include", "/usr/local/share/povray-3.7/include"}) {
        std::error_code ec;
        if (std::filesystem::is_directory(dir, ec)) dirs.emplace_back(dir);
    }
    return dirs;
}

}  // namespace photon::dsl
