// SPDX-License-Identifier: MIT
// photon: renders POV-Ray scene files by photon mapping.
//
//   photon render scene.pov -o image.png [--width W --height H --mode rt|pm|pm-direct|reference|sppm ...]
//   photon check scene.pov
//   photon export-pov scene.pov -o flat.pov
//
// This unit reads the command line (CLI11, parsed here only); each command is its own unit
// (commands.hpp), so the program's parts compile in parallel.

#include <CLI/CLI.hpp>

#include <photon/dsl/diagnostics.hpp>
#include <photon/version.hpp>

#include "commands.hpp"
#include "setting_options.hpp"

#include <cstdlib>
#include <exception>
#include <iostream>
#include <string>

namespace {

using photon::cli::SceneOptions;

/// The options of every command that reads a scene.
void add_scene_options(CLI::App& cmd, SceneOptions& so) {
    cmd.add_option("scene", so.scene, "The scene file (POV-Ray 3.7 language, see docs/scene-language.md)")
        ->required()
        ->check(CLI::ExistingFile);
    // One value per flag, so that `-D A=1 scene.pov` leaves the scene alone; repeat the flag.
    cmd.add_option("-D,--define", so.defines, "Declare a float before reading the scene: NAME=VALUE (repeatable)")
        ->allow_extra_args(false)
        ->multi_option_policy(CLI::MultiOptionPolicy::TakeAll);
    cmd.add_option("-I,--include-path", so.include_paths, "Also look for #include files in DIR (repeatable), before PHOTON_INCLUDE_PATH and POV-Ray's own include directory")
        ->allow_extra_args(false)
        ->multi_option_policy(CLI::MultiOptionPolicy::TakeAll);
    // POV-Ray's animation options, for the scenes that read `clock` or `frame_number`.
    cmd.add_option("--clock", so.animation.clock, "The scene's `clock` for a still image (POV-Ray's +K / Clock=); sets clock_on");
    cmd.add_option("--frames", so.frames, "FIRST:LAST: the animation's frame range (POV-Ray's Initial_Frame/Final_Frame)");
    cmd.add_option("--clock-range", so.clock_range, "FROM:TO: the clock at the first and last frame (POV-Ray's Initial_Clock/Final_Clock, default 0:1)");
    cmd.add_option("--frame", so.animation.frame, "Read frame N of the animation (its `frame_number`; default the first frame of --frames)");
    cmd.add_flag("--strict", so.strict, "Treat warnings as errors (exit status 1)");
    // POV-Ray's I/O restrictions (povray.conf), docs/robustness.md.
    cmd.add_option("--io-restrictions", so.io_restrictions,
                   "Which files the scene may open, as POV-Ray's [File I/O Security]: restricted (only the scene's "
                   "folder, the include path, the current folder and the permitted paths), read-only (read any file, "
                   "write only there) or none (default: --io-config's level, else restricted)")
        ->check(CLI::IsMember({"none", "read-only", "restricted"}));
    cmd.add_option("--io-config", so.io_config,
                   "A povray.conf (POV-Ray's syntax) whose [File I/O Security] level and [Permitted Paths] apply")
        ->check(CLI::ExistingFile);
    cmd.add_option("--permit-path", so.permitted_paths, "Also let the scene read files in DIR and its subfolders (repeatable)")
        ->allow_extra_args(false)
        ->multi_option_policy(CLI::MultiOptionPolicy::TakeAll);
    cmd.add_option("--max-parse-seconds", so.max_parse_seconds,
                   "Stop reading the scene after this many seconds, with an error (0: no limit)")
        ->capture_default_str()
        ->check(CLI::NonNegativeNumber);
    cmd.add_flag("-q,--quiet", so.quiet, "Print errors only");
}

}  // namespace

int main(int argc, char** argv) {
    CLI::App app{"photon: global illumination by photon mapping (Jensen 1996) for POV-Ray 3.7 scene files.", "photon"};
    app.footer(
        "Examples:\n"
        "  photon render examples/scenes/cornell.pov -o cornell.png\n"
        "  photon render examples/scenes/room1.pov -o room1.exr --width 400 --height 300 --mode rt\n"
        "  photon check examples/scenes/room2.pov\n"
        "  photon export-pov my.pov -o flat.pov   # one self-contained file for POV-Ray\n"
        "\n"
        "Settings come from the scene file (global_settings, and photon's own settings inside\n"
        "#ifdef (photon_version) ... #end); command-line options override them. The language, its\n"
        "units and the settings are described in docs/scene-language.md. Exit status: 0 success,\n"
        "1 error, 2 bad usage, 130 interrupted (the image so far is written, marked partial).");
    app.set_version_flag("--version", std::to_string(photon::version_major) + "." +
                                          std::to_string(photon::version_minor) + "." +
                                          std::to_string(photon::version_patch));
    app.require_subcommand(1);

    photon::cli::SceneOptions so;
    photon::cli::RenderOptions ro;
    photon::cli::SettingOptions settings;
    std::string export_output;

    CLI::App* render = app.add_subcommand("render", "Render a scene file to an image");
    add_scene_options(*render, so);
    render
        ->add_option("-o,--output", ro.output,
                     "Image to write: .png, .exr, .jpg, .tif, .hdr (anything OpenImageIO writes). "
                     "Floating-point formats hold radiance, 8-bit ones sRGB")
        ->required();
    settings.add_to(*render);
    render->add_option("--exposure", ro.exposure, "Multiplies radiance before 8-bit output (PNG, JPEG)")
        ->check(CLI::PositiveNumber);
    render->add_flag("--no-stats", ro.no_stats, "Do not print the statistics table");
    render->add_option("--error-image", ro.error_image,
                       "pm, sppm and reference: also write each pixel's estimated error: |A - B| / 2 of the two "
                       "independent half-images (sppm, reference), or pm's distance to its short sppm judge with "
                       "the judge's noise taken out (an .exr keeps it linear)");
    render->add_flag("--no-error-estimate", ro.no_error_estimate,
                     "pm: do not estimate the error (it runs sppm for about a tenth of pm's own time again to measure "
                     "pm's noise and bias; needed by --target-error)");
    render->add_flag("--no-mis", ro.no_mis,
                     "reference: direct light by shadow rays alone, without multiple importance sampling "
                     "(to measure what it gains)");

    CLI::App* check = app.add_subcommand("check", "Read and build a scene, report what it holds and any warnings");
    add_scene_options(*check, so);
    settings.add_to(*check);  // the settings and the plan a render with them would use

    CLI::App* export_pov = app.add_subcommand(
        "export-pov",
        "Write the scene as one self-contained POV-Ray 3.7 file (declarations, includes and expressions "
        "evaluated; photon's own settings inside #ifdef (photon_version))");
    add_scene_options(*export_pov, so);
    export_pov->add_option("-o,--output", export_output, "File to write (default: standard output)");

    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
        const int code = app.exit(e);
        return code == 0 ? EXIT_SUCCESS : photon::cli::exit_usage;
    }

    try {
        if (render->parsed()) {
            ro.overrides = settings.overrides();
            if (ro.no_error_estimate) ro.overrides["pm_error_passes"] = std::uint64_t(0);
            return photon::cli::run_render(so, ro);
        }
        if (check->parsed()) return photon::cli::run_check(so, settings.overrides());
        return photon::cli::run_export(so, export_output);
    } catch (const photon::dsl::Error& e) {
        std::cerr << so.format({photon::dsl::Severity::error, e.location(), e.message(), {}, {}}) << '\n';
    } catch (const std::exception& e) {
        std::cerr << "photon: error: " << e.what() << '\n';
    }
    return photon::cli::exit_error;
}
