// SPDX-License-Identifier: MIT
#pragma once
// The one table of render settings. Each entry is one RenderSettings field: the global_settings
// item that sets it in a scene file, the `photon render` option that overrides it, its bounds,
// its kind and its help text. The parser (parser/settings.hpp), the command line
// (cli/setting_options.hpp), the build step (build.hpp), export-pov (export_pov.hpp) and the
// settings table of docs/scene-language.md (checked by tests/dsl/settings_table_test.cpp) all
// read it, so a setting is declared here and nowhere else.
//
// Each entry also holds `photon render`'s default where it differs from the library's (the
// RenderSettings member's initializer): a function of what the scene is and of the render mode
// (ProgramDefault), so that the one resolution (build/settings.hpp) applies it where neither the
// file nor the command line writes the setting, for `render`, `check` and the tools alike.
//
// Not in the table, because they are not one item for one field: POV-Ray's `photons { }` block
// (its `count`, `gather MIN, MAX`, `radius` of up to four values and `max_trace_level` set
// photon's caustic settings with a different meaning, and `spacing` has no photon equivalent:
// parser/settings.hpp and build/settings.hpp). The command line's output options (-o,
// --exposure, --no-stats, --no-mis) are not settings a scene file carries: they stay in cli/.

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <type_traits>
#include <variant>
#include <vector>

#include <photon/settings/render_settings.hpp>

#include "description.hpp"
#include "value.hpp"

namespace photon::dsl {

/// The names of the render modes, each mode's first name being how photon writes it. A scene
/// file's `render_mode` takes the names marked `in_scene` (not `reference`, as before this table);
/// the command line's `--mode` takes them all.
struct RenderModeName {
    std::string_view name;
    RenderMode mode;
    bool in_scene;
};
inline constexpr RenderModeName render_mode_names[] = {
    {"rt", RenderMode::rt, true},        {"pm", RenderMode::pm, true},
    {"pm_direct", RenderMode::pm_direct, true}, {"pm-direct", RenderMode::pm_direct, true},  // a string in a file
    {"reference", RenderMode::reference, false}, {"sppm", RenderMode::sppm, true}};

[[nodiscard]] constexpr const RenderModeName* find_render_mode(std::string_view name) {
    for (const RenderModeName& m : render_mode_names)
        if (m.name == name) return &m;
    return nullptr;
}
/// The name photon writes for `mode` (pm_direct, not pm-direct: a file can write it unquoted).
[[nodiscard]] constexpr std::string_view render_mode_name(RenderMode mode) {
    for (const RenderModeName& m : render_mode_names)
        if (m.mode == mode) return m.name;
    return "?";
}

/// What a setting's value is: a whole number (a count, a depth, a seed), a real, a mode name, or
/// a string (a quoted string in a file) that the setting's own `text_problem` checks.
enum class SettingKind { integer, real, mode, text };

/// How the table reaches a RenderSettings field: set it from a checked value, read it back.
struct SettingField {
    void (*set)(RenderSettings&, const SettingValue&);
    SettingValue (*get)(const RenderSettings&);
};

namespace detail {

template <class T>
T from_setting_value(const SettingValue& v) {
    if constexpr (std::is_same_v<T, RenderMode>) {
        return find_render_mode(std::get<std::string>(v))->mode;
    } else if constexpr (std::is_same_v<T, EffectSwitches>) {
        return parse_effect_switches(std::get<std::string>(v));
    } else if constexpr (std::is_floating_point_v<T>) {
        return std::holds_alternative<double>(v) ? T(std::get<double>(v)) : T(std::get<std::uint64_t>(v));
    } else {
        return std::holds_alternative<double>(v) ? T(std::get<double>(v)) : T(std::get<std::uint64_t>(v));
    }
}
/// The double written as the float's shortest decimal (0.05, not 0.05000000074505806): what a
/// file would write for it, and it reads back as the same float.
inline double float_as_written(float v) {
    char buf[32];
    const auto r = std::to_chars(buf, buf + sizeof buf, v);
    double d = 0;
    std::from_chars(buf, r.ptr, d);
    return d;
}
template <class T>
SettingValue to_setting_value(T v) {
    if constexpr (std::is_same_v<T, RenderMode>)
        return std::string(render_mode_name(v));
    else if constexpr (std::is_same_v<T, EffectSwitches>)
        return to_string(v);
    else if constexpr (std::is_same_v<T, float>)
        return float_as_written(v);
    else if constexpr (std::is_floating_point_v<T>)
        return double(v);
    else
        return std::uint64_t(v);
}
template <auto Member>
void set_member(RenderSettings& s, const SettingValue& v) {
    s.*Member = from_setting_value<std::remove_cvref_t<decltype(s.*Member)>>(v);
}
template <auto Member>
SettingValue get_member(const RenderSettings& s) {
    return to_setting_value(s.*Member);
}
template <auto Estimate, auto Member>
void set_estimate(RenderSettings& s, const SettingValue& v) {
    (s.*Estimate).*Member = from_setting_value<std::remove_cvref_t<decltype((s.*Estimate).*Member)>>(v);
}
template <auto Estimate, auto Member>
SettingValue get_estimate(const RenderSettings& s) {
    return to_setting_value((s.*Estimate).*Member);
}

}  // namespace detail

/// RenderSettings::*Member.
template <auto Member>
inline constexpr SettingField member{&detail::set_member<Member>, &detail::get_member<Member>};
/// (RenderSettings::*Estimate).*Member: a field of the global or the caustic estimate.
template <auto Estimate, auto Member>
inline constexpr SettingField estimate_member{&detail::set_estimate<Estimate, Member>,
                                              &detail::get_estimate<Estimate, Member>};

inline constexpr double unbounded = std::numeric_limits<double>::max();

/// What `photon render`'s defaults depend on (build/settings.hpp fills it in): the facts of the
/// scene file, and the mode the render runs in, resolved first.
struct DefaultContext {
    RenderMode mode = RenderMode::pm;
    bool mode_written = false;      ///< the file or the command line chose the mode
    bool radiosity = false;         ///< the file has POV-Ray's `radiosity { }`
    bool povray_photons = false;    ///< the file has POV-Ray's `photons { }` in global_settings
    unsigned area_light_grid = 0;   ///< the largest area_light's N1 x N2 (0: no area light)
    unsigned blur_samples = 0;      ///< the camera's focal blur samples (0: no focal blur)
    bool budget = false;            ///< a time limit or a target error is set
};

/// `photon render`'s default of a setting in `c`, or nothing to keep the library's.
using ProgramDefault = std::optional<SettingValue> (*)(const DefaultContext& c);

/// Whether mode m renders its image with pass 2's camera samples (image_pass.hpp).
[[nodiscard]] constexpr bool traces_pixels(RenderMode m) noexcept {
    return m == RenderMode::rt || m == RenderMode::pm || m == RenderMode::pm_direct;
}

/// One render setting.
struct RenderSetting {
    std::string_view key;      ///< the RenderSettings field it sets, as the description and overrides name it
    std::string_view keyword;  ///< its global_settings item ("" when a file cannot set it)
    std::string_view block;    ///< the global_settings block holding the keyword ("global_estimate"), or ""
    bool povray = false;       ///< POV-Ray's own item (written outside `#ifdef (photon_version)`)
    std::string_view flag;     ///< its `photon render` option ("" when there is none)
    SettingKind kind = SettingKind::integer;
    double lo = 0, hi = unbounded;  ///< bounds (a real's `hi` unbounded: any finite value)
    bool lo_exclusive = false;      ///< a real must be above `lo`
    std::string_view noun;          ///< what messages call it ("samples per pixel")
    std::string_view help;          ///< for --help and the docs
    /// A real the command line may also write with a unit: "seconds" (90s, 2m, 1h), "fraction" (1%).
    std::string_view units;
    SettingField field{};
    /// A text setting: why a value is not one of it ("must be ..."), or nothing.
    std::optional<std::string> (*text_problem)(std::string_view) = nullptr;
    /// `photon render`'s default, where it differs from the library's (null: the library's).
    ProgramDefault program_default = nullptr;
    /// What the program default depends on besides the mode, for the docs ("" when only the mode).
    std::string_view program_default_note;
};

// Each entry names only the members it sets (the others keep their defaults), which GCC's
// -Wextra reports although the initializers are designated.
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmissing-field-initializers"
#endif
// clang-format off
// cache_gather_noise's help text names the cap: change both together.
static_assert(cache_gather_max_factor == 4, "update the help text of cache_gather_noise");

/// Every render setting, in the order of `photon render --help` and of the docs' table.
inline constexpr RenderSetting render_settings_table[] = {
    {.key = "width", .keyword = "width", .flag = "--width", .lo = 1, .hi = 65536, .noun = "image width",
     .help = "Image width in pixels", .field = member<&RenderSettings::width>},
    {.key = "height", .keyword = "height", .flag = "--height", .lo = 1, .hi = 65536, .noun = "image height",
     .help = "Image height in pixels", .field = member<&RenderSettings::height>},
    {.key = "mode", .keyword = "render_mode", .flag = "--mode", .kind = SettingKind::mode, .noun = "render mode",
     .help = "rt: ray tracing, direct light only; pm: photon mapping (global illumination); "
             "pm-direct: everything read from the photon maps; reference: path tracing, "
             "slow and unbiased, to check the others against, except that it cannot see light "
             "from point lights through mirrors or glass onto diffuse surfaces (renders it black) "
             "and finds sphere-light caustics by chance (noisy); sppm: stochastic progressive photon "
             "mapping, consistent for every light path (caustics of point lights too), the judge",
     .field = member<&RenderSettings::mode>,
     // As POV-Ray renders the file: global illumination where it asks for radiosity, caustics
     // where it asks for photons (pm without indirect light: the effects' default), else ray tracing.
     .program_default = [](const DefaultContext& c) -> std::optional<SettingValue> {
         return std::string(c.radiosity || c.povray_photons ? "pm" : "rt");
     },
     .program_default_note = "pm where the file has POV-Ray's radiosity or photons"},
    {.key = "max_ray_depth", .keyword = "max_trace_level", .povray = true, .flag = "--ray-depth", .lo = 1,
     .hi = SettingsLimits::max_ray_depth, .noun = "max ray depth",
     .help = "Longest camera path, primary ray = 1 (POV-Ray's max_trace_level)",
     .field = member<&RenderSettings::max_ray_depth>,
     .program_default = [](const DefaultContext&) -> std::optional<SettingValue> { return std::uint64_t(5); }},
    {.key = "adc_bailout", .keyword = "adc_bailout", .povray = true, .flag = "--adc-bailout",
     .kind = SettingKind::real, .hi = 1, .noun = "adc bailout",
     .help = "rt and pm: a mirror or glass ray whose weight in its pixel is below this is not traced "
             "(POV-Ray's adc_bailout; 0: every ray to the ray depth)",
     .field = member<&RenderSettings::adc_bailout>,
     .program_default = [](const DefaultContext&) -> std::optional<SettingValue> { return 1.0 / 255.0; }},
    {.key = "global_photons", .keyword = "global_photons", .flag = "--global-photons", .hi = 1e12,
     .noun = "global photons", .help = "Photons emitted for the global map",
     .field = member<&RenderSettings::global_photons>},
    {.key = "caustic_photons", .keyword = "caustic_photons", .flag = "--caustic-photons", .hi = 1e12,
     .noun = "caustic photons", .help = "Photons emitted towards mirrors and glass for the caustic map",
     .field = member<&RenderSettings::caustic_photons>},
    {.key = "global_estimate.k", .keyword = "count", .block = "global_estimate", .flag = "--global-k", .lo = 1,
     .hi = 1e6, .noun = "the photons per estimate (`count`)", .help = "Photons per global estimate",
     .field = estimate_member<&RenderSettings::global_estimate, &EstimateSettings::k>},
    {.key = "global_estimate.max_radius", .keyword = "radius", .block = "global_estimate", .flag = "--global-radius",
     .kind = SettingKind::real, .noun = "the estimate radius",
     .help = "Largest radius of a global estimate, scene units (0: twice the global map's median distance "
             "from a photon to its k-th nearest)",
     .field = estimate_member<&RenderSettings::global_estimate, &EstimateSettings::max_radius>},
    {.key = "global_estimate.flatten", .keyword = "flatten", .block = "global_estimate", .kind = SettingKind::real,
     .lo = 1, .noun = "`flatten`",
     .help = "Distance along the normal counts this many times in a global estimate (1: a sphere)",
     .field = estimate_member<&RenderSettings::global_estimate, &EstimateSettings::flatten>},
    {.key = "global_estimate.boundary_probes", .keyword = "probes", .block = "global_estimate", .hi = 1024,
     .noun = "`probes`", .help = "Rays that clip a global estimate's disc at walls (0: off)",
     .field = estimate_member<&RenderSettings::global_estimate, &EstimateSettings::boundary_probes>},
    {.key = "caustic_estimate.k", .keyword = "count", .block = "caustic_estimate", .flag = "--caustic-k", .lo = 1,
     .hi = 1e6, .noun = "the photons per estimate (`count`)", .help = "Photons per caustic estimate",
     .field = estimate_member<&RenderSettings::caustic_estimate, &EstimateSettings::k>},
    {.key = "caustic_estimate.max_radius", .keyword = "radius", .block = "caustic_estimate",
     .flag = "--caustic-radius", .kind = SettingKind::real, .noun = "the estimate radius",
     .help = "Largest radius of a caustic estimate, scene units (0: twice the distance within which 90% of "
             "the caustic map's photons find their k nearest)",
     .field = estimate_member<&RenderSettings::caustic_estimate, &EstimateSettings::max_radius>},
    {.key = "caustic_estimate.flatten", .keyword = "flatten", .block = "caustic_estimate", .kind = SettingKind::real,
     .lo = 1, .noun = "`flatten`",
     .help = "Distance along the normal counts this many times in a caustic estimate (1: a sphere)",
     .field = estimate_member<&RenderSettings::caustic_estimate, &EstimateSettings::flatten>},
    {.key = "caustic_estimate.boundary_probes", .keyword = "probes", .block = "caustic_estimate", .hi = 1024,
     .noun = "`probes`", .help = "Rays that clip a caustic estimate's disc at walls (0: off)",
     .field = estimate_member<&RenderSettings::caustic_estimate, &EstimateSettings::boundary_probes>},
    {.key = "max_photon_depth", .keyword = "max_photon_depth", .flag = "--photon-depth", .lo = 1,
     .hi = SettingsLimits::max_photon_depth, .noun = "max photon depth",
     .help = "Most bounces of a photon (a backstop: Russian roulette ends photon paths)",
     .field = member<&RenderSettings::max_photon_depth>},
    {.key = "final_gather_rays", .keyword = "final_gather", .flag = "--final-gather",
     .hi = SettingsLimits::max_samples, .noun = "final gather rays",
     .help = "Rays per final gather in pm mode (0: read the global map at the first diffuse hit)",
     .field = member<&RenderSettings::final_gather_rays>},
    {.key = "irradiance_cache_error", .keyword = "irradiance_cache", .flag = "--irradiance-cache",
     .kind = SettingKind::real, .hi = 1, .noun = "irradiance cache error",
     .help = "Error bound of the cache of final gathers (Ward's a; 0: gather at every sample)",
     .field = member<&RenderSettings::irradiance_cache_error>},
    {.key = "cache_gather_noise", .keyword = "cache_gather_noise", .flag = "--cache-gather-noise",
     .kind = SettingKind::real, .hi = 1, .noun = "cache gather noise",
     .help = "Relative noise an irradiance cache record's gather aims at: a noisier one gathers again where its "
             "cells vary, up to 4x the final gather rays in all (0.03, or 3% on the command line; 0: every record "
             "takes the final gather rays)",
     .units = "fraction", .field = member<&RenderSettings::cache_gather_noise>},
    {.key = "shadow_samples", .keyword = "shadow_samples", .flag = "--shadow-samples", .lo = 1,
     .hi = SettingsLimits::max_samples, .noun = "shadow samples",
     .help = "Shadow rays per area light and shading point (a file without it: its largest area_light N1 x N2)",
     .field = member<&RenderSettings::shadow_samples>,
     .program_default = [](const DefaultContext& c) -> std::optional<SettingValue> {
         if (c.area_light_grid > 1) return std::uint64_t(c.area_light_grid);  // POV-Ray's shadow rays per light
         return std::nullopt;
     },
     .program_default_note = "the file's largest area_light N1 x N2"},
    {.key = "samples_per_pixel", .keyword = "samples_per_pixel", .flag = "--spp", .lo = 1,
     .hi = SettingsLimits::max_samples, .noun = "samples per pixel",
     .help = "Samples every pixel takes (anti-aliasing by contrast adds more where pixels differ)",
     .field = member<&RenderSettings::samples_per_pixel>,
     // One sample where contrast decides the rest, as POV-Ray's +A. Under focal blur, rounds of
     // up to 9 while the pixel is noisy (aa_max_samples: blur_samples), as POV-Ray's blur stops
     // once its samples agree.
     .program_default = [](const DefaultContext& c) -> std::optional<SettingValue> {
         const std::uint64_t blur = std::min<std::uint64_t>(c.blur_samples, SettingsLimits::max_samples);
         if (traces_pixels(c.mode)) return blur > 0 ? std::min<std::uint64_t>(blur, 9) : 1;
         if (blur > RenderSettings{}.samples_per_pixel) return blur;
         return std::nullopt;
     },
     .program_default_note = "up to 9 where the camera has focal blur"},
    {.key = "aa_contrast", .keyword = "aa_contrast", .flag = "--aa-contrast", .kind = SettingKind::real,
     .noun = "aa contrast",
     .help = "rt, pm and pm-direct: anti-aliasing by contrast; a pixel whose colour differs from a neighbour's "
             "by at least this (POV-Ray's Antialias_Threshold, on values of gamma 2.5) takes rounds of aa samples "
             "more (0: off)",
     .field = member<&RenderSettings::aa_contrast>,
     .program_default = [](const DefaultContext& c) -> std::optional<SettingValue> {
         // POV-Ray's +A0.3; under focal blur every pixel is noisy: the noise decides (aa_threshold).
         if (traces_pixels(c.mode) && c.blur_samples == 0) return 0.3;
         return std::nullopt;
     },
     .program_default_note = "0 where the camera has focal blur"},
    {.key = "aa_samples", .keyword = "aa_samples", .flag = "--aa-samples", .lo = 1,
     .hi = SettingsLimits::max_samples, .noun = "aa samples",
     .help = "Samples per round of anti-aliasing by contrast (POV-Ray's Antialias_Depth 3: 3 x 3)",
     .field = member<&RenderSettings::aa_samples>},
    {.key = "aa_threshold", .keyword = "aa_threshold", .flag = "--aa-threshold", .kind = SettingKind::real,
     .noun = "aa threshold",
     .help = "rt, pm and pm-direct: adaptive anti-aliasing; a pixel takes more rounds of samples while the "
             "standard error of its mean luminance is above this fraction of the mean (0: off; with anti-aliasing "
             "by contrast, only the pixels it supersamples)",
     .field = member<&RenderSettings::aa_threshold>,
     .program_default = [](const DefaultContext& c) -> std::optional<SettingValue> {
         if (c.mode == RenderMode::rt || c.mode == RenderMode::pm) return 0.1;
         return std::nullopt;
     }},
    {.key = "aa_max_samples", .keyword = "aa_max_samples", .flag = "--aa-max-spp", .lo = 1,
     .hi = SettingsLimits::max_samples, .noun = "aa max samples",
     .help = "Most samples a pixel takes under adaptive anti-aliasing (whole rounds of the samples per pixel)",
     .field = member<&RenderSettings::aa_max_samples>,
     .program_default = [](const DefaultContext& c) -> std::optional<SettingValue> {
         // Focal blur's blur_samples: the most POV-Ray takes.
         if (traces_pixels(c.mode) && c.blur_samples > RenderSettings{}.aa_max_samples)
             return std::uint64_t(std::min<std::uint64_t>(c.blur_samples, SettingsLimits::max_samples));
         return std::nullopt;
     },
     .program_default_note = "the camera's blur_samples where more"},
    {.key = "irradiance_stride", .keyword = "irradiance_stride", .flag = "--irradiance-stride", .hi = 1e6,
     .noun = "irradiance stride",
     .help = "Final gather rays read irradiance precomputed at every N-th global photon "
             "(0: a full density estimate per gather ray)",
     .field = member<&RenderSettings::irradiance_stride>},
    {.key = "sppm_passes", .keyword = "sppm_passes", .flag = "--passes", .lo = 1,
     .hi = SettingsLimits::max_sppm_passes, .noun = "sppm passes",
     .help = "sppm: passes (one camera ray per pixel and a photon set each)",
     .field = member<&RenderSettings::sppm_passes>,
     .program_default = [](const DefaultContext& c) -> std::optional<SettingValue> {
         // A budget without a pass count of its own decides when sppm stops.
         if (c.mode == RenderMode::sppm && c.budget) return std::uint64_t(SettingsLimits::max_sppm_passes);
         return std::nullopt;
     },
     .program_default_note = "as many as the time limit or target error takes, where one is set"},
    {.key = "sppm_photons_per_pass", .keyword = "sppm_photons", .flag = "--photons-per-pass", .lo = 1,
     .hi = double(SettingsLimits::max_sppm_photons_per_pass), .noun = "sppm photons per pass",
     .help = "sppm: photons emitted per pass", .field = member<&RenderSettings::sppm_photons_per_pass>},
    {.key = "time_limit", .keyword = "time_limit", .flag = "--time", .kind = SettingKind::real, .noun = "time limit",
     .help = "sppm and reference: stop after the pass (sppm) or round of samples per pixel (reference) at which "
             "this many seconds have passed; pm: render again with twice the photons and gather rays while the "
             "next render fits (the command line also takes 90s, 2m, 1h; 0: no limit)",
     .units = "seconds", .field = member<&RenderSettings::time_limit>},
    {.key = "target_error", .keyword = "target_error", .flag = "--target-error", .kind = SettingKind::real,
     .noun = "target error",
     .help = "sppm, reference and pm: stop once the estimated relative RMSE of the image is at most this "
             "(0.01, or 1% on the command line; 0: no target)",
     .units = "fraction", .field = member<&RenderSettings::target_error>},
    {.key = "pm_error_passes", .keyword = "pm_error_passes", .flag = "--error-passes",
     .hi = SettingsLimits::max_sppm_passes, .noun = "pm error passes",
     .help = "pm: estimate the error against a short sppm run of at most this many passes, taking about a tenth "
             "of pm's own time (0: no estimate, as --no-error-estimate)",
     .field = member<&RenderSettings::pm_error_passes>,
     .program_default = [](const DefaultContext& c) -> std::optional<SettingValue> {
         // A number the user can trust or distrust, for about a tenth of pm's own time again.
         if (c.mode == RenderMode::pm) return std::uint64_t(64);
         return std::nullopt;
     }},
    {.key = "effects", .keyword = "effects", .flag = "--effects", .kind = SettingKind::text, .noun = "effects",
     .help = "Effects forced on or off against the light-path plan, e.g. caustics=off,indirect=on "
             "(caustics, indirect: on, off or auto; lights=on: photons also from lights the plan finds "
             "hidden); see docs/effects-plan.md",
     .field = member<&RenderSettings::effects>, .text_problem = &effect_switches_problem,
     // POV-Ray's photons without its radiosity: caustics, and the ambient term for indirect light.
     .program_default = [](const DefaultContext& c) -> std::optional<SettingValue> {
         if (c.mode == RenderMode::pm && !c.mode_written && c.povray_photons && !c.radiosity)
             return std::string("indirect=off");
         return std::nullopt;
     },
     .program_default_note = "indirect=off where the file has POV-Ray's photons but not its radiosity and chooses no "
                             "mode"},
    {.key = "seed", .keyword = "seed", .flag = "--seed", .hi = 1e12, .noun = "seed",
     .help = "Random seed; the same seed gives the same image", .field = member<&RenderSettings::seed>},
    {.key = "threads", .flag = "--threads", .hi = 65536, .noun = "threads",
     .help = "Worker threads (0: all cores); the image does not depend on it",
     .field = member<&RenderSettings::threads>},
};
// clang-format on
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic pop
#endif

[[nodiscard]] constexpr const RenderSetting* find_setting(std::string_view key) {
    for (const RenderSetting& s : render_settings_table)
        if (s.key == key) return &s;
    return nullptr;
}
/// The entry of global_settings item `keyword` in `block` ("" for the top level), or nullptr.
[[nodiscard]] constexpr const RenderSetting* find_setting_item(std::string_view block, std::string_view keyword) {
    for (const RenderSetting& s : render_settings_table)
        if (!s.keyword.empty() && s.block == block && s.keyword == keyword) return &s;
    return nullptr;
}
[[nodiscard]] constexpr bool is_settings_block(std::string_view word) {
    for (const RenderSetting& s : render_settings_table)
        if (!s.block.empty() && s.block == word) return true;
    return false;
}

namespace detail {
constexpr std::size_t count_photon_items() {
    std::size_t n = 0;
    for (std::size_t i = 0; i < std::size(render_settings_table); ++i) {
        const RenderSetting& s = render_settings_table[i];
        const std::string_view item = s.block.empty() ? s.keyword : s.block;
        if (item.empty() || s.povray) continue;
        bool seen = false;
        for (std::size_t j = 0; j < i; ++j) {
            const RenderSetting& e = render_settings_table[j];
            seen = seen || (e.block.empty() ? e.keyword : e.block) == item;
        }
        n += !seen;
    }
    return n;
}
}  // namespace detail

/// photon's own global_settings items (POV-Ray does not know them): keywords and blocks.
[[nodiscard]] constexpr std::array<std::string_view, detail::count_photon_items()> photon_setting_items() {
    std::array<std::string_view, detail::count_photon_items()> items{};
    std::size_t n = 0;
    for (const RenderSetting& s : render_settings_table) {
        const std::string_view item = s.block.empty() ? s.keyword : s.block;
        if (item.empty() || s.povray) continue;
        bool seen = false;
        for (std::size_t j = 0; j < n; ++j) seen = seen || items[j] == item;
        if (!seen) items[n++] = item;
    }
    return items;
}

/// A whole number as written (1000000, not 1e+06), so that a bound reads as it would be written.
[[nodiscard]] inline std::string format_whole(double x) {
    return x == std::floor(x) && std::abs(x) < 1e15 ? std::to_string(std::int64_t(x)) : format_number(x);
}

/// `v` as text: a whole number, a real that reads back exactly, or a name.
[[nodiscard]] inline std::string format_setting_value(const SettingValue& v) {
    if (const auto* i = std::get_if<std::uint64_t>(&v)) return std::to_string(*i);
    if (const auto* d = std::get_if<double>(&v)) return format_number(*d);
    return std::get<std::string>(v);
}

/// Why `v` is not a value of `s`, as the end of a sentence ("must be from 1 to 256, found 300"),
/// or nothing when it is one.
[[nodiscard]] inline std::optional<std::string> setting_value_problem(const RenderSetting& s, const SettingValue& v) {
    if (s.kind == SettingKind::mode) {
        const auto* name = std::get_if<std::string>(&v);
        if (name && find_render_mode(*name)) return std::nullopt;
        std::string names;
        for (const RenderModeName& m : render_mode_names) names += (names.empty() ? "" : ", ") + std::string(m.name);
        return "must be one of " + names + ", found " + (name ? *name : format_setting_value(v));
    }
    if (s.kind == SettingKind::text) {
        const auto* text = std::get_if<std::string>(&v);
        if (!text) return "must be a string, found " + format_setting_value(v);
        return s.text_problem ? s.text_problem(*text) : std::nullopt;
    }
    if (std::holds_alternative<std::string>(v)) return "must be a number, found " + std::get<std::string>(v);
    const double x = std::holds_alternative<double>(v) ? std::get<double>(v) : double(std::get<std::uint64_t>(v));
    const std::string found = ", found " + format_setting_value(v);
    if (s.kind == SettingKind::integer) {
        if (x != std::floor(x)) return "must be a whole number" + found;
        if (!(x >= s.lo && x <= s.hi)) return "must be from " + format_whole(s.lo) + " to " + format_whole(s.hi) + found;
        return std::nullopt;
    }
    const bool above = s.lo_exclusive ? x > s.lo : x >= s.lo;
    if (above && x <= s.hi) return std::nullopt;
    if (s.hi != unbounded) return "must be from " + format_number(s.lo) + " to " + format_number(s.hi) + found;
    if (s.lo_exclusive) return (s.lo == 0 ? std::string("must be positive") : "must be above " + format_number(s.lo)) + found;
    return "must be >= " + format_number(s.lo) + found;
}

/// `photon render`'s default of `s` as text, for --help and the docs: its value in each mode,
/// grouped ("0.3 in rt, pm and pm_direct, else 0"), and what else it depends on.
[[nodiscard]] inline std::string program_default_text(const RenderSetting& s) {
    const std::string library = format_setting_value(s.field.get(RenderSettings{}));
    if (!s.program_default) return library;
    std::vector<std::pair<std::string, std::string>> by_value;  // value, the modes that take it
    for (const RenderModeName& m : render_mode_names) {
        if (render_mode_name(m.mode) != m.name) continue;  // an alias
        DefaultContext c;
        c.mode = m.mode;
        const auto v = s.program_default(c);
        const std::string value = v ? format_setting_value(*v) : library;
        auto it = std::find_if(by_value.begin(), by_value.end(), [&](const auto& e) { return e.first == value; });
        if (it == by_value.end()) it = by_value.insert(by_value.end(), {value, ""});
        it->second.append(it->second.empty() ? "" : ", ").append(m.name);
    }
    std::string text;
    if (by_value.size() == 1) {
        text = by_value[0].first;
    } else {
        // The value most modes share last, as "else".
        std::stable_sort(by_value.begin(), by_value.end(), [](const auto& a, const auto& b) {
            return std::count(a.second.begin(), a.second.end(), ',') < std::count(b.second.begin(), b.second.end(), ',');
        });
        for (std::size_t i = 0; i + 1 < by_value.size(); ++i)
            text.append(i ? "; " : "").append(by_value[i].first + " in " + by_value[i].second);
        text.append(", else " + by_value.back().first);
    }
    if (!s.program_default_note.empty()) text.append(" (" + std::string(s.program_default_note) + ")");
    return text;
}

/// Applies `v` to `settings`; throws std::invalid_argument when `key` names no setting or `v` is out
/// of the setting's bounds: "`from`: NOUN must be ...", `from` being how the value was given (by
/// default the setting's option, else its key).
inline void apply_setting(std::string_view key, const SettingValue& v, RenderSettings& settings,
                          std::string_view from = {}) {
    const RenderSetting* s = find_setting(key);
    if (!s) throw std::invalid_argument("no render setting is called `" + std::string(key) + "`");
    if (from.empty()) from = s->flag.empty() ? s->key : s->flag;
    if (const auto problem = setting_value_problem(*s, v))
        throw std::invalid_argument(std::string(from) + ": " + std::string(s->noun) + " " + *problem);
    s->field.set(settings, v);
}

}  // namespace photon::dsl
