// SPDX-License-Identifier: MIT
#pragma once
// The render settings a scene file and the command line give, through the settings table.

#include <algorithm>
#include <functional>
#include <map>
#include <stdexcept>
#include <string>
#include <variant>

#include <photon/integrator/render_settings.hpp>

#include "../description.hpp"
#include "../settings_table.hpp"
#include "warnings.hpp"

namespace photon::dsl {

/// Settings given outside the scene file (the command line), by the settings table's key
/// ("samples_per_pixel", "global_estimate.k", settings_table.hpp); each one overrides the file.
using SettingsOverrides = std::map<std::string, SettingValue, std::less<>>;

/// Render settings: the library's defaults, then POV-Ray's photons block, then the file's items of
/// the settings table, then `overrides` (each one setting through the table). Throws dsl::Error if
/// a file's value is out of range, std::invalid_argument naming the option if an override is.
[[nodiscard]] inline RenderSettings render_settings(const SceneDescription& desc, const SettingsOverrides& o,
                                                    Warnings& warn) {
    RenderSettings s;
    const GlobalSettings& g = desc.settings;
    if (g.photons) {
        const PovPhotons& ph = *g.photons;
        if (ph.count)
            s.caustic_photons = std::size_t(*ph.count);
        else if (ph.spacing)
            warn(ph.at,
                 "photons `spacing` has no photon equivalent: photon shoots a number of photons (`count`, or "
                 "`caustic_photons` in photon's own settings)");
        if (ph.gather_max) s.caustic_estimate.k = *ph.gather_max;
        if (ph.radius) s.caustic_estimate.max_radius = float(*ph.radius);
        if (ph.max_trace_level) s.max_photon_depth = *ph.max_trace_level;
    }
    for (const auto& [key, written] : g.render) {
        try {  // checked where written already, unless the description was made by a program
            const RenderSetting* setting = find_setting(key);
            std::string keyword = "`";
            keyword.append(setting ? setting->keyword : key).push_back('`');
            apply_setting(key, written.value, s, keyword);
        } catch (const std::invalid_argument& e) {
            throw Error(written.at, e.what());
        }
    }
    if (!g.render.count("shadow_samples")) {
        // POV-Ray's area_light N1 x N2 grid is its number of shadow rays per light.
        unsigned most = 0;
        std::function<void(const Object&)> visit = [&](const Object& obj) {
            if (const auto* l = std::get_if<LightSource>(&obj.shape); l && l->area)
                most = std::max(most, unsigned(l->area->size1 * l->area->size2));
            if (const auto* u = std::get_if<UnionShape>(&obj.shape))
                for (const auto& c : u->children) visit(*c);
            if (const auto* csg = std::get_if<CsgShape>(&obj.shape))
                for (const auto& c : csg->children) visit(*c);
        };
        for (const Object& obj : desc.objects) visit(obj);
        if (most > 1) s.shadow_samples = most;
    }
    for (const auto& [key, value] : o) apply_setting(key, value, s);  // std::invalid_argument names the option
    try {
        validate(s);
    } catch (const std::invalid_argument& e) {
        throw Error(g.at.known() ? g.at : desc.at, e.what());
    }
    return s;
}

}  // namespace photon::dsl
