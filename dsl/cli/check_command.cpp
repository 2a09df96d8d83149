// SPDX-License-Identifier: MIT
// `photon check`: reads and builds a scene as `render` does and reports what it holds, with the
// settings and plan lines that `render` prints too (scene_report.hpp).

#include "commands.hpp"
#include "load_image_io.hpp"
#include "scene_report.hpp"

#include <photon/dsl/parser.hpp>
#include <photon/plan/plan_report.hpp>

#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <iostream>
#include <map>
#include <sstream>
#include <type_traits>
#include <variant>

namespace photon::cli {

namespace {

std::string vec(const Vec3<float>& v) {
    std::ostringstream s;
    s << '<' << v.x << ", " << v.y << ", " << v.z << '>';
    return s.str();
}

std::string rgb(const Rgb<float>& c) {
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

/// Prints what the scene holds: the report of `photon check`.
void report(const std::string& file, const dsl::SceneDescription& desc, const dsl::BuiltScene<float>& b) {
    const auto& scene = b.scene;
    std::cout << "scene      " << file << " (" << desc.files.size() << " file" << (desc.files.size() == 1 ? "" : "s")
              << ")\n";
    const auto& cam = b.camera;
    std::cout << "camera     " << to_string(cam.projection()) << ", location " << vec(cam.location()) << ", direction "
              << vec(cam.direction()) << ", right " << vec(cam.right()) << ", up " << vec(cam.up());
    switch (cam.projection()) {
        case Projection::perspective:
            std::cout << " (horizontal field of view "
                      << 2.0f * std::atan(0.5f * glm::length(cam.right()) / glm::length(cam.direction())) * 180.0f / pi<float>
                      << " deg)";
            break;
        case Projection::orthographic: break;
        case Projection::spherical:
            std::cout << ", angles " << cam.frame().angle << " x " << cam.frame().vertical_angle << " deg";
            break;
        default: std::cout << ", angle " << cam.frame().angle << " deg";
    }
    if (cam.has_focal_blur())
        std::cout << ", aperture " << cam.focal_blur().aperture << ", focal distance " << cam.focal_blur().focal_distance;
    std::cout << '\n';
    std::cout << "lights     " << scene.lights().size() << '\n';
    for (const auto& light : scene.lights()) {
        const float radius = light_radius(light);
        const auto* area = std::get_if<AreaLight<float>>(&light);
        const auto* parallel = std::get_if<ParallelLight<float>>(&light);
        std::cout << "           "
                  << (area ? "area light" : parallel ? "parallel light" : radius > 0 ? "sphere light" : "point light")
                  << " at " << vec(light_center(light));
        if (parallel) {
            std::cout << ", direction " << vec(parallel->direction) << ", irradiance " << rgb(parallel->irradiance)
                      << " W/m^2, beam radius " << parallel->beam_radius << ", power " << rgb(light_power(light)) << " W";
        } else if (area)
            std::cout << ", axes " << vec(area->axis1) << " and " << vec(area->axis2) << ", " << area->size1 << " x "
                      << area->size2 << (area->jitter ? " jittered" : "") << (area->circular ? " circular" : "");
        else if (radius > 0)
            std::cout << ", radius " << radius;
        if (!parallel)
            std::cout << ", power " << rgb(light_power(light)) << " W, intensity " << rgb(radiant_intensity(light))
                      << " W/sr";
        if (const auto& cone = light_cone(light))
            std::cout << ", " << (cone->is_soft() ? "spotlight profile " : "cone ") << vec(cone->axis()) << " half-angle "
                      << cone->half_angle_degrees() << " deg";
        const auto& falloff = light_falloff(light);
        using Kind = std::remove_cvref_t<decltype(falloff)>::Kind;
        if (falloff.kind == Kind::constant) std::cout << ", no falloff";
        if (falloff.kind == Kind::fade)
            std::cout << ", fade 1 / (1 + (d / " << falloff.distance << ")^" << falloff.power << ")";
        if (!light_casts_shadows(light)) std::cout << ", shadowless";
        std::cout << '\n';
    }
    std::map<std::string, std::size_t> kinds;
    std::size_t targets = 0, shadowless = 0;
    for (std::uint32_t i = 0; i < scene.objects().size(); ++i) {
        const auto& o = scene.objects()[i];
        ++kinds[std::visit([](const auto& shape) { return plan::shape_name(shape); }, o.shape)];
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
        if (p.transmission != Rgb<float>(0) || p.fresnel) std::cout << ", ior " << p.ior << (p.fresnel ? " (Fresnel)" : "");
        if (p.phong > 0) std::cout << ", phong " << p.phong << " size " << p.phong_exponent;
        if (p.blinn > 0) std::cout << ", blinn " << p.blinn << " exponent " << p.blinn_exponent;
        if (p.metallic > 0 && (p.phong > 0 || p.blinn > 0)) std::cout << ", metallic " << p.metallic;
        if (p.brilliance != 1) std::cout << ", brilliance " << p.brilliance;
        if (p.ambient != Rgb<float>(0)) std::cout << ", ambient " << rgb(p.ambient);
        if (p.normal_field) std::cout << ", normal pattern (tilted shading normal)";
        std::cout << '\n';
    }
    std::cout << "settings   " << settings_line(b.settings) << '\n';
    const char* label = "plan       ";  // what a render of this scene will do (plan/effects_plan.hpp)
    for (const std::string& line : plan_of(b, b.settings)) {
        std::cout << label << line << '\n';
        label = "           ";
    }
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

}  // namespace

std::string settings_line(const RenderSettings& s) {
    std::ostringstream o;
    o << s.width << " x " << s.height << ", mode " << to_string(s.mode) << ", " << s.samples_per_pixel
      << " samples per pixel";
    const bool pass_two = s.mode == RenderMode::rt || s.mode == RenderMode::pm || s.mode == RenderMode::pm_direct;
    if (pass_two && samples_by_contrast(s)) {
        o << " (anti-aliased where neighbours differ by " << s.aa_contrast << ": rounds of " << s.aa_samples;
        if (s.aa_threshold > 0) o << " while noisier than " << s.aa_threshold;
        o << ", up to " << s.aa_max_samples << ")";
    } else if (pass_two && samples_adaptively(s)) {
        o << " (adaptive to " << s.aa_max_samples << " at threshold " << s.aa_threshold << ")";
    }
    o << ", ray depth " << s.max_ray_depth;
    if (pass_two && s.adc_bailout > 0) o << " (adc bailout " << s.adc_bailout << ")";
    o << ", " << s.shadow_samples << " shadow samples";
    if (s.mode == RenderMode::sppm)
        o << "; sppm: " << s.sppm_passes << " passes of " << s.sppm_photons_per_pass << " photons, initial radius "
          << (s.sppm_initial_radius > 0 ? std::to_string(s.sppm_initial_radius) : std::string("auto"))
          << ", photon depth " << s.max_photon_depth;
    else if (s.mode != RenderMode::rt)
        o << "; photons: " << s.global_photons << " global (k " << s.global_estimate.k << ", radius "
          << radius_text(s.global_estimate.max_radius) << "), " << s.caustic_photons << " caustic (k "
          << s.caustic_estimate.k << ", radius " << radius_text(s.caustic_estimate.max_radius) << "), photon depth "
          << s.max_photon_depth << ", final gather " << s.final_gather_rays;
    if (uses_irradiance_cache(s) && s.cache_gather_noise > 0)
        o << " (cache records to " << 100 * s.cache_gather_noise << "% noise)";
    if (s.mode == RenderMode::reference && !s.reference_mis) o << ", no MIS";
    if (s.time_limit > 0) o << ", time limit " << s.time_limit << " s";
    if (s.target_error > 0) o << ", target error " << 100 * s.target_error << "%";
    o << ", seed " << s.seed;
    return o.str();
}

std::vector<std::string> plan_of(const dsl::BuiltScene<float>& built, const RenderSettings& settings) {
    return plan_lines(plan_effects(built.scene, built.camera, settings), to_string(settings.mode));
}

/// `photon check` builds the scene as `render` does, so the build step's errors (a mesh file
/// missing or broken, at its name in the scene) are reported by check too.
int run_check(SceneOptions& so, const dsl::SettingsOverrides& overrides) {
    const dsl::SceneDescription desc = dsl::parse_file(so.scene, so.parse_options(overrides));
    dsl::BuildOptions bo;
    bo.diagnostics = so.sink();
    bo.overrides = overrides;
    bo.read_image = [](const std::filesystem::path& f, ImageGamma g) { return photon::image_module::read_pixel_grid(f, g); };
    const dsl::BuiltScene<float> built = dsl::build<float>(desc, bo);
    if (!so.quiet) {  // -q: errors only, the exit status says the rest
        report(so.scene, desc, built);
        std::cout << "warnings   " << so.warnings << '\n';
        print_degraded(so.degraded);
    }
    return so.failed_strict() ? exit_error : EXIT_SUCCESS;
}

}  // namespace photon::cli
