// SPDX-License-Identifier: MIT
#pragma once
// Helpers shared by the hard-case tests: tiny render settings, per-region means, and the check
// every render in this suite must pass (no NaN, Inf or negative pixel).

#include <catch2/catch.hpp>

#include <photon/photon.hpp>

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <string>
#include <vector>

namespace hard {

using namespace photon;

/// 32x24, one sample per pixel, few photons and gather rays: fast, still every code path.
inline RenderSettings tiny(RenderMode mode) {
    RenderSettings s;
    s.mode = mode;
    s.width = 32;
    s.height = 24;
    s.samples_per_pixel = 1;
    s.shadow_samples = 4;
    s.global_photons = 20'000;
    s.caustic_photons = 20'000;
    s.final_gather_rays = 16;
    s.threads = 2;
    return s;
}

/// Index and value of the first pixel that is NaN, Inf or negative, as a message ("" if none).
inline std::string first_invalid_pixel(const Film& film) {
    for (unsigned y = 0; y < film.height(); ++y)
        for (unsigned x = 0; x < film.width(); ++x) {
            const Rgb<float>& p = film.at(x, y);
            if (!is_finite(p) || min_component(p) < 0.0f)
                return "pixel (" + std::to_string(x) + ", " + std::to_string(y) + ") = <" + std::to_string(p.x) +
                       ", " + std::to_string(p.y) + ", " + std::to_string(p.z) + ">";
        }
    return "";
}

/// Every render of the suite goes through this: the image holds no NaN, Inf or negative pixel.
#define HARD_REQUIRE_VALID(film) REQUIRE(::hard::first_invalid_pixel(film) == "")

/// Writes `film` to $PHOTON_HARD_CASE_IMAGES/<name>.pfm when that variable names a folder, so
/// that the renders of this suite can be looked at (oiiotool reads PFM); does nothing otherwise.
/// PFM, written here in a few lines, keeps OpenImageIO's start-up cost (about a second) out of
/// every test process.
inline void dump(const Film& film, const std::string& name) {
    const char* dir = std::getenv("PHOTON_HARD_CASE_IMAGES");
    if (!dir) return;
    std::ofstream out(std::string(dir) + "/" + name + ".pfm", std::ios::binary);
    out << "PF\n" << film.width() << ' ' << film.height() << "\n-1\n";  // -1: little-endian floats
    for (unsigned y = film.height(); y-- > 0;)  // PFM stores the bottom row first
        for (unsigned x = 0; x < film.width(); ++x) {
            const Rgb<float>& p = film.at(x, y);
            const float rgb[3] = {p.x, p.y, p.z};
            out.write(reinterpret_cast<const char*>(rgb), sizeof rgb);
        }
}

/// Mean radiance (mean of the three channels) of each cell of a cols x rows grid over the image,
/// row-major.
inline std::vector<double> region_means(const Film& film, unsigned cols, unsigned rows) {
    std::vector<double> sum(std::size_t(cols) * rows, 0.0);
    std::vector<std::size_t> count(sum.size(), 0);
    for (unsigned y = 0; y < film.height(); ++y)
        for (unsigned x = 0; x < film.width(); ++x) {
            const std::size_t cell = std::size_t(y * rows / film.height()) * cols + x * cols / film.width();
            const Rgb<float>& p = film.at(x, y);
            sum[cell] += (double(p.x) + double(p.y) + double(p.z)) / 3.0;
            ++count[cell];
        }
    for (std::size_t i = 0; i < sum.size(); ++i) sum[i] /= double(count[i]);
    return sum;
}

/// Largest relative difference between two images' pixels, with `floor` added to both values
/// (so black-on-black compares as equal and tiny values do not dominate).
inline double max_relative_difference(const Film& a, const Film& b, double floor) {
    double worst = 0;
    for (std::size_t i = 0; i < a.pixels().size(); ++i)
        for (int c = 0; c < 3; ++c) {
            const double x = a.pixels()[i][c], y = b.pixels()[i][c];
            worst = std::max(worst, std::abs(x - y) / (std::max(x, y) + floor));
        }
    return worst;
}

template <class S> using SceneOf = DefaultScene<S>;

}  // namespace hard
