// SPDX-License-Identifier: MIT
// photon: renders POV-Ray scene files by photon mapping.
//
//   photon render scene.pov -o image.png [--width W --height H --mode rt|pm|pm-direct|reference|sppm ...]
//   photon check scene.pov
//   photon export-pov scene.pov -o flat.pov

#include <CLI/CLI.hpp>

#include <photon/dsl/dsl.hpp>
#include <photon/plan/plan_report.hpp>

#include "load_image_io.hpp"
#include "setting_options.hpp"

#include <atomic>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <mutex>
#include <optional>
#include <sstream>
#include <string>
#include <tuple>
#include <unistd.h>
#include <vector>

namespace {

namespace dsl = photon::dsl;
namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

constexpr int exit_error = 1;
constexpr int exit_usage = 2;
constexpr int exit_interrupted = 130;

std::atomic<bool> cancel_requested{false};

extern "C" void on_interrupt(int) {
    if (cancel_requested.load()) _exit(exit_interrupted);
    cancel_requested.store(true);
    static const char message[] =
        "\nphoton: interrupted: stopping, the image so far will be written "
        "(press Ctrl-C again to quit at once)\n";
    [[maybe_unused]] const auto n = ::write(STDERR_FILENO, message, sizeof message - 1);
}

/// Options shared by every command that reads a scene.
struct SceneOptions {
    std::string scene;
    std::vector<std::string> defines;
    std::vector<std::string> include_paths;
    dsl::AnimationRequest animation;  // POV-Ray's +K, Initial_Frame/Final_Frame, Initial_Clock/Final_Clock
    std::string frames, clock_range;
    bool strict = false;
    bool quiet = false;
    std::size_t warnings = 0;
    /// Constructs photon read but skipped or approximated: count per warning kind and keyword.
    std::map<std::string, std::map<std::string, std::size_t>> degraded;

    void add_to(CLI::App& cmd) {
        cmd.add_option("scene", scene, "The scene file (POV-Ray 3.7 language, see docs/scene-language.md)")
            ->required()
            ->check(CLI::ExistingFile);
        // One value per flag, so that `-D A=1 scene.pov` leaves the scene alone; repeat the flag.
        cmd.add_option("-D,--define", defines, "Declare a float before reading the scene: NAME=VALUE (repeatable)")
            ->allow_extra_args(false)
            ->multi_option_policy(CLI::MultiOptionPolicy::TakeAll);
        cmd.add_option("-I,--include-path", include_paths, "Also look for #include files in DIR (repeatable), before PHOTON_INCLUDE_PATH and POV-Ray's own include directory")
            ->allow_extra_args(false)
            ->multi_option_policy(CLI::MultiOptionPolicy::TakeAll);
        // POV-Ray's animation options, for the scenes that read `clock` or `frame_number`.
        cmd.add_option("--clock", animation.clock, "The scene's `clock` for a still image (POV-Ray's +K / Clock=); sets clock_on");
        cmd.add_option("--frames", frames, "FIRST:LAST: the animation's frame range (POV-Ray's Initial_Frame/Final_Frame)");
        cmd.add_option("--clock-range", clock_range, "FROM:TO: the clock at the first and last frame (POV-Ray's Initial_Clock/Final_Clock, default 0:1)");
        cmd.add_option("--frame", animation.frame, "Read frame N of the animation (its `frame_number`; default the first frame of --frames)");
        cmd.add_flag("--strict", strict, "Treat warnings as errors (exit status 1)");
        cmd.add_flag("-q,--quiet", quiet, "Print errors only");
    }

    dsl::DiagnosticSink sink() {
        return [this](const dsl::Diagnostic& d) {
            ++warnings;
            if (!d.kind.empty()) ++degraded[d.kind][d.keyword];
            if (!quiet || strict) std::cerr << dsl::format_diagnostic(d) << '\n';
        };
    }

    dsl::ParseOptions parse_options(unsigned width, unsigned height) {
        dsl::ParseOptions o;
        o.diagnostics = sink();
        o.geometry = dsl::library_object_geometry();  // trace(), min_extent(), max_extent()
        o.image_width = width;
        o.image_height = height;
        for (const auto& dir : include_paths) o.include_paths.emplace_back(dir);
        for (auto& dir : dsl::standard_include_paths()) o.include_paths.push_back(std::move(dir));
        for (const auto& d : defines) {
            const auto eq = d.find('=');
            const std::string name = d.substr(0, eq);
            double value = 1;
            if (eq != std::string::npos) {
                try {
                    std::size_t used = 0;
                    value = std::stod(d.substr(eq + 1), &used);
                    if (used != d.size() - eq - 1) throw std::invalid_argument("trailing characters");
                } catch (const std::exception&) {
                    throw std::invalid_argument("--define " + d + ": expected NAME=NUMBER");
                }
            }
            if (name.empty()) throw std::invalid_argument("--define " + d + ": expected NAME=NUMBER");
            o.defines[name] = value;
        }
        o.animation = animation_clock();
        return o;
    }

    /// The identifiers clock, frame_number, ... from the animation options (POV-Ray's rules).
    dsl::AnimationClock animation_clock() {
        const auto pair = [](const std::string& text, const char* option) {
            const auto colon = text.find(':');
            try {
                std::size_t a = 0, b = 0;
                const double first = std::stod(text.substr(0, colon), &a);
                const std::string rest = colon == std::string::npos ? "" : text.substr(colon + 1);
                const double second = std::stod(rest, &b);
                if (a != colon || b != rest.size()) throw std::invalid_argument("trailing characters");
                return std::pair{first, second};
            } catch (const std::exception&) {
                throw std::invalid_argument(std::string(option) + " " + text + ": expected two numbers A:B");
            }
        };
        dsl::AnimationRequest r = animation;
        if (!frames.empty()) std::tie(r.initial_frame, r.final_frame) = pair(frames, "--frames");
        if (!clock_range.empty()) std::tie(r.initial_clock, r.final_clock) = pair(clock_range, "--clock-range");
        return dsl::animation_clock(r);
    }

    /// Exit status 1 under --strict when there were warnings.
    [[nodiscard]] bool failed_strict() const {
        if (!strict || warnings == 0) return false;
        std::cerr << "photon: " << warnings << " warning" << (warnings == 1 ? "" : "s") << " (--strict)\n";
        return true;
    }
};

/// `photon render`'s options: the render settings (from the settings table), and the output.
struct RenderOptions {
    photon::cli::SettingOptions settings;
    std::string output;
    float exposure = 1.0f;
    bool no_stats = false;
    bool no_mis = false;
    std::string error_image;  ///< sppm and reference: where to write the per-pixel error estimate
};

std::string vec(const photon::Vec3<float>& v) {
    std::ostringstream s;
    s << '<' << v.x << ", " << v.y << ", " << v.z << '>';
    return s.str();
}

std::string rgb(const photon::Rgb<float>& c) {
    std::ostringstream s;
    if (c.x == c.y && c.y == c.z)
        s << c.x;
    else
        s << '<' << c.x << ", " << c.y << ", " << c.z << '>';
    return s.str();
}

/// An estimate's max radius as the settings line shows it: 0 is derived from the photon density.
std::string radius_text(float r) {
    std::ostringstream o;
    if (r > 0) o << r; else o << "auto";
    return o.str();
}

std::string settings_line(const photon::RenderSettings& s) {
    std::ostringstream o;
    o << s.width << " x " << s.height << ", mode " << photon::to_string(s.mode) << ", " << s.samples_per_pixel
      << " samples per pixel, ray depth " << s.max_ray_depth << ", " << s.shadow_samples << " shadow samples";
    if (s.mode == photon::RenderMode::sppm)
        o << "; sppm: " << s.sppm_passes << " passes of " << s.sppm_photons_per_pass << " photons, initial radius "
          << (s.sppm_initial_radius > 0 ? std::to_string(s.sppm_initial_radius) : std::string("auto"))
          << ", photon depth " << s.max_photon_depth;
    else if (s.mode != photon::RenderMode::rt)
        o << "; photons: " << s.global_photons << " global (k " << s.global_estimate.k << ", radius "
          << radius_text(s.global_estimate.max_radius) << "), " << s.caustic_photons << " caustic (k "
          << s.caustic_estimate.k << ", radius " << radius_text(s.caustic_estimate.max_radius) << "), photon depth "
          << s.max_photon_depth
          << ", final gather " << s.final_gather_rays;
    if (s.mode == photon::RenderMode::reference && !s.reference_mis) o << ", no MIS";
    if (s.time_limit > 0) o << ", time limit " << s.time_limit << " s";
    if (s.target_error > 0) o << ", target error " << 100 * s.target_error << "%";
    o << ", seed " << s.seed;
    return o.str();
}

/// Prints what the scene holds: the report of `photon check`.
void report(const std::string& file, const dsl::SceneDescription& desc, const dsl::BuiltScene<float>& b) {
    const auto& scene = b.scene;
    std::cout << "scene      " << file << " (" << desc.files.size() << " file" << (desc.files.size() == 1 ? "" : "s")
              << ")\n";
    const auto& cam = b.camera;
    const float hfov =
        2.0f * std::atan(0.5f * glm::length(cam.right()) / glm::length(cam.direction())) * 180.0f / photon::pi<float>;
    std::cout << "camera     location " << vec(cam.location()) << ", direction " << vec(cam.direction()) << ", right "
              << vec(cam.right()) << ", up " << vec(cam.up()) << " (horizontal field of view " << hfov << " deg)\n";
    std::cout << "lights     " << scene.lights().size() << '\n';
    for (const auto& light : scene.lights()) {
        const float radius = photon::light_radius(light);
        std::cout << "           " << (radius > 0 ? "sphere light" : "point light") << " at "
                  << vec(photon::light_center(light));
        if (radius > 0) std::cout << ", radius " << radius;
        std::cout << ", power " << rgb(photon::light_power(light)) << " W, intensity "
                  << rgb(photon::radiant_intensity(light)) << " W/sr";
        if (const auto& cone = photon::light_cone(light))
            std::cout << ", " << (cone->is_soft() ? "spotlight profile " : "cone ") << vec(cone->axis()) << " half-angle "
                      << cone->half_angle_degrees() << " deg";
        const auto& falloff = photon::light_falloff(light);
        using Kind = std::remove_cvref_t<decltype(falloff)>::Kind;
        if (falloff.kind == Kind::constant) std::cout << ", no falloff";
        if (falloff.kind == Kind::fade)
            std::cout << ", fade 1 / (1 + (d / " << falloff.distance << ")^" << falloff.power << ")";
        if (!photon::light_casts_shadows(light)) std::cout << ", shadowless";
        std::cout << '\n';
    }
    std::map<std::string, std::size_t> kinds;
    std::size_t targets = 0, shadowless = 0;
    for (std::uint32_t i = 0; i < scene.objects().size(); ++i) {
        const auto& o = scene.objects()[i];
        ++kinds[std::visit([](const auto& shape) { return photon::plan::shape_name(shape); }, o.shape)];
        targets += scene.is_caustic_target(i);
        shadowless += !o.options.casts_shadow;
    }
    std::cout << "objects    " << scene.objects().size() << (kinds.empty() ? "" : ":");  // none: all skipped
    const char* sep = " ";
    for (const auto& [name, n] : kinds) std::cout << sep << n << ' ' << name, sep = ", ";
    std::cout << "; " << targets << " caustic target" << (targets == 1 ? "" : "s");
    if (shadowless) std::cout << ", " << shadowless << " without shadow";
    std::cout << '\n';
    std::cout << "materials  " << scene.materials().size() << '\n';
    for (std::size_t i = 0; i < scene.materials().size(); ++i) {
        const auto& p = scene.materials()[i].params();
        std::cout << "           #" << i << ": diffuse " << rgb(p.diffuse) << ", mirror " << rgb(p.specular)
                  << ", transmission " << rgb(p.transmission);
        if (p.transmission != photon::Rgb<float>(0) || p.fresnel)
            std::cout << ", ior " << p.ior << (p.fresnel ? " (Fresnel)" : "");
        if (p.phong > 0) std::cout << ", phong " << p.phong << " size " << p.phong_exponent;
        if (p.blinn > 0) std::cout << ", blinn " << p.blinn << " exponent " << p.blinn_exponent;
        if (p.metallic > 0 && (p.phong > 0 || p.blinn > 0)) std::cout << ", metallic " << p.metallic;
        if (p.brilliance != 1) std::cout << ", brilliance " << p.brilliance;
        if (p.ambient != photon::Rgb<float>(0)) std::cout << ", ambient " << rgb(p.ambient);
        if (p.normal_field) std::cout << ", normal pattern (tilted shading normal)";
        std::cout << '\n';
    }
    std::cout << "settings   " << settings_line(b.settings) << '\n';
    const char* label = "plan       ";  // what a render of this scene will do (plan/effects_plan.hpp)
    for (const std::string& line :
         photon::plan_lines(photon::plan_effects(scene, b.camera, b.settings), photon::to_string(b.settings.mode))) {
        std::cout << label << line << '\n';
        label = "           ";
    }
}

/// Progress of pass 2: a bar on a terminal, a line every 10% otherwise.
class Progress {
public:
    explicit Progress(bool enabled) : enabled_(enabled), tty_(::isatty(STDERR_FILENO) != 0), start_(Clock::now()) {}

    /// One report of `phase` being `fraction` done; a new phase starts a new bar (or new lines).
    void operator()(photon::RenderPhase phase, double fraction) {
        if (!enabled_) return;
        const std::lock_guard lock(mutex_);
        if (phase != phase_) {
            if (tty_ && last_ >= 0 && !line_done_) std::fputc('\n', stderr);
            phase_ = phase;
            start_ = Clock::now();
            last_ = -1;
            step_ = 0;
            line_done_ = false;
        }
        const double elapsed = std::chrono::duration<double>(Clock::now() - start_).count();
        const char* label = photon::to_string(phase);
        if (tty_) {
            if (fraction < 1.0 && last_ >= 0 && elapsed - last_ < 0.1) return;
            last_ = elapsed;
            constexpr int width = 40;
            const int filled = int(fraction * width);
            std::string bar(std::size_t(filled), '#');
            bar.append(std::size_t(width - filled), '-');
            const double left = fraction > 0 ? elapsed * (1.0 - fraction) / fraction : 0.0;
            std::fprintf(stderr, "\rphoton: %-24s [%s] %3d%%  %.1f s, %.1f s left  ", label, bar.c_str(),
                         int(fraction * 100), elapsed, left);
            if (fraction >= 1.0) {
                std::fputc('\n', stderr);
                line_done_ = true;
            }
        } else {
            const int step = int(fraction * 10);
            if (step <= step_) return;
            step_ = step;
            std::fprintf(stderr, "photon: %s %d%% (%.1f s)\n", label, step * 10, elapsed);
        }
        std::fflush(stderr);
    }
    void finish() {
        if (enabled_ && tty_ && last_ >= 0 && !line_done_) std::fputc('\n', stderr);
    }

private:
    bool enabled_, tty_;
    Clock::time_point start_;
    std::mutex mutex_;
    photon::RenderPhase phase_ = photon::RenderPhase::image;
    double last_ = -1;
    int step_ = 0;
    bool line_done_ = false;
};

int run_render(SceneOptions& so, const RenderOptions& ro) {
    const fs::path output(ro.output);
    photon::image_module::check_writable_image_path(output);
    dsl::BuildOptions bo;
    bo.diagnostics = so.sink();
    bo.overrides = ro.settings.overrides();
    // POV-Ray's image_width and image_height are the command line's size when it gives one.
    auto size = [&](const char* key, unsigned otherwise) {
        const auto it = bo.overrides.find(key);
        if (it == bo.overrides.end() || dsl::setting_value_problem(*dsl::find_setting(key), it->second))
            return otherwise;  // build() reports it
        return unsigned(std::get<std::uint64_t>(it->second));
    };

    const dsl::SceneDescription desc =
        dsl::parse_file(so.scene, so.parse_options(size("width", 800), size("height", 600)));
    dsl::BuiltScene<float> built = dsl::build<float>(desc, bo);
    if (so.failed_strict()) return exit_error;
    photon::RenderSettings& settings = built.settings;
    if (ro.no_mis) settings.reference_mis = false;
    const bool budget = settings.time_limit > 0 || settings.target_error > 0;
    if (budget && settings.mode != photon::RenderMode::sppm && settings.mode != photon::RenderMode::reference)
        std::cerr << "photon: warning: --time and --target-error apply to the sppm and reference modes; mode "
                  << photon::to_string(settings.mode) << " renders once, as its settings ask\n";
    // A budget without a pass count of its own decides when sppm stops.
    if (budget && settings.mode == photon::RenderMode::sppm && !bo.overrides.count("sppm_passes") &&
        !desc.settings.render.count("sppm_passes"))
        settings.sppm_passes = photon::SettingsLimits::max_sppm_passes;
    if (!ro.error_image.empty() && settings.mode != photon::RenderMode::sppm &&
        settings.mode != photon::RenderMode::reference)
        throw std::runtime_error("--error-image: only the sppm and reference modes estimate their error (mode " +
                                 std::string(photon::to_string(settings.mode)) + ")");
    if (!ro.error_image.empty()) photon::image_module::check_writable_image_path(ro.error_image);
    if (!so.quiet) {
        std::cerr << "photon: " << so.scene << ": " << built.scene.objects().size() << " objects, "
                  << built.scene.lights().size() << " light" << (built.scene.lights().size() == 1 ? "" : "s") << ", "
                  << built.scene.materials().size() << " materials\n"
                  << "photon: " << settings_line(settings) << '\n';
        for (const std::string& line : photon::plan_lines(photon::plan_effects(built.scene, built.camera, settings),
                                                          photon::to_string(settings.mode)))
            std::cerr << "photon: plan: " << line << '\n';
    }

    Progress progress(!so.quiet);
    settings.progress = [&](photon::RenderPhase phase, double f) { progress(phase, f); };
    const bool progressive = settings.mode == photon::RenderMode::sppm || (settings.mode == photon::RenderMode::reference && budget);
    if (progressive && !so.quiet) {
        // One line per pass (sppm) or round (reference): the unit the image improves by, and can
        // be stopped after, with the image's estimated error.
        settings.progress = {};
        settings.on_pass = [sppm = settings.mode == photon::RenderMode::sppm,
                            capped = !budget || bo.overrides.count("sppm_passes") || desc.settings.render.count("sppm_passes")](
                               const photon::PassReport& r) {
            char error[96] = "";
            if (r.error.available)
                std::snprintf(error, sizeof error, ", estimated error %.3g%% (worst block %.3g%%)", 100 * r.error.relative_rmse,
                              100 * r.error.worst_block);
            if (sppm && capped)
                std::fprintf(stderr, "photon: sppm pass %u/%u (%.1f s)%s\n", r.pass, r.most, r.seconds, error);
            else
                std::fprintf(stderr, "photon: %s %u (%.1f s)%s\n", sppm ? "sppm pass" : "reference round", r.pass, r.seconds,
                             error);
        };
    }
    settings.cancel = &cancel_requested;
    struct sigaction action {};
    action.sa_handler = on_interrupt;
    sigemptyset(&action.sa_mask);
    sigaction(SIGINT, &action, nullptr);
    sigaction(SIGTERM, &action, nullptr);

    photon::RenderResult result = photon::render(built.scene, built.camera, settings);
    // A file with assumed_gamma G rendered numbers of a gamma-G space; the image is linear.
    photon::decode_working_gamma(result.film, built.working_gamma);
    const bool partial = result.stats.partial || cancel_requested.load();
    if (partial) progress.finish();

    photon::ImageWriteOptions wo;
    wo.exposure = ro.exposure;
    wo.metadata = {
        {"photon:partial", partial ? "true" : "false"},
        {"photon:scene", so.scene},
        {"photon:mode", photon::to_string(settings.mode)},
        {"photon:settings", settings_line(settings)},
        {"photon:version", std::to_string(photon::version_major) + "." + std::to_string(photon::version_minor) + "." +
                               std::to_string(photon::version_patch)}};
    fs::path written = output;
    std::error_code ec;
    if (partial && fs::exists(output, ec)) {
        // Never replace a finished image by an unfinished one.
        written.replace_filename(output.stem().string() + ".partial" + output.extension().string());
    }
    photon::image_module::write_image(written, result.film, wo);
    if (!ro.error_image.empty()) {
        fs::path error_written = ro.error_image;
        if (partial && fs::exists(error_written, ec))
            error_written.replace_filename(error_written.stem().string() + ".partial" + error_written.extension().string());
        if (result.error_image.pixels().empty())
            std::cerr << "photon: warning: no error image: the render had no two independent halves (one pass, or one "
                         "sample per pixel in one round)\n";
        else
            photon::image_module::write_image(error_written, result.error_image, wo);
    }
    if (!so.quiet || partial) {
        std::cerr << "photon: wrote " << written.string()
                  << (partial ? " (PARTIAL: interrupted, marked photon:partial=true)" : "") << '\n';
    }
    // A warning about one object was already reported at its place in the file when the scene was built.
    if (!so.quiet || so.strict)
        for (const photon::RenderWarning& w : result.stats.warnings)
            if (!w.object) std::cerr << "photon: warning: " << w.message << '\n';
    if (!ro.no_stats && !so.quiet) std::cout << photon::format_stats(result.stats);
    return partial ? exit_interrupted : EXIT_SUCCESS;
}

/// The summary of what photon read but skipped or approximated, by kind and keyword.
void print_degraded(const std::map<std::string, std::map<std::string, std::size_t>>& degraded) {
    if (degraded.empty()) return;
    std::cout << "degraded   what photon read but does not render as written:\n";
    for (const auto& [kind, keywords] : degraded) {
        std::size_t total = 0;
        for (const auto& [keyword, n] : keywords) total += n;
        std::cout << "           " << total << ' ' << kind;
        const char* sep = ": ";
        for (const auto& [keyword, n] : keywords)
            if (!keyword.empty()) std::cout << sep << n << ' ' << keyword, sep = ", ";
        std::cout << '\n';
    }
}

/// `photon check` builds the scene as `render` does, so the build step's errors (a mesh file
/// missing or broken, at its name in the scene) are reported by check too.
int run_check(SceneOptions& so) {
    const dsl::SceneDescription desc = dsl::parse_file(so.scene, so.parse_options(800, 600));
    dsl::BuildOptions bo;
    bo.diagnostics = so.sink();
    const dsl::BuiltScene<float> built = dsl::build<float>(desc, bo);
    report(so.scene, desc, built);
    std::cout << "warnings   " << so.warnings << '\n';
    print_degraded(so.degraded);
    return so.failed_strict() ? exit_error : EXIT_SUCCESS;
}

int run_export(SceneOptions& so, const std::string& output) {
    const dsl::SceneDescription desc = dsl::parse_file(so.scene, so.parse_options(800, 600));
    const std::string text = dsl::export_pov(desc, so.sink());
    if (output.empty() || output == "-") {
        std::cout << text;
    } else {
        const fs::path path(output);
        fs::path tmp = path;
        tmp.replace_filename("." + path.filename().string() + ".tmp-" + std::to_string(::getpid()));
        {
            std::ofstream out(tmp, std::ios::binary);
            out << text;
            out.close();
            if (!out) {
                std::error_code ec;
                fs::remove(tmp, ec);
                throw std::runtime_error("cannot write " + output);
            }
        }
        std::error_code ec;
        fs::rename(tmp, path, ec);
        if (ec) {
            fs::remove(tmp, ec);
            throw std::runtime_error("cannot write " + output + ": " + ec.message());
        }
        if (!so.quiet) std::cerr << "photon: wrote " << output << '\n';
    }
    return so.failed_strict() ? exit_error : EXIT_SUCCESS;
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

    SceneOptions so;
    RenderOptions ro;
    std::string export_output;

    CLI::App* render = app.add_subcommand("render", "Render a scene file to an image");
    so.add_to(*render);
    render
        ->add_option("-o,--output", ro.output,
                     "Image to write: .png, .exr, .jpg, .tif, .hdr (anything OpenImageIO writes). "
                     "Floating-point formats hold radiance, 8-bit ones sRGB")
        ->required();
    ro.settings.add_to(*render);
    render->add_option("--exposure", ro.exposure, "Multiplies radiance before 8-bit output (PNG, JPEG)")
        ->check(CLI::PositiveNumber);
    render->add_flag("--no-stats", ro.no_stats, "Do not print the statistics table");
    render->add_option("--error-image", ro.error_image,
                       "sppm and reference: also write each pixel's estimated error |A - B| / 2 of the two "
                       "independent half-images (an .exr keeps it linear)");
    render->add_flag("--no-mis", ro.no_mis,
                     "reference: direct light by shadow rays alone, without multiple importance sampling "
                     "(to measure what it gains)");

    CLI::App* check = app.add_subcommand("check", "Read and build a scene, report what it holds and any warnings");
    so.add_to(*check);

    CLI::App* export_pov = app.add_subcommand(
        "export-pov",
        "Write the scene as one self-contained POV-Ray 3.7 file (declarations, includes and expressions "
        "evaluated; photon's own settings inside #ifdef (photon_version))");
    so.add_to(*export_pov);
    export_pov->add_option("-o,--output", export_output, "File to write (default: standard output)");

    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
        const int code = app.exit(e);
        return code == 0 ? EXIT_SUCCESS : exit_usage;
    }

    try {
        if (render->parsed()) return run_render(so, ro);
        if (check->parsed()) return run_check(so);
        return run_export(so, export_output);
    } catch (const dsl::Error& e) {
        std::cerr << e.what() << '\n';
    } catch (const std::exception& e) {
        std::cerr << "photon: error: " << e.what() << '\n';
    }
    return exit_error;
}
