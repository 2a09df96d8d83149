// SPDX-License-Identifier: MIT
#pragma once
// A pigment's pattern as the library's Pigment: its pattern and modifiers, its colours as diffuse
// albedos (rgb times the opacity 1 - filter - transmit, as material_params reads a colour), and
// its placement in the world.

#include <algorithm>
#include <string>

#include <photon/texture/image_map.hpp>
#include <photon/texture/pigment.hpp>

#include "../description.hpp"
#include "../image_files.hpp"
#include "../physical_ranges.hpp"

namespace photon::dsl {

[[nodiscard]] inline PatternKind pattern_kind(const std::string& name) {
    static const std::pair<const char*, PatternKind> kinds[] = {
        {"checker", PatternKind::checker},     {"gradient", PatternKind::gradient}, {"bozo", PatternKind::bozo},
        {"spotted", PatternKind::spotted},     {"granite", PatternKind::granite},   {"marble", PatternKind::marble},
        {"wood", PatternKind::wood},           {"agate", PatternKind::agate},       {"onion", PatternKind::onion},
        {"leopard", PatternKind::leopard},     {"radial", PatternKind::radial},     {"ripples", PatternKind::ripples},
        {"waves", PatternKind::waves},         {"spherical", PatternKind::spherical}, {"planar", PatternKind::planar},
        {"boxed", PatternKind::boxed},         {"cylindrical", PatternKind::cylindrical}, {"hexagon", PatternKind::hexagon},
        {"cells", PatternKind::cells},         {"crackle", PatternKind::crackle},   {"bumps", PatternKind::bumps},
        {"dents", PatternKind::dents},         {"wrinkles", PatternKind::wrinkles}, {"mandel", PatternKind::mandel},
        {"spiral1", PatternKind::spiral1},     {"spiral2", PatternKind::spiral2},   {"quilted", PatternKind::quilted}};
    for (const auto& [n, k] : kinds)
        if (name == n) return k;
    throw std::invalid_argument("photon does not evaluate the pattern `" + name + "`");
}

/// The colour of a map entry as a diffuse albedo (before the finish's `diffuse` factor).
[[nodiscard]] inline Vector3 albedo_color(const Color& c) {
    const Color p = physical_pigment(c).value;
    return p.rgb * std::max(0.0, 1.0 - p.filter - p.transmit);
}

/// The largest albedo_color of the pattern's colours, per channel (of a pigment_map's
/// patterned entries, theirs; of an image, 1: image files hold colours up to 1).
[[nodiscard]] inline Vector3 max_albedo_color(const PigmentPattern& p) {
    if (p.image) return Vector3(1.0);
    Vector3 m(0.0);
    for (std::size_t i = 0; i < p.colors.size(); ++i)
        m = glm::max(m, i < p.nested.size() && p.nested[i] ? max_albedo_color(*p.nested[i]->pattern)
                                                            : albedo_color(p.colors[i].second));
    return m;
}

/// The pattern's modifiers (gradient, turbulence, noise, wave) written onto `out`.
[[nodiscard]] inline Pattern with_modifiers(Pattern out, const PigmentPattern& p) {
    out.gradient = p.gradient;
    out.agate_turb = p.agate_turb;
    out.crackle = {.form = p.crackle_form, .metric = p.crackle_metric, .offset = p.crackle_offset, .solid = p.crackle_solid};
    out.fractal = {.iterations = p.fractal_iterations, .interior_type = p.interior_type, .exterior_type = p.exterior_type,
                   .interior_factor = p.interior_factor, .exterior_factor = p.exterior_factor};
    out.spiral_arms = p.spiral_arms;
    out.quilt_control0 = p.quilt_control0;
    out.quilt_control1 = p.quilt_control1;
    out.turbulence = p.turbulence;
    out.octaves = {.octaves = p.octaves, .omega = p.omega, .lambda = p.lambda};
    if (p.noise_generator != 0) out.noise_generator = NoiseGenerator(p.noise_generator);
    out.wave.frequency = p.frequency;
    out.wave.phase = p.phase;
    out.wave.exponent = p.exponent;
    static const std::pair<const char*, WaveType> waves[] = {{"ramp_wave", WaveType::ramp},   {"sine_wave", WaveType::sine},
                                                             {"triangle_wave", WaveType::triangle},
                                                             {"scallop_wave", WaveType::scallop},
                                                             {"cubic_wave", WaveType::cubic}, {"poly_wave", WaveType::poly}};
    for (const auto& [n, w] : waves)
        if (p.wave == n) out.wave.type = w;
    return out;
}

/// image_map as the library's ImageMap, its pixels read through `images` (a located error when
/// none is given or the file cannot be read); `placement` maps the image's space to the world.
template <Scalar S>
[[nodiscard]] std::shared_ptr<const ImageMap<S>> image_map(const ImageMapDesc& m, const Transform& placement,
                                                           ImageFiles* images) {
    if (!images) throw Error(m.file.at, "image maps are not read here (no image files were given to this build)");
    Affine<double> a;
    a.linear = placement.linear;
    a.translation = placement.translation;
    const ImageMapOptions options{.map_type = ImageMapType(m.map_type),
                                  .interpolate = ImageInterpolation(m.interpolate),
                                  .once = m.once,
                                  .filter_all = m.filter_all,
                                  .transmit_all = m.transmit_all};
    return std::make_shared<const ImageMap<S>>(images->grid(m.file, true), options, a);
}

[[nodiscard]] inline Pattern library_pattern(const PigmentPattern& p) {
    return with_modifiers(Pattern::of(pattern_kind(p.name)), p);
}

/// The pigment's pattern as a library Pigment whose colours are albedos; `placement` maps the
/// pattern's space to the world.
template <Scalar S>
[[nodiscard]] photon::Pigment<S> library_pigment(const PigmentPattern& p, const Transform& placement) {
    std::vector<typename ColorMap<S>::Entry> entries;
    for (const auto& [v, c] : p.colors) entries.push_back({v, Rgb<S>(albedo_color(c))});
    Affine<double> a;
    a.linear = placement.linear;
    a.translation = placement.translation;
    return photon::Pigment<S>(library_pattern(p), ColorMap<S>(std::move(entries)), a);
}

}  // namespace photon::dsl
