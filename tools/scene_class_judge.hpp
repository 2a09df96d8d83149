// SPDX-License-Identifier: MIT
#pragma once
// The measuring instrument of the scene-class gallery (examples/scenes/classes/*.pov): renders a
// class with photon's modes and with a judge (a consistent renderer that sees the class's light
// paths), splits the images into a grid of blocks and reports each mode's worst block bias against
// the judge, with the judge's own noise measured from two runs of different seeds. Used by the
// gallery test (tests/classes, small images) and photon-classes (tools/render_classes.cpp, the
// pictures of docs/scene-classes.md).

#include <photon/dsl/dsl.hpp>
#include <photon/integrator/render.hpp>

#include "region_statistics.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace classes {

using namespace photon;

/// A class of the gallery and what it needs to be judged.
struct SceneClass {
    const char* name;
    bool direct_only;           ///< L D E only: rt must match the judge too
    bool point_light_caustics;  ///< light from a point light through mirrors or glass onto a diffuse surface
    unsigned reference_samples; ///< path tracer: samples per pixel of each of the judge's two runs
    unsigned sppm_passes;       ///< sppm: passes of each run
    /// Samples per pixel of the judged modes (0: the measurement's). A caustic focused to a few
    /// millimetres is found by few camera samples: at 16 per pixel pm's caustic block varied
    /// with the seed, at 256 it matches the judge (docs/scene-classes.md, 'Results').
    unsigned judged_samples = 0;
};

/// The gallery. The judges' efforts are for 48 x 36 and 4 x 4 blocks (the test): enough to keep
/// the judge's block noise under 0.75%. The path tracer finds light that comes by way of a mirror
/// or glass (L S+ D E) only by hitting the light after the diffuse bounce, so those classes need
/// many more of its samples.
inline constexpr SceneClass gallery[] = {
    // name, direct only, point-light caustics, path tracer samples, sppm passes
    {"diffuse-ball", false, false, 512, 256},
    {"mirror-plane", false, false, 16384, 256},
    {"glass-slab", false, false, 6144, 256},
    {"point-caustic", false, true, 1024, 256, 256},
    {"cone-light", true, false, 256, 256},
    {"nested-glass", false, false, 2048, 256},
    {"csg-glass", false, false, 2048, 256},
    {"mirror-corridor", false, false, 14336, 256},
    {"window-room", false, false, 1536, 512},
    {"sky-room", false, false, 1536, 512},
    {"scale-km", false, false, 512, 256},
    {"scale-mm", false, false, 512, 256},
    {"many-lights", true, false, 16, 16},
    {"mesh", false, false, 512, 256},
};

/// How hard the judge works beyond a class's own effort (photon-classes raises it for pictures).
struct JudgeEffort {
    double scale = 1.0;                           ///< times the class's samples or passes
    std::size_t sppm_photons_per_pass = 20'000;   ///< the pass count, not the photons, shrinks the radii
};

/// A renderer that judges the others: its mode, how its effort is set, and which paths it sees.
struct Judge {
    RenderMode mode;
    /// Whether it finds light that reaches a diffuse surface from a point light through mirrors
    /// or glass (L S+ D E with a point light). A path tracer cannot: it would have to hit a point.
    bool sees_point_light_caustics;
    /// Sets the judge's effort for a class (samples per pixel, or passes).
    void (*configure)(RenderSettings&, const SceneClass&, const JudgeEffort&);
    /// The judge renders this many times the measured width and height (its blocks cover the
    /// same parts of the image). sppm's first radius is 2 pixel footprints: at 48 x 36 that blurs
    /// a sharp caustic across block edges (point-caustic, blocks 1,2 and 2,2: 0.246 and 0.130 at
    /// 48 x 36, 0.254 and 0.118 at 192 x 144 and 0.254 and 0.119 at 320 x 240).
    unsigned supersampling = 1;
};

inline unsigned scaled(unsigned samples, double scale) { return std::max(1u, unsigned(std::lround(samples * scale))); }

/// The path tracer (--mode reference): unbiased, but blind to point-light caustics.
inline const Judge path_tracer_judge{RenderMode::reference, false,
                                     [](RenderSettings& s, const SceneClass& c, const JudgeEffort& e) {
                                         s.samples_per_pixel = scaled(c.reference_samples, e.scale);
                                     }};

/// Stochastic progressive photon mapping (--mode sppm): consistent, sees every path. Its
/// photons follow up to 100 bounces (the files' max_photon_depth is pm's setting, not the
/// scene's), and one shadow ray per light and pass (the passes average them).
inline const Judge sppm_judge{RenderMode::sppm, true, [](RenderSettings& s, const SceneClass& c, const JudgeEffort& e) {
                                  s.sppm_passes = scaled(c.sppm_passes, e.scale);
                                  s.sppm_photons_per_pass = e.sppm_photons_per_pass;
                                  s.max_photon_depth = 100;
                                  s.shadow_samples = 1;
                              },
                              4};

/// The image size, grid and thresholds of the measurement.
struct Measurement {
    std::filesystem::path classes_dir;  ///< examples/scenes/classes
    unsigned width = 48, height = 36;  ///< small: the judge must converge within CI's time
    unsigned columns = 4, rows = 4;    ///< blocks of 12 x 9 pixels at 48 x 36
    double min_light_fraction = 0.01;  ///< blocks holding less of the judge's light are not judged
    /// Of the judged modes (the judge sets its own). The files ask for 4, enough at 320 x 240; but a
    /// 12 x 9 block that a sharp light edge crosses keeps a few percent of anti-aliasing noise at 4
    /// (cone-light's rt: docs/scene-classes.md, 'The measurement'), which is not what is measured.
    unsigned samples_per_pixel = 16;
    /// pm's irradiance cache error for the judged renders (unset: the file's, the default). The
    /// cache bounds its records' radii in pixels of an image at least 800 wide
    /// (irradiance_cache_pass.hpp), so at 48 x 36 it interpolates no further in the scene than at
    /// picture sizes; before that bound, one record spanned much of the scene (scale-km with the
    /// cache against a final gather at every sample: docs/scene-classes.md, 'The measurement').
    std::optional<float> irradiance_cache_error{};
};

struct Render {
    Film film;
    std::vector<Rgb<double>> blocks;  ///< grid means
    double seconds = 0.0;             ///< photon tracing and image, as RenderStats::total_seconds
};

/// Renders class `name` in `mode` at the measurement's size; the scene file's settings otherwise,
/// changed by `adjust` (the judge's samples, a seed).
template <class Adjust>
Render render_class(const std::string& name, RenderMode mode, const Measurement& m, Adjust adjust,
                    unsigned supersampling = 1) {
    const unsigned width = m.width * supersampling, height = m.height * supersampling;
    dsl::ParseOptions po;
    po.image_width = width, po.image_height = height;
    dsl::BuildOptions bo;
    bo.overrides = {{"width", width}, {"height", height}, {"mode", std::string(dsl::render_mode_name(mode))}};
    auto built = dsl::load_scene<float>(m.classes_dir / (name + ".pov"), po, bo);
    adjust(built.settings);
    const auto result = photon::render(built.scene, built.camera, built.settings);
    if (!result.film.all_finite_nonnegative()) throw std::runtime_error(name + ": the image holds NaN, Inf or negative values");
    return {result.film, regions::grid_means(result.film, m.columns, m.rows), result.stats.total_seconds};
}

/// A judged mode: the file's settings at the measurement's size and samples per pixel.
inline Render render_class(const std::string& name, RenderMode mode, const Measurement& m) {
    return render_class(name, mode, m, [&](RenderSettings& s) {
        s.samples_per_pixel = m.samples_per_pixel;
        if (m.irradiance_cache_error) s.irradiance_cache_error = *m.irradiance_cache_error;
    });
}

/// The judge's two runs, their mean, and the blocks that count.
struct Judgement {
    Film film;                        ///< mean of the two runs (at the judge's supersampled size)
    std::vector<Rgb<double>> blocks;  ///< mean of the two runs
    std::vector<bool> lit;            ///< blocks holding more than the minimum share of its light
    regions::RelativeNoise noise;     ///< relative noise of `blocks`, from the runs' difference
    double seconds = 0.0;             ///< both runs
};

inline Judgement judge_class(const SceneClass& c, const Judge& judge, const Measurement& m,
                             const JudgeEffort& effort = {}) {
    Render runs[2];
    for (unsigned i = 0; i < 2; ++i)
        runs[i] = render_class(c.name, judge.mode, m, [&](RenderSettings& s) {
            judge.configure(s, c, effort);
            s.seed = 1 + i;
        }, judge.supersampling);
    Judgement j;
    j.film = runs[0].film;
    for (std::size_t p = 0; p < j.film.pixels().size(); ++p)
        j.film.pixels()[p] = (runs[0].film.pixels()[p] + runs[1].film.pixels()[p]) * 0.5f;
    for (std::size_t b = 0; b < runs[0].blocks.size(); ++b) j.blocks.push_back((runs[0].blocks[b] + runs[1].blocks[b]) * 0.5);
    const std::vector<double> sizes(j.blocks.size(), 1.0);  // equal blocks at the measurement's sizes
    j.lit = regions::lit_regions(j.blocks, sizes, m.min_light_fraction);
    j.noise = regions::noise_of_mean(runs[0].blocks, runs[1].blocks, j.lit);
    j.seconds = runs[0].seconds + runs[1].seconds;
    return j;
}

/// One mode's result against the judge.
struct Verdict {
    std::string mode;
    regions::WorstBias worst;
    double tolerance = 0.0;
    double seconds = 0.0;
    [[nodiscard]] bool passes() const noexcept { return std::abs(worst.bias) <= tolerance; }
};

inline Verdict verdict(const std::string& mode, const Render& r, const Judgement& j, double tolerance) {
    return {mode, regions::worst_bias(r.blocks, j.blocks, j.lit), tolerance, r.seconds};
}

inline std::string percent(double fraction) {
    char text[32];
    std::snprintf(text, sizeof text, "%+.1f%%", 100.0 * fraction);
    return text;
}

/// "pm -38.2% (block 9) 0.41 s" for the table.
inline std::string describe(const Verdict& v, unsigned columns) {
    char text[96];
    if (v.worst.region < 0) return v.mode + " -";
    std::snprintf(text, sizeof text, "%s (block %d,%d) in %.2f s", percent(v.worst.bias).c_str(),
                  v.worst.region % int(columns), v.worst.region / int(columns), v.seconds);
    return text;
}

}  // namespace classes
