// SPDX-License-Identifier: MIT
#pragma once
// What a caller sets for one read of a scene: include paths or a sandboxed reader, predefined
// identifiers, where warnings go, and the bounds that keep any input from crashing or hanging the parser.

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <map>
#include <optional>
#include <photon/version.hpp>
#include <string>
#include <vector>

#include "../diagnostics.hpp"

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

struct ParseOptions {
    /// Searched for `#include` files after the including file's own directory.
    std::vector<std::filesystem::path> include_paths;
    /// When set, `#include "name"` reads the text this returns instead of a file (nullopt: not
    /// found), and the file system is never touched: a sandbox for untrusted scenes (the fuzzer)
    /// and for scenes held in memory. Names are compared as written, for include loops.
    std::function<std::optional<std::string>(const std::string& name)> read_include;
    /// Floats declared before the scene is read (POV-Ray's `Declare=NAME=VALUE`).
    std::map<std::string, double> defines;
    DiagnosticSink diagnostics;
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
};

}  // namespace photon::dsl
