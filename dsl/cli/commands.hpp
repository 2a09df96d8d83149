// SPDX-License-Identifier: MIT
#pragma once
// The `photon` program's commands, each in its own translation unit so that they compile in
// parallel and only main.cpp parses CLI11: main.cpp reads the command line into these option
// structs and calls run_render (render_command.cpp), run_check (check_command.cpp) or
// run_export (export_command.cpp). Exit statuses are the program's: 0, 1 (error), 130 (interrupted).

#include <photon/dsl/animation.hpp>
#include <photon/dsl/build/settings.hpp>
#include <photon/dsl/diagnostics.hpp>
#include <photon/dsl/parser/parse_options.hpp>

#include <cstddef>
#include <map>
#include <string>
#include <vector>

namespace photon::cli {

inline constexpr int exit_error = 1;
inline constexpr int exit_usage = 2;
inline constexpr int exit_interrupted = 130;

/// Options shared by every command that reads a scene (scene_options.cpp).
struct SceneOptions {
    std::string scene;
    std::vector<std::string> defines;
    std::vector<std::string> include_paths;
    dsl::AnimationRequest animation;  // POV-Ray's +K, Initial_Frame/Final_Frame, Initial_Clock/Final_Clock
    std::string frames, clock_range;
    bool strict = false;
    bool quiet = false;
    /// POV-Ray's I/O restrictions: the level (empty: the configuration's, else photon's
    /// default), a povray.conf, and folders permitted for reading with their subfolders.
    std::string io_restrictions, io_config;
    std::vector<std::string> permitted_paths;
    double max_parse_seconds = dsl::ParseOptions{}.max_parse_seconds;
    /// The rules the scene is read under (parse_options sets them): messages quote a line of a
    /// file only when these permit reading it.
    dsl::FileAccessRules file_access;
    std::size_t warnings = 0;
    /// Constructs photon read but skipped or approximated: count per warning kind and keyword.
    std::map<std::string, std::map<std::string, std::size_t>> degraded;

    /// Counts each diagnostic and prints it (unless --quiet without --strict).
    dsl::DiagnosticSink sink();
    /// `d` as printed: its source line quoted only when the scene may read its file.
    [[nodiscard]] std::string format(const dsl::Diagnostic& d) const;
    /// How to read the scene: defines, include paths, the animation clock, and the image size
    /// (POV-Ray's image_width and image_height): the command line's --width and --height when
    /// given, else 800 x 600.
    dsl::ParseOptions parse_options(const dsl::SettingsOverrides& overrides);
    /// The identifiers clock, frame_number, ... from the animation options (POV-Ray's rules).
    dsl::AnimationClock animation_clock();
    /// Exit status 1 under --strict when there were warnings.
    [[nodiscard]] bool failed_strict() const;
};

/// `photon render`'s options: the render settings given on the command line, and the output.
struct RenderOptions {
    dsl::SettingsOverrides overrides;
    std::string output;
    float exposure = 1.0f;
    bool no_stats = false;
    bool no_mis = false;
    bool no_error_estimate = false;  ///< pm: no short sppm run to estimate its error
    std::string error_image;  ///< pm, sppm and reference: where to write the per-pixel error estimate
};

int run_render(SceneOptions& so, const RenderOptions& ro);
/// `photon check` takes render's settings options too: it reports the settings and the plan a
/// render with them would use, and reads the scene at their image size.
int run_check(SceneOptions& so, const dsl::SettingsOverrides& overrides);
int run_export(SceneOptions& so, const std::string& output);

}  // namespace photon::cli
