// SPDX-License-Identifier: MIT
// The scene-class gallery (examples/scenes/classes, docs/scene-classes.md) judged at a small size:
// each class is rendered at 48 x 36 with pm, pm-direct and (where the class has only direct light)
// rt, and by a consistent judge twice with different seeds (tools/scene_class_judge.hpp). The
// image is split into a 4 x 4 grid of blocks of 12 x 9 pixels; on every block holding more than 1%
// of the judge's light, pm must be within 3% of the judge's mean, pm-direct within 5% and rt within
// the judge's noise. The judge's noise (from its two runs) is measured, printed, and must be small
// enough for those tolerances to mean something. The judged modes use the file's settings but 16
// samples per pixel: at this size 4 would add anti-aliasing noise that picture sizes do not have
// (Measurement says why).
//
// The checks that fail today are in `known_failures` below, with the error measured when they were
// recorded (pm-direct's blur on most classes; window-room's pm at the edge of the tolerance). A known failure is
// reported, not failed, unless it grows well past its recorded size; when it passes, the test says
// so and its line should be removed. ctest -V shows each class's table row.

#include <catch2/catch.hpp>

#include "scene_class_judge.hpp"

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <sstream>

using namespace classes;

namespace {

Measurement measurement() {
    Measurement m;
    m.classes_dir = PHOTON_CLASSES_DIR;
    return m;
}

std::filesystem::path class_path(const std::string& name) {
    return std::filesystem::path(PHOTON_CLASSES_DIR) / (name + ".pov");
}

/// The judge every class is measured against: sppm, or the path tracer when the environment
/// variable PHOTON_CLASSES_JUDGE is `reference`.
const Judge& judge = [] () -> const Judge& {
    const char* chosen = std::getenv("PHOTON_CLASSES_JUDGE");
    return chosen && std::string(chosen) == "reference" ? path_tracer_judge : sppm_judge;
}();

constexpr double pm_tolerance = 0.03, pm_direct_tolerance = 0.05;
/// The judge's block noise (relative standard deviation of a block mean, from its two runs) for
/// a 3% check to mean something: a 3% bias is then 4 standard deviations of the judge.
constexpr double max_judge_noise = 0.0075;
/// rt against the judge on direct-light-only classes: equal within 4 standard deviations of the
/// judge's block noise, and never tighter than 0.5%. rt is rendered with as many samples per
/// pixel as the judge (it is cheap), so that its own anti-aliasing noise is the judge's too.
double rt_tolerance(const regions::RelativeNoise& noise) { return std::max(4.0 * noise.rms, 0.005); }

/// Checks that fail with today's code, with the worst block bias measured when recorded (judge
/// sppm, 48 x 36, 4 x 4 blocks; docs/scene-classes.md shows the pictures). Remove a line when its
/// check passes.
struct KnownFailure {
    const char* scene;
    const char* mode;
    double recorded_bias;
    const char* why;
};
constexpr KnownFailure known_failures[] = {
    // pm-direct reads everything, direct light included, from the global map (k = 100 within the
    // file's radius): it blurs shadow edges and caustics across blocks. That is the method's, not
    // a lost path; the remedy is more photons and a smaller k, or pm.
    {"diffuse-ball", "pm-direct", +0.190, "the global map read directly blurs light into the ball's shadow"},
    {"glass-slab", "pm-direct", +0.057, "the light under the slab read from the global map"},
    {"point-caustic", "pm-direct", +0.121, "the focused caustic read from the global map"},
    {"cone-light", "pm-direct", +0.171, "the global map read directly blurs the cones' sharp edges"},
    {"nested-glass", "pm-direct", +0.113, "the caustics under the glass read from the global map"},
    {"csg-glass", "pm-direct", +0.081, "the lens's and the block's caustics read from the global map"},
    {"window-room", "pm", +0.030, "at the edge of the tolerance, by less than the judge's largest block noise (1.1%)"},
    {"window-room", "pm-direct", -0.073, "the indirectly lit room read from 1 M photons directly"},
    {"sky-room", "pm-direct", -0.116, "the sky's light in the room read from the global map directly (1 M photons, 1 in 20 inside)"},
    {"scale-km", "pm-direct", -0.088, "dark around the ball"},
    {"scale-mm", "pm-direct", -0.089, "dark around the ball"},
    {"mesh", "pm-direct", +0.163, "the global map read directly blurs light into the mesh's shadow"},
};
/// A known failure still fails when it grows this far (absolute) past its recorded size.
constexpr double known_failure_slack = 0.03;

const KnownFailure* known_failure(const std::string& scene, const std::string& mode) {
    for (const auto& k : known_failures)
        if (scene == k.scene && mode == k.mode) return &k;
    return nullptr;
}

void check_verdict(const std::string& scene, const Verdict& v) {
    INFO(scene << " " << v.mode << ": worst block " << percent(v.worst.bias) << ", tolerance "
               << percent(v.tolerance).substr(1));
    REQUIRE(v.worst.region >= 0);
    if (const KnownFailure* k = known_failure(scene, v.mode)) {
        if (v.passes())
            WARN(scene << " " << v.mode << " is now within " << percent(v.tolerance).substr(1) << " ("
                       << percent(v.worst.bias) << "): remove it from known_failures");
        else
            WARN(scene << " " << v.mode << ": known failure, " << percent(v.worst.bias) << " (recorded "
                       << percent(k->recorded_bias) << ": " << k->why << ")");
        CHECK(std::abs(v.worst.bias) <= std::abs(k->recorded_bias) + known_failure_slack);
    } else {
        CHECK(v.passes());
    }
}

/// The table row of one class, printed to standard output (ctest -V shows it).
void report(const SceneClass& c, const Judgement& j, const std::vector<Verdict>& verdicts) {
    std::ostringstream row;
    char text[128];
    std::snprintf(text, sizeof text, "judge %s noise %.2f%% rms, %.2f%% max, %.1f s", to_string(judge.mode),
                  100.0 * j.noise.rms, 100.0 * j.noise.max, j.seconds);
    row << "| " << c.name << " | " << text;
    for (const auto& v : verdicts) row << " | " << v.mode << " " << describe(v, 4) << (v.passes() ? "" : " FAIL");
    row << " |";
    std::cout << row.str() << std::endl;
}

void judge_scene_class(const SceneClass& c) {
    if (c.point_light_caustics && !judge.sees_point_light_caustics) {
        WARN(c.name << ": skipped, the judge (" << to_string(judge.mode)
                    << ") cannot see light from a point light through glass or mirrors");
        return;
    }
    const Measurement m = measurement();
    const Judgement j = judge_class(c, judge, m);
    {
        INFO(c.name << ": the judge's block noise is " << 100.0 * j.noise.rms << "% rms (" << 100.0 * j.noise.max
                    << "% at worst); raise its samples");
        CHECK(j.noise.rms <= max_judge_noise);
    }
    std::vector<Verdict> verdicts;
    Measurement judged = m;
    if (c.judged_samples > 0) judged.samples_per_pixel = c.judged_samples;
    verdicts.push_back(verdict("pm", render_class(c.name, RenderMode::pm, judged), j, pm_tolerance));
    verdicts.push_back(verdict("pm-direct", render_class(c.name, RenderMode::pm_direct, judged), j, pm_direct_tolerance));
    if (c.direct_only) {
        Measurement fine = m;
        fine.samples_per_pixel = c.reference_samples;
        verdicts.push_back(verdict("rt", render_class(c.name, RenderMode::rt, fine), j, rt_tolerance(j.noise)));
    }
    report(c, j, verdicts);
    for (const auto& v : verdicts) check_verdict(c.name, v);
}

const SceneClass& scene_class(const std::string& name) {
    for (const auto& c : gallery)
        if (name == c.name) return c;
    throw std::invalid_argument("no scene class " + name);
}

}  // namespace

TEST_CASE("every scene class parses and builds without warnings and names its light paths", "[classes]") {
    for (const auto& c : gallery) {
        INFO(c.name);
        std::vector<dsl::Diagnostic> warnings;
        dsl::ParseOptions po;
        po.diagnostics = [&](const dsl::Diagnostic& d) { warnings.push_back(d); };
        const auto built = dsl::load_scene<float>(class_path(c.name), po);
        CHECK(warnings.empty());  // the mirror plane too: it is aimed at through its mirror image
        CHECK((!built.scene.lights().empty() || built.scene.has_environment_light()));  // sky-room: the sky alone
        std::ifstream file(class_path(c.name));
        const std::string text((std::istreambuf_iterator<char>(file)), std::istreambuf_iterator<char>());
        CHECK(text.find("// Light paths: ") != std::string::npos);
        CHECK(text.find("Scene class \"" + std::string(c.name) + "\"") != std::string::npos);
    }
}

TEST_CASE("the many-lights class has 100 lights", "[classes]") {
    const auto built = dsl::load_scene<float>(class_path("many-lights"));
    CHECK(built.scene.lights().size() == 100);
}

// One test case per class, so that ctest runs them in parallel and names the one that fails.
TEST_CASE("scene class diffuse-ball against the judge", "[classes][gallery]") { judge_scene_class(scene_class("diffuse-ball")); }
TEST_CASE("scene class mirror-plane against the judge", "[classes][gallery]") { judge_scene_class(scene_class("mirror-plane")); }
TEST_CASE("scene class glass-slab against the judge", "[classes][gallery]") { judge_scene_class(scene_class("glass-slab")); }
TEST_CASE("scene class point-caustic against the judge", "[classes][gallery]") { judge_scene_class(scene_class("point-caustic")); }
TEST_CASE("scene class cone-light against the judge", "[classes][gallery]") { judge_scene_class(scene_class("cone-light")); }
TEST_CASE("scene class nested-glass against the judge", "[classes][gallery]") { judge_scene_class(scene_class("nested-glass")); }
TEST_CASE("scene class csg-glass against the judge", "[classes][gallery]") { judge_scene_class(scene_class("csg-glass")); }
TEST_CASE("scene class mirror-corridor against the judge", "[classes][gallery]") { judge_scene_class(scene_class("mirror-corridor")); }
TEST_CASE("scene class window-room against the judge", "[classes][gallery]") { judge_scene_class(scene_class("window-room")); }
TEST_CASE("scene class sky-room against the judge", "[classes][gallery]") { judge_scene_class(scene_class("sky-room")); }
TEST_CASE("scene class scale-km against the judge", "[classes][gallery]") { judge_scene_class(scene_class("scale-km")); }
TEST_CASE("scene class scale-mm against the judge", "[classes][gallery]") { judge_scene_class(scene_class("scale-mm")); }
TEST_CASE("scene class many-lights against the judge", "[classes][gallery]") { judge_scene_class(scene_class("many-lights")); }
TEST_CASE("scene class mesh against the judge", "[classes][gallery]") { judge_scene_class(scene_class("mesh")); }

TEST_CASE("scale-km and scale-mm, the same scene 10^6 times apart, render alike", "[classes][gallery]") {
    const Measurement m = measurement();
    for (const RenderMode mode : {RenderMode::rt, RenderMode::pm}) {
        const Render km = render_class("scale-km", mode, m), mm = render_class("scale-mm", mode, m);
        const auto lit = regions::lit_regions(km.blocks, std::vector<double>(km.blocks.size(), 1.0), m.min_light_fraction);
        const auto worst = regions::worst_bias(mm.blocks, km.blocks, lit);
        INFO(to_string(mode) << ": scale-mm / scale-km - 1 is " << percent(worst.bias) << " on block " << worst.region);
        std::cout << "scale-mm against scale-km, " << to_string(mode) << ": worst block " << percent(worst.bias) << std::endl;
        // rt is direct light by shadow rays: the same strata at either scale. pm adds photon noise.
        CHECK(std::abs(worst.bias) <= (mode == RenderMode::rt ? 0.005 : pm_tolerance));
    }
}
