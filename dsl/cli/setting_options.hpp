// SPDX-License-Identifier: MIT
#pragma once
// The `photon render` options of the render settings, one per entry of the settings table
// (photon/dsl/settings_table.hpp) that has a flag. CLI11 reads each value as its kind (a whole
// number, a real, a mode name); the bounds are checked when the overrides are applied
// (dsl::apply_setting), which names the option: "--spp: samples per pixel must be from 1 to
// 1000000, found 0".

#include <CLI/CLI.hpp>

#include <photon/dsl/build.hpp>
#include <photon/dsl/settings_table.hpp>

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace photon::cli {

class SettingOptions {
public:
    /// Adds one option per setting with a flag to `cmd`. This object must outlive the parse.
    void add_to(CLI::App& cmd) {
        for (std::size_t i = 0; i < std::size(dsl::render_settings_table); ++i) {
            const dsl::RenderSetting& s = dsl::render_settings_table[i];
            if (s.flag.empty()) continue;
            const std::string flag(s.flag), help(s.help);
            CLI::Option* option = nullptr;
            if (s.kind == dsl::SettingKind::integer) {
                // CLI11 would read -1 as 2^64 - 1: a sign is a usage error, as for an unsigned option.
                option = cmd.add_option(flag, integers_[i], help)->check(CLI::NonNegativeNumber);
            } else if (s.kind == dsl::SettingKind::real) {
                option = cmd.add_option(flag, reals_[i], help);
            } else {
                std::vector<std::string> names;
                for (const dsl::RenderModeName& m : dsl::render_mode_names) names.emplace_back(m.name);
                option = cmd.add_option(flag, names_[i], help)->check(CLI::IsMember(names));
            }
            // The library's default, which a scene file's setting replaces.
            option->default_str(dsl::format_setting_value(s.field.get(RenderSettings{})));
        }
    }

    /// The settings given on the command line, by the table's key.
    [[nodiscard]] dsl::SettingsOverrides overrides() const {
        dsl::SettingsOverrides o;
        for (std::size_t i = 0; i < std::size(dsl::render_settings_table); ++i) {
            const std::string key(dsl::render_settings_table[i].key);
            if (integers_[i]) o[key] = *integers_[i];
            if (reals_[i]) o[key] = *reals_[i];
            if (names_[i]) o[key] = *names_[i];
        }
        return o;
    }

private:
    static constexpr std::size_t n = std::size(dsl::render_settings_table);
    std::array<std::optional<std::uint64_t>, n> integers_{};
    std::array<std::optional<double>, n> reals_{};
    std::array<std::optional<std::string>, n> names_{};
};

}  // namespace photon::cli
