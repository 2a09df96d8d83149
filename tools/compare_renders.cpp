// SPDX-License-Identifier: MIT
// photon-compare: numbers and pictures for two renders of the same scene file (photon against
// POV-Ray in scripts/compare-povray.sh).
//
//   photon-compare SCENE.pov A.exr B.exr [--region NAME=X0,Y0,Z0,X1,Y1,Z1,AXIS]... [--side-by-side OUT.jpg]
//                  [--mask OUT.png] [--summary OUT.tsv] [--exposure E] [--labels A,B] [--block N]
//                  [--relative-mse OUT.txt]
//
// Both images must hold linear radiance of the same size. Regions are pieces of surface named in
// scene coordinates (an axis-aligned box and the direction the surface faces, e.g. the Cornell
// floor is `floor=-1.2,-0.001,-1.2,1.2,0.001,1.2,+y`). A pixel belongs to a region when the
// camera rays through its centre and four inner points all hit that surface directly (photon's
// own intersection code on the scene file, so no pixel rectangle needs maintaining by hand), and
// so do its four neighbours: edges, anti-aliased silhouettes and whatever a mirror shows are left
// out. Prints a Markdown table of mean radiance per region to standard output.
//
// --block N also measures the RMSE of the N x N block means (whole blocks only): per-pixel noise
// averages away in a block, low-frequency bias and blotches do not. The summary line then gains
// three fields: block RMSE, the largest |A / B - 1| of the regions' channel means, and that region.
//
// --relative-mse writes the relative MSE of A against B as the judge: the sum over pixels and
// channels of (A - B)^2 over the sum of B^2 (docs/accuracy.md's "normalised MSE"; the accuracy
// studies against POV-Ray use it), one number in its own file so that the summary line keeps its
// fields.

#include <CLI/CLI.hpp>

#include <photon/dsl/dsl.hpp>
#include "load_image_io.hpp"

#include "region_statistics.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

namespace {

namespace dsl = photon::dsl;
using photon::Film;
using photon::Rgb;
using Vec3 = photon::Vec3<float>;

/// A piece of surface: hit points inside `box` whose geometric normal points along `facing`.
struct Region {
    std::string name;
    Vec3 lo, hi;
    Vec3 facing;

    [[nodiscard]] bool contains(const photon::Hit<float>& hit) const {
        constexpr float slack = 1e-3f;  // hit points sit within float error of the plane
        for (int a = 0; a < 3; ++a)
            if (hit.point[a] < lo[a] - slack || hit.point[a] > hi[a] + slack) return false;
        return glm::dot(hit.normal, facing) > 0.99f;
    }
};

/// Parses NAME=X0,Y0,Z0,X1,Y1,Z1,AXIS with AXIS one of +x -x +y -y +z -z.
Region parse_region(const std::string& spec) {
    auto fail = [&](const std::string& why) {
        throw std::invalid_argument("--region " + spec + ": " + why +
                                    " (expected NAME=X0,Y0,Z0,X1,Y1,Z1,AXIS with AXIS one of +x -x +y -y +z -z)");
    };
    const auto eq = spec.find('=');
    if (eq == std::string::npos || eq == 0) fail("no name");
    Region r;
    r.name = spec.substr(0, eq);
    std::vector<std::string> fields;
    std::stringstream rest(spec.substr(eq + 1));
    for (std::string f; std::getline(rest, f, ',');) fields.push_back(f);
    if (fields.size() != 7) fail("needs 7 comma-separated fields after the name");
    float c[6];
    for (int i = 0; i < 6; ++i) {
        try {
            std::size_t used = 0;
            c[i] = std::stof(fields[std::size_t(i)], &used);
            if (used != fields[std::size_t(i)].size()) fail("'" + fields[std::size_t(i)] + "' is not a number");
        } catch (const std::logic_error&) {
            fail("'" + fields[std::size_t(i)] + "' is not a number");
        }
    }
    r.lo = Vec3(std::min(c[0], c[3]), std::min(c[1], c[4]), std::min(c[2], c[5]));
    r.hi = Vec3(std::max(c[0], c[3]), std::max(c[1], c[4]), std::max(c[2], c[5]));
    const std::string& axis = fields[6];
    if (axis.size() != 2 || (axis[0] != '+' && axis[0] != '-') || axis[1] < 'x' || axis[1] > 'z')
        fail("'" + axis + "' is not an axis");
    r.facing = Vec3(0.0f);
    r.facing[axis[1] - 'x'] = axis[0] == '+' ? 1.0f : -1.0f;
    return r;
}

/// Region index of every pixel, -1 for none (see the file comment).
std::vector<int> label_pixels(const dsl::BuiltScene<float>& built, const std::vector<Region>& regions, unsigned width,
                              unsigned height) {
    const auto& scene = built.scene;
    auto region_of = [&](float u, float v) {
        const auto ray = built.camera.ray(u, v);
        if (!ray) return -1;
        const auto hit = scene.intersect(*ray);
        if (!hit) return -1;
        for (std::size_t r = 0; r < regions.size(); ++r)
            if (regions[r].contains(hit->hit)) return int(r);
        return -1;
    };
    constexpr float inner[4][2] = {{0.15f, 0.15f}, {0.85f, 0.15f}, {0.15f, 0.85f}, {0.85f, 0.85f}};
    std::vector<int> label(std::size_t(width) * height, -1);
    for (unsigned y = 0; y < height; ++y)
        for (unsigned x = 0; x < width; ++x) {
            auto at = [&](float dx, float dy) { return region_of((float(x) + dx) / float(width), (float(y) + dy) / float(height)); };
            int l = at(0.5f, 0.5f);
            for (const auto& p : inner)
                if (l >= 0 && at(p[0], p[1]) != l) l = -1;
            label[std::size_t(y) * width + x] = l;
        }
    // Erode by one pixel: a region pixel must have region neighbours on all four sides.
    std::vector<int> eroded(label.size(), -1);
    for (unsigned y = 1; y + 1 < height; ++y)
        for (unsigned x = 1; x + 1 < width; ++x) {
            const std::size_t i = std::size_t(y) * width + x;
            const int l = label[i];
            if (l >= 0 && label[i - 1] == l && label[i + 1] == l && label[i - width] == l && label[i + width] == l)
                eroded[i] = l;
        }
    return eroded;
}

using photon::regions::channel_mean;

struct Accumulator {
    Rgb<double> a{0.0}, b{0.0};
    std::size_t pixels = 0;
};

std::string fixed(double v, int digits) {
    std::ostringstream s;
    s << std::fixed << std::setprecision(digits) << v;
    return s.str();
}

std::string rgb_text(const Rgb<double>& c) {
    return "(" + fixed(c.x, 3) + ", " + fixed(c.y, 3) + ", " + fixed(c.z, 3) + ")";
}

/// The ratio a / b of the channel means as text, with the verdict against the 10% target.
std::string ratio_text(const Rgb<double>& a, const Rgb<double>& b) {
    const double mb = channel_mean(b);
    if (!(mb > 0.0)) return "-";
    const double r = channel_mean(a) / mb;
    return fixed(r, 3) + (std::abs(r - 1.0) <= 0.1 ? "" : " **");
}

/// Signed difference picture: red where A is brighter, blue where B is; full colour at +-50% of
/// B's radiance (floored at a tenth of B's mean, so that black areas do not blow up).
Film difference_picture(const Film& a, const Film& b, double floor) {
    Film d(a.width(), a.height());
    for (std::size_t i = 0; i < d.pixels().size(); ++i) {
        const double la = channel_mean(Rgb<double>(a.pixels()[i])), lb = channel_mean(Rgb<double>(b.pixels()[i]));
        const float t = float(std::clamp((la - lb) / std::max(lb, floor) / 0.5, -1.0, 1.0));
        d.pixels()[i] = t >= 0 ? Rgb<float>(t, 0.15f * t, 0.0f) : Rgb<float>(0.0f, 0.4f * -t, -t);
    }
    return d;
}

/// A, B and their difference next to each other with `gap` black pixels between them.
Film side_by_side(const std::vector<const Film*>& films, unsigned gap) {
    const unsigned w = films[0]->width(), h = films[0]->height();
    const auto n = unsigned(films.size());
    Film out(n * w + (n - 1) * gap, h);
    for (unsigned k = 0; k < n; ++k)
        for (unsigned y = 0; y < h; ++y)
            for (unsigned x = 0; x < w; ++x) out.at(k * (w + gap) + x, y) = films[k]->at(x, y);
    return out;
}

}  // namespace

int main(int argc, char** argv) {
    CLI::App app{"photon-compare: mean radiance per surface, RMSE and PSNR of two linear renders of one scene",
                 "photon-compare"};
    std::string scene_file, a_file, b_file, side_file, mask_file, summary_file, relative_file,
        labels = "photon,POV-Ray";
    std::vector<std::string> region_specs;
    float exposure = 1.0f;
    unsigned block = 0;
    app.add_option("scene", scene_file, "The scene file both images render")->required()->check(CLI::ExistingFile);
    app.add_option("a", a_file, "First image (linear radiance, e.g. EXR)")->required()->check(CLI::ExistingFile);
    app.add_option("b", b_file, "Second image, the one ratios divide by")->required()->check(CLI::ExistingFile);
    app.add_option("--region", region_specs, "NAME=X0,Y0,Z0,X1,Y1,Z1,AXIS: a surface to average over (repeatable)")
        ->allow_extra_args(false)
        ->multi_option_policy(CLI::MultiOptionPolicy::TakeAll);
    app.add_option("--side-by-side", side_file, "Write A | B | difference (8-bit, e.g. .jpg)");
    app.add_option("--mask", mask_file, "Write the region of every pixel as colours, for checking the regions");
    app.add_option("--summary", summary_file, "Write rmse, psnr, mean A, mean B as one tab-separated line");
    app.add_option("--relative-mse", relative_file, "Write sum (A - B)^2 / sum B^2 over pixels and channels");
    app.add_option("--exposure", exposure, "Exposure of the side-by-side picture")->check(CLI::PositiveNumber);
    app.add_option("--labels", labels, "Names of A and B in the table (comma-separated)");
    app.add_option("--block", block, "Also the RMSE of N x N block means; adds it and the worst region bias to --summary")
        ->check(CLI::PositiveNumber);
    CLI11_PARSE(app, argc, argv);

    try {
        std::vector<Region> regions;
        for (const auto& spec : region_specs) regions.push_back(parse_region(spec));
        const auto comma = labels.find(',');
        const std::string name_a = labels.substr(0, comma),
                          name_b = comma == std::string::npos ? "B" : labels.substr(comma + 1);

        const Film a = photon::image_module::read_image(a_file), b = photon::image_module::read_image(b_file);
        if (a.width() != b.width() || a.height() != b.height())
            throw std::invalid_argument(a_file + " is " + std::to_string(a.width()) + "x" + std::to_string(a.height()) +
                                        " but " + b_file + " is " + std::to_string(b.width()) + "x" +
                                        std::to_string(b.height()));
        if (block > std::min(a.width(), a.height()))
            throw std::invalid_argument("--block " + std::to_string(block) + " is larger than the " +
                                        std::to_string(a.width()) + "x" + std::to_string(a.height()) + " images");
        if (!a.all_finite_nonnegative() || !b.all_finite_nonnegative())
            throw std::invalid_argument("an image holds NaN, infinite or negative values");

        dsl::ParseOptions po;
        po.image_width = a.width(), po.image_height = a.height();
        po.include_paths = dsl::standard_include_paths();  // as `photon render`: POV-Ray's includes and fonts
        po.diagnostics = [](const dsl::Diagnostic&) {};  // the renders already reported them
        dsl::BuildOptions bo;  // scenes with image maps and height fields read them as `photon render` does
        bo.read_image = [](const std::filesystem::path& f, photon::ImageGamma g) { return photon::image_module::read_pixel_grid(f, g); };
        const auto built = dsl::load_scene<float>(scene_file, po, bo);
        const std::vector<int> label = label_pixels(built, regions, a.width(), a.height());

        // Whole image: RMSE over all pixels and channels; PSNR against a peak of 1 W m^-2 sr^-1, the
        // radiance an 8-bit picture at exposure 1 shows as white.
        double squared = 0.0, squared_b = 0.0;
        Accumulator whole;
        std::vector<Accumulator> per_region(regions.size());
        for (std::size_t i = 0; i < a.pixels().size(); ++i) {
            const Rgb<double> pa(a.pixels()[i]), pb(b.pixels()[i]);
            const Rgb<double> d = pa - pb;
            squared += glm::dot(d, d);
            squared_b += glm::dot(pb, pb);
            whole.a += pa, whole.b += pb, ++whole.pixels;
            if (label[i] >= 0) {
                auto& r = per_region[std::size_t(label[i])];
                r.a += pa, r.b += pb, ++r.pixels;
            }
        }
        const double mse = squared / (3.0 * double(a.pixels().size()));
        const double rmse = std::sqrt(mse), psnr = 10.0 * std::log10(1.0 / mse);
        const Rgb<double> mean_a = whole.a / double(whole.pixels), mean_b = whole.b / double(whole.pixels);

        std::cout << "| surface | pixels | " << name_a << " (r, g, b) | " << name_b << " (r, g, b) | " << name_a
                  << " / " << name_b << " |\n|---|---:|---|---|---:|\n";
        std::cout << "| whole image | " << whole.pixels << " | " << rgb_text(mean_a) << " | " << rgb_text(mean_b)
                  << " | " << ratio_text(mean_a, mean_b) << " |\n";
        for (std::size_t r = 0; r < regions.size(); ++r) {
            const auto& acc = per_region[r];
            if (acc.pixels == 0) {
                std::cout << "| " << regions[r].name << " | 0 | - | - | - |\n";
                continue;
            }
            const auto ma = acc.a / double(acc.pixels), mb = acc.b / double(acc.pixels);
            std::cout << "| " << regions[r].name << " | " << acc.pixels << " | " << rgb_text(ma) << " | "
                      << rgb_text(mb) << " | " << ratio_text(ma, mb) << " |\n";
        }

        // The region whose mean is furthest from B's, as A / B - 1 of the channel means.
        std::vector<Rgb<double>> region_a, region_b;
        std::vector<bool> seen;
        for (const auto& acc : per_region) {
            region_a.push_back(acc.pixels ? acc.a / double(acc.pixels) : Rgb<double>(0.0));
            region_b.push_back(acc.pixels ? acc.b / double(acc.pixels) : Rgb<double>(0.0));
            seen.push_back(acc.pixels > 0);
        }
        const auto worst = photon::regions::worst_bias(region_a, region_b, seen);
        const double worst_bias = worst.bias;
        const std::string worst_region = worst.region < 0 ? "-" : regions[std::size_t(worst.region)].name;
        const double rmse_blocks = block > 0 ? photon::regions::block_rmse(a, b, block) : 0.0;

        if (!summary_file.empty()) {
            std::ofstream out(summary_file);
            out << fixed(rmse, 4) << '\t' << fixed(psnr, 2) << '\t' << fixed(channel_mean(mean_a), 4) << '\t'
                << fixed(channel_mean(mean_b), 4);
            if (block > 0) out << '\t' << fixed(rmse_blocks, 4) << '\t' << fixed(worst_bias, 4) << '\t' << worst_region;
            out << '\n';
            if (!out) throw std::runtime_error("cannot write " + summary_file);
        }
        if (!relative_file.empty()) {
            std::ofstream out(relative_file);
            out << std::setprecision(6) << (squared_b > 0.0 ? squared / squared_b : 0.0) << '\n';
            if (!out) throw std::runtime_error("cannot write " + relative_file);
        }
        if (!side_file.empty()) {
            const Film diff = difference_picture(a, b, 0.1 * channel_mean(mean_b));
            // The difference is a picture already: undo the exposure the writer applies to all three.
            Film diff_unexposed = diff;
            for (auto& p : diff_unexposed.pixels()) p /= exposure;
            photon::ImageWriteOptions wo;
            wo.exposure = exposure;
            wo.metadata = {{"Compression", "jpeg:88"}};
            photon::image_module::write_image(side_file, side_by_side({&a, &b, &diff_unexposed}, 8), wo);
        }
        if (!mask_file.empty()) {
            constexpr float palette[8][3] = {{1, 0.2f, 0.2f}, {0.2f, 1, 0.2f}, {0.3f, 0.3f, 1}, {1, 1, 0.2f},
                                             {1, 0.2f, 1},    {0.2f, 1, 1},    {1, 0.6f, 0.2f}, {0.6f, 0.4f, 1}};
            Film mask(a.width(), a.height());
            for (std::size_t i = 0; i < label.size(); ++i) {
                // Regions in colour over a dim copy of B, so that one sees what they cover.
                const float grey = 0.25f * std::min(1.0f, float(channel_mean(Rgb<double>(b.pixels()[i]))));
                const auto& c = palette[std::size_t(std::max(label[i], 0)) % 8];
                mask.pixels()[i] = label[i] < 0 ? Rgb<float>(grey) : Rgb<float>(c[0], c[1], c[2]);
            }
            photon::image_module::write_image(mask_file, mask);
        }
        std::cerr << "photon-compare: RMSE " << fixed(rmse, 4) << ", PSNR " << fixed(psnr, 2)
                  << " dB (peak 1), mean " << fixed(channel_mean(mean_a), 4) << " vs " << fixed(channel_mean(mean_b), 4)
                  << '\n';
        if (block > 0)
            std::cerr << "photon-compare: RMSE of " << block << "x" << block << " block means " << fixed(rmse_blocks, 4)
                      << ", worst region " << worst_region << " " << fixed(100.0 * worst_bias, 1) << "%\n";
        return EXIT_SUCCESS;
    } catch (const dsl::Error& e) {
        std::cerr << e.what() << '\n';
    } catch (const std::exception& e) {
        std::cerr << "photon-compare: error: " << e.what() << '\n';
    }
    return EXIT_FAILURE;
}
