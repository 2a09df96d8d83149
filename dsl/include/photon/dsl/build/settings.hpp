// SPDX-License-Identifier: MIT
#pragma once
// The render settings of a render: the library's defaults, the scene file, the command line and
// `photon render`'s own defaults, resolved once through the settings table.

#include <algorithm>
#include <functional>
#include <map>
#include <set>
#include <stdexcept>
#include <string>
#include <variant>

#include <photon/settings/render_settings.hpp>

#include "../description.hpp"
#include "../settings_table.hpp"
#include "warnings.hpp"

namespace photon::dsl {

/// Settings given outside the scene file (the command line), by the settings table's key
/// ("samples_per_pixel", "global_estimate.k", settings_table.hpp); each one overrides the file.
using SettingsOverrides = std::map<std::string, SettingValue, std::less<>>;

/// What `photon render`'s defaults depend on in the file (DefaultContext, without the mode).
[[nodiscard]] inline DefaultContext scene_default_context(const SceneDescription& desc) {
    DefaultContext c;
    c.radiosity = desc.settings.radiosity;
    c.povray_photons = desc.settings.photons.has_value();
    std::function<void(const Object&)> visit = [&](const Object& obj) {
        if (const auto* l = std::get_if<LightSource>(&obj.shape); l && l->area)
            c.area_light_grid = std::max(c.area_light_grid, unsigned(l->area->size1 * l->area->size2));
        if (const auto* u = std::get_if<UnionShape>(&obj.shape))
            for (const auto& child : u->children) visit(*child);
        if (const auto* csg = std::get_if<CsgShape>(&obj.shape))
            for (const auto& child : csg->children) visit(*child);
    };
    for (const Object& obj : desc.objects) visit(obj);
    if (const auto& cam = desc.camera; cam && cam->aperture && *cam->aperture != 0.0 && cam->blur_samples)
        c.blur_samples = *cam->blur_samples;  // POV-Ray's rule for focal blur (build/camera.hpp)
    return c;
}

/// The render settings of a render of `desc`, resolved once for `render`, `check` and the tools:
/// the library's defaults, then POV-Ray's photons block, then the file's items of the settings
/// table, then `overrides` (the command line; each one setting through the table), and last, for
/// every setting neither the file nor `overrides` wrote, `photon render`'s default
/// (RenderSetting::program_default), the mode's first. `program_defaults` false keeps the
/// library's defaults instead (a program that wants the library's behaviour). Throws dsl::Error if
/// a file's value is out of range, std::invalid_argument naming the option if an override is.
[[nodiscard]] inline RenderSettings render_settings(const SceneDescription& desc, const SettingsOverrides& o,
                                                    Warnings& warn, bool program_defaults = true) {
    RenderSettings s;
    const GlobalSettings& g = desc.settings;
    std::set<std::string, std::less<>> written;
    if (g.photons) {
        const PovPhotons& ph = *g.photons;
        auto set = [&](std::string_view key, auto apply) {
            apply();
            written.emplace(key);
        };
        if (ph.count)
            set("caustic_photons", [&] { s.caustic_photons = std::size_t(*ph.count); });
        else if (ph.spacing)
            warn(ph.at,
                 "photons `spacing` has no photon equivalent: photon shoots a number of photons (`count`, or "
                 "`caustic_photons` in photon's own settings)");
        if (ph.gather_max) set("caustic_estimate.k", [&] { s.caustic_estimate.k = *ph.gather_max; });
        if (ph.radius) set("caustic_estimate.max_radius", [&] { s.caustic_estimate.max_radius = float(*ph.radius); });
        if (ph.max_trace_level) set("max_photon_depth", [&] { s.max_photon_depth = *ph.max_trace_level; });
    }
    for (const auto& [key, setting] : g.render) {
        try {  // checked where written already, unless the description was made by a program
            const RenderSetting* row = find_setting(key);
            std::string keyword = "`";
            keyword.append(row ? row->keyword : key).push_back('`');
            apply_setting(key, setting.value, s, keyword);
            written.insert(key);
        } catch (const std::invalid_argument& e) {
            throw Error(setting.at, e.what());
        }
    }
    for (const auto& [key, value] : o) {
        apply_setting(key, value, s);  // std::invalid_argument names the option
        written.insert(key);
    }
    if (program_defaults) {
        DefaultContext c = scene_default_context(desc);
        c.mode_written = written.count("mode") > 0;
        const RenderSetting& mode_row = *find_setting("mode");
        if (!c.mode_written)
            if (const auto v = mode_row.program_default(c)) mode_row.field.set(s, *v);
        c.mode = s.mode;
        c.budget = s.time_limit > 0 || s.target_error > 0;
        for (const RenderSetting& row : render_settings_table)
            if (&row != &mode_row && row.program_default && !written.count(row.key))
                if (const auto v = row.program_default(c)) row.field.set(s, *v);
    }
    try {
        validate(s);
    } catch (const std::invalid_argument& e) {
        throw Error(g.at.known() ? g.at : desc.at, e.what());
    }
    return s;
}

}  // namespace photon::dsl
