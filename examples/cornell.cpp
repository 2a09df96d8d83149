// SPDX-License-Identifier: MIT
// Renders the paper's Cornell box with ray tracing (rt) and photon mapping (pm), built in C++
// without a scene file, and writes both images with their statistics.
//
//   cornell [--width W] [--height H] [--threads T] [--out DIR]

#include <cstdio>
#include <cstdlib>
#include <exception>
#include <string>

#include "cornell_box.hpp"

#include <photon/film/image_io.hpp>

int main(int argc, char** argv) try {
    photon::RenderSettings settings;  // the library's defaults: 800 x 600, ray depth 4, photon depth 100
    std::string out_dir = ".";
    for (int i = 1; i + 1 < argc; i += 2) {
        const std::string key = argv[i], value = argv[i + 1];
        if (key == "--width") settings.width = unsigned(std::stoul(value));
        else if (key == "--height") settings.height = unsigned(std::stoul(value));
        else if (key == "--threads") settings.threads = unsigned(std::stoul(value));
        else if (key == "--out") out_dir = value;
        else throw std::invalid_argument("unknown option " + key);
    }
    const auto box = cornell::make_cornell_box<float>(float(settings.width) / float(settings.height));
    for (const auto mode : {photon::RenderMode::rt, photon::RenderMode::pm}) {
        settings.mode = mode;
        const auto result = photon::render(box.scene, box.camera, settings);
        const std::string base = out_dir + "/cornell-" + photon::to_string(mode);
        photon::write_image(base + ".png", result.film);
        photon::write_image(base + ".exr", result.film);
        std::printf("%s.png\n%s", base.c_str(), photon::format_stats(result.stats).c_str());
    }
    return EXIT_SUCCESS;
} catch (const std::exception& e) {
    std::fprintf(stderr, "cornell: %s\n", e.what());
    return EXIT_FAILURE;
}
