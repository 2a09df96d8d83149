// SPDX-License-Identifier: MIT
// `photon render`: reads, builds and renders a scene and writes the image, with a progress bar,
// and on Ctrl-C the image so far (marked partial).

#include "commands.hpp"
#include "load_image_io.hpp"
#include "scene_report.hpp"
#include "work_share_cli.hpp"

#include <photon/dsl/parser.hpp>

#include <atomic>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <mutex>
#include <stdexcept>
#include <string>
#include <unistd.h>

namespace photon::cli {

namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

std::atomic<bool> cancel_requested{false};

extern "C" void on_interrupt(int) {
    if (cancel_requested.load()) _exit(exit_interrupted);
    cancel_requested.store(true);
    static const char message[] =
        "\nphoton: interrupted: stopping, the image so far will be written "
        "(press Ctrl-C again to quit at once)\n";
    [[maybe_unused]] const auto n = ::write(STDERR_FILENO, message, sizeof message - 1);
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

}  // namespace

/// The render, alone or as one of the ranks of `share`.
static int render_as(SceneOptions& so, const RenderOptions& ro, photon::WorkShare* share) {
    const bool writer = !share || share->rank() == 0;
    if (!writer) so.quiet = true;
    const fs::path output(ro.output);
    photon::image_module::check_writable_image_path(output);
    dsl::BuildOptions bo;
    bo.diagnostics = so.sink();
    bo.read_image = [](const std::filesystem::path& f, ImageGamma g) { return photon::image_module::read_pixel_grid(f, g); };
    bo.overrides = ro.overrides;
    const dsl::SceneDescription desc = dsl::parse_file(so.scene, so.parse_options(ro.overrides));
    dsl::BuiltScene<float> built = dsl::build<float>(desc, bo);
    if (so.failed_strict()) return exit_error;
    photon::RenderSettings& settings = built.settings;
    if (ro.no_mis) settings.reference_mis = false;
    const bool budget = settings.time_limit > 0 || settings.target_error > 0;
    const bool pm = settings.mode == photon::RenderMode::pm;
    const bool estimates = settings.mode == photon::RenderMode::sppm || settings.mode == photon::RenderMode::reference || pm;
    if (budget && !estimates)
        std::cerr << "photon: warning: --time and --target-error apply to the pm, sppm and reference modes; mode "
                  << photon::to_string(settings.mode) << " renders once, as its settings ask\n";
    if (pm && settings.target_error > 0 && settings.pm_error_passes == 0)
        throw std::runtime_error("--target-error: pm measures its error only with its estimate (not with --no-error-estimate "
                                 "or pm_error_passes 0)");
    if (!ro.error_image.empty() && !estimates)
        throw std::runtime_error("--error-image: only the pm, sppm and reference modes estimate their error (mode " +
                                 std::string(photon::to_string(settings.mode)) + ")");
    if (!ro.error_image.empty() && pm && settings.pm_error_passes == 0)
        throw std::runtime_error("--error-image: pm estimates its error only without --no-error-estimate");
    if (!ro.error_image.empty()) photon::image_module::check_writable_image_path(ro.error_image);
    if (!ro.error_image.empty() && pm) settings.pm_error_stride = 1;  // an error image shows every pixel's error
    if (!so.quiet) {
        std::cerr << "photon: " << so.scene << ": " << built.scene.objects().size() << " objects, "
                  << built.scene.lights().size() << " light" << (built.scene.lights().size() == 1 ? "" : "s") << ", "
                  << built.scene.materials().size() << " materials\n"
                  << "photon: " << settings_line(settings) << '\n';
        for (const std::string& line : plan_of(built, settings))
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
                            capped = settings.sppm_passes < photon::SettingsLimits::max_sppm_passes](
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
    photon::ImageWriteOptions wo;
    wo.exposure = ro.exposure;
    wo.metadata = {
        {"photon:partial", "false"},
        {"photon:scene", so.scene},
        {"photon:mode", photon::to_string(settings.mode)},
        {"photon:settings", settings_line(settings)},
        {"photon:version", std::to_string(photon::version_major) + "." + std::to_string(photon::version_minor) + "." +
                               std::to_string(photon::version_patch)}};
    if (pm && (budget || settings.pm_error_passes > 0)) {
        // One line per render (several under a budget), with its estimated error; under a budget
        // each finished render is written at once, so the image on disk is the best so far.
        settings.on_pass = [&, quiet = so.quiet](const photon::PassReport& r) {
            if (!quiet) {
                progress.finish();
                char error[96] = "";
                if (r.error.available)
                    std::snprintf(error, sizeof error, ", estimated error %s%.3g%% (worst block %.3g%%)",
                                  r.error.at_floor ? "below " : "", 100 * r.error.relative_rmse, 100 * r.error.worst_block);
                std::fprintf(stderr, "photon: pm render %u (%.1f s)%s\n", r.pass, r.seconds, error);
            }
            if (budget && writer && r.image) {  // rank 0 alone writes
                photon::Film film = *r.image;
                photon::decode_working_space(film, built.working_space);
                photon::image_module::write_image(output, film, wo);
            }
        };
    }
    if (share) {
        // Ranks must agree on every phase they run: no cancelling one of them (mpirun stops all).
        settings.share = share;
    } else {
        settings.cancel = &cancel_requested;
        struct sigaction action {};
        action.sa_handler = on_interrupt;
        sigemptyset(&action.sa_mask);
        sigaction(SIGINT, &action, nullptr);
        sigaction(SIGTERM, &action, nullptr);
    }

    photon::RenderResult result = photon::render(built.scene, built.camera, settings);
    const std::string exchanges = share ? exchange_stats(*share) : std::string();
    if (!writer) return EXIT_SUCCESS;
    // The film holds numbers of the scene's working space (POV-Ray's gamma rules); the image is linear.
    photon::decode_working_space(result.film, built.working_space);
    const bool partial = result.stats.partial || cancel_requested.load();
    if (partial) progress.finish();

    wo.metadata[0].second = partial ? "true" : "false";
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
                         "sample per pixel in one round, or pm cancelled before its judge had two passes)\n";
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
    if (!ro.no_stats && !so.quiet) std::cout << photon::format_stats(result.stats) << exchanges;
    return partial ? exit_interrupted : EXIT_SUCCESS;
}

int run_render(SceneOptions& so, const RenderOptions& ro) {
    // Under mpirun every rank renders its share; rank 0 alone reports and writes the image.
    const std::unique_ptr<photon::WorkShare> share = open_work_share();
    if (!share) return render_as(so, ro, nullptr);
    try {
        return render_as(so, ro, share.get());
    } catch (const std::exception& e) {
        abort_ranks(*share, e.what());  // the other ranks may wait in an exchange: stop them all
    }
}

}  // namespace photon::cli
