// SPDX-License-Identifier: MIT
#pragma once
// The `photon render` options of the render settings, one per entry of the settings table
// (photon/dsl/settings_table.hpp) that has a flag. CLI11 reads each value as its kind (a whole
// number, a real, a mode name: a usage error otherwise); the bounds are checked when the overrides are applied
// (dsl::apply_setting), which names the option: "--spp: samples per pixel must be from 1 to
// 1000000, found 0".

#include <CLI/CLI.hpp>

#include <photon/dsl/build/settings.hpp>
#include <photon/dsl/settings_table.hpp>

#include <array>
#include <cstdint>
#include <cstdlib>
#include <map>
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
                option = cmd.add_option(flag, integers_[i], help);
            } else if (s.kind == dsl::SettingKind::real) {
                option = cmd.add_option(flag, reals_[i], help);
                if (s.units == "seconds")
                    option->transform(CLI::AsNumberWithUnit(std::map<std::string, double>{{"s", 1}, {"m", 60}, {"h", 3600}}));
                else if (s.units == "fraction")
                    option->transform(CLI::Validator(percent_as_fraction, "NUMBER[%]"));
            } else if (s.kind == dsl::SettingKind::text) {
                option = cmd.add_option(flag, names_[i], help);
            } else {
                std::vector<std::string> names;
                for (const dsl::RenderModeName& m : dsl::render_mode_names) names.emplace_back(m.name);
                option = cmd.add_option(flag, names_[i], help)->check(CLI::IsMember(names));
            }
            // photon render's default, which a scene file's setting replaces.
            option->default_str(dsl::program_default_text(s));
        }
    }

    /// The settings given on the command line, by the table's key.
    [[nodiscard]] dsl::SettingsOverrides overrides() const {
        dsl::SettingsOverrides o;
        for (std::size_t i = 0; i < std::size(dsl::render_settings_table); ++i) {
            const std::string key(dsl::render_settings_table[i].key);
            // Read signed (an unsigned option would take -1 as 2^64 - 1), so that a negative value is
            // reported with the setting's bounds.
            if (integers_[i]) o[key] = *integers_[i] >= 0 ? dsl::SettingValue(std::uint64_t(*integers_[i]))
                                                          : dsl::SettingValue(double(*integers_[i]));
            if (reals_[i]) o[key] = *reals_[i];
            if (names_[i]) o[key] = *names_[i];
        }
        return o;
    }

private:
    /// "1%" read as 0.01; a number without the sign as it is (CLI11 then reads it).
    static std::string percent_as_fraction(std::string& value) {
        if (value.empty() || value.back() != '%') return {};
        const std::string number = value.substr(0, value.size() - 1);
        char* end = nullptr;
        const double x = std::strtod(number.c_str(), &end);
        if (number.empty() || end != number.c_str() + number.size()) return "not a percentage: " + value;
        value = std::to_string(x / 100);
        return {};
    }

    static constexpr std::size_t n = std::size(dsl::render_settings_table);
    std::array<std::optional<std::int64_t>, n> integers_{};
    std::array<std::optional<double>, n> reals_{};
    std::array<std::optional<std::string>, n> names_{};
};

}  // namespace photon::cli
