// SPDX-License-Identifier: MIT
// photon-classes: renders the scene-class gallery (examples/scenes/classes) with pm, pm-direct,
// rt (direct-light-only classes) and the judge, at any size, and measures each mode's worst block
// bias against the judge exactly as the gallery test does (tools/scene_class_judge.hpp), with the
// judge's noise from its two runs. scripts/scene-classes.sh makes docs/scene-classes.md from it.
//
//   photon-classes CLASSES_DIR OUT_DIR [--size WxH] [--judge sppm|reference] [--effort F]
//                  [--photons-per-pass N] [--supersampling N] [--samples-per-pixel N] [--classes a,b,...]
//
// Writes OUT_DIR/NAME-pm.exr and OUT_DIR/NAME-judge.exr (the mean of the judge's two runs),
// OUT_DIR/NAME-judge-blocks.tsv (the judge's block means, channel mean, row by row, and whether
// each holds more than 1% of its light: to compare two judges), and one tab-separated line per
// class to standard output: name, judge, noise rms, noise max, judge seconds (both runs), then
// mode, worst bias, worst block, seconds for pm, pm-direct and rt.

#include <CLI/CLI.hpp>

#include "load_image_io.hpp"

#include "scene_class_judge.hpp"

#include <cstdlib>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>

int main(int argc, char** argv) {
    using namespace classes;
    CLI::App app{"photon-classes: the scene-class gallery rendered and judged", "photon-classes"};
    std::string classes_dir, out_dir, size = "320x240", judge_name = "sppm", only;
    double effort = 1.0;
    std::size_t photons_per_pass = JudgeEffort{}.sppm_photons_per_pass;
    unsigned supersampling = 1, samples_per_pixel = 4;
    bool no_cache = false;
    app.add_option("classes", classes_dir, "examples/scenes/classes")->required()->check(CLI::ExistingDirectory);
    app.add_option("out", out_dir, "Directory for the EXR images")->required();
    app.add_option("--size", size, "Image size WxH (default 320x240)");
    app.add_option("--judge", judge_name, "sppm (default) or reference")->check(CLI::IsMember({"sppm", "reference"}));
    app.add_option("--effort", effort, "Judge effort: times the class's passes or samples (made for 48x36)")
        ->check(CLI::PositiveNumber);
    app.add_option("--photons-per-pass", photons_per_pass, "sppm photons per pass")->check(CLI::PositiveNumber);
    app.add_option("--supersampling", supersampling,
                   "The judge renders N times the width and height (the test uses 4 for sppm at 48x36)")
        ->check(CLI::PositiveNumber);
    app.add_option("--samples-per-pixel", samples_per_pixel, "Of pm, pm-direct and rt (default 4, the files')")
        ->check(CLI::PositiveNumber);
    app.add_flag("--no-cache", no_cache, "pm gathers at every sample instead of the irradiance cache (as the test)");
    app.add_option("--classes", only, "Comma-separated class names (default all)");
    CLI11_PARSE(app, argc, argv);

    try {
        Measurement m;
        m.classes_dir = classes_dir;
        if (std::sscanf(size.c_str(), "%ux%u", &m.width, &m.height) != 2 || m.width < m.columns || m.height < m.rows)
            throw std::invalid_argument("--size must be WxH, at least 4x4, found " + size);
        // The files' own settings by default: at 320 x 240 a block holds 4,800 pixels and a cache
        // record a few of them.
        m.samples_per_pixel = samples_per_pixel;
        if (!no_cache) m.irradiance_cache_error.reset();
        Judge judge = judge_name == "reference" ? path_tracer_judge : sppm_judge;
        judge.supersampling = supersampling;  // at picture sizes sppm's radii are small already
        const JudgeEffort judge_effort{effort, photons_per_pass};
        std::filesystem::create_directories(out_dir);
        for (const SceneClass& c : gallery) {
            if (!only.empty() && ("," + only + ",").find("," + std::string(c.name) + ",") == std::string::npos) continue;
            if (c.point_light_caustics && !judge.sees_point_light_caustics) {
                std::cerr << "photon-classes: " << c.name << ": skipped, the judge cannot see point-light caustics\n";
                continue;
            }
            std::cerr << "photon-classes: " << c.name << "\n";
            const Judgement j = judge_class(c, judge, m, judge_effort);
            std::vector<std::pair<std::string, Render>> renders;
            renders.emplace_back("pm", render_class(c.name, RenderMode::pm, m));
            renders.emplace_back("pm-direct", render_class(c.name, RenderMode::pm_direct, m));
            if (c.direct_only) renders.emplace_back("rt", render_class(c.name, RenderMode::rt, m));
            photon::image_module::write_image(out_dir + "/" + c.name + "-judge.exr", j.film);
            photon::image_module::write_image(out_dir + "/" + c.name + "-pm.exr", renders[0].second.film);
            std::ofstream blocks(out_dir + "/" + c.name + "-judge-blocks.tsv");
            for (std::size_t b = 0; b < j.blocks.size(); ++b)
                blocks << regions::channel_mean(j.blocks[b]) << '\t' << int(j.lit[b]) << '\n';
            std::ostringstream line;
            line << c.name << '\t' << to_string(judge.mode) << '\t' << j.noise.rms << '\t' << j.noise.max << '\t'
                 << j.seconds;
            for (const auto& [mode, r] : renders) {
                const auto worst = regions::worst_bias(r.blocks, j.blocks, j.lit);
                line << '\t' << mode << '\t' << worst.bias << '\t' << worst.region % int(m.columns) << ','
                     << worst.region / int(m.columns) << '\t' << r.seconds;
            }
            std::cout << line.str() << std::endl;
        }
        return EXIT_SUCCESS;
    } catch (const photon::dsl::Error& e) {
        std::cerr << e.what() << '\n';
    } catch (const std::exception& e) {
        std::cerr << "photon-classes: error: " << e.what() << '\n';
    }
    return EXIT_FAILURE;
}
