// SPDX-License-Identifier: MIT
// How every `photon` command reads its scene: the diagnostics it counts and prints, and the
// parse options made from -D, -I, the I/O restrictions, the limits and the animation flags
// (commands.hpp).

#include "commands.hpp"

#include <photon/dsl/object_geometry.hpp>
#include <photon/dsl/povray_conf.hpp>

#include <cstdint>
#include <exception>
#include <iostream>
#include <stdexcept>
#include <tuple>
#include <utility>
#include <variant>

namespace photon::cli {

dsl::DiagnosticSink SceneOptions::sink() {
    return [this](const dsl::Diagnostic& d) {
        if (d.severity != dsl::Severity::note) ++warnings;
        if (!d.kind.empty()) ++degraded[d.kind][d.keyword];
        if (!quiet || strict) std::cerr << format(d) << '\n';
    };
}

std::string SceneOptions::format(const dsl::Diagnostic& d) const {
    // A file the scene may not read is never read, so its lines are never there to quote: this
    // holds that true of every message, whatever reached it.
    const bool quote = d.location.file && file_access.permits(dsl::resolved_path(d.location.file->name), dsl::FileAccess::read);
    return dsl::format_diagnostic(d, quote);
}

dsl::ParseOptions SceneOptions::parse_options(const dsl::SettingsOverrides& overrides) {
    auto size = [&](const char* key, unsigned otherwise) {
        const auto it = overrides.find(key);
        if (it == overrides.end() || dsl::setting_value_problem(*dsl::find_setting(key), it->second))
            return otherwise;  // build() reports it
        return unsigned(std::get<std::uint64_t>(it->second));
    };
    dsl::ParseOptions o;
    o.diagnostics = sink();
    o.geometry = dsl::library_object_geometry();  // trace(), min_extent(), max_extent()
    o.image_width = size("width", 800);
    o.image_height = size("height", 600);
    for (const auto& dir : include_paths) o.include_paths.emplace_back(dir);
    for (auto& dir : dsl::standard_include_paths()) o.include_paths.push_back(std::move(dir));
    for (const auto& d : defines) {
        const auto eq = d.find('=');
        const std::string name = d.substr(0, eq);
        double value = 1;
        if (eq != std::string::npos) {
            try {
                std::size_t used = 0;
                value = std::stod(d.substr(eq + 1), &used);
                if (used != d.size() - eq - 1) throw std::invalid_argument("trailing characters");
            } catch (const std::exception&) {
                throw std::invalid_argument("--define " + d + ": expected NAME=NUMBER");
            }
        }
        if (name.empty()) throw std::invalid_argument("--define " + d + ": expected NAME=NUMBER");
        o.defines[name] = value;
    }
    o.animation = animation_clock();
    o.max_parse_seconds = max_parse_seconds;
    dsl::FileAccessRules& rules = o.file_access;
    rules.how_to_permit = "permit it with --permit-path DIR (reading), a `read* = DIR` or `read+write* = DIR` line "
                          "in a povray.conf given with --io-config, or --io-restrictions read-only or none";
    if (!io_config.empty()) dsl::apply_povray_conf_file(rules, io_config);
    if (!io_restrictions.empty()) {
        rules.level = *dsl::io_restrictions_named(io_restrictions);  // CLI11 checked the name
        rules.level_origin = "--io-restrictions";
    }
    for (const auto& dir : permitted_paths) rules.permit(dir, true, false, "--permit-path " + dir);
    file_access = dsl::scene_file_access(o, scene);
    return o;
}

dsl::AnimationClock SceneOptions::animation_clock() {
    const auto pair = [](const std::string& text, const char* option) {
        const auto colon = text.find(':');
        try {
            std::size_t a = 0, b = 0;
            const double first = std::stod(text.substr(0, colon), &a);
            const std::string rest = colon == std::string::npos ? "" : text.substr(colon + 1);
            const double second = std::stod(rest, &b);
            if (a != colon || b != rest.size()) throw std::invalid_argument("trailing characters");
            return std::pair{first, second};
        } catch (const std::exception&) {
            throw std::invalid_argument(std::string(option) + " " + text + ": expected two numbers A:B");
        }
    };
    dsl::AnimationRequest r = animation;
    if (!frames.empty()) std::tie(r.initial_frame, r.final_frame) = pair(frames, "--frames");
    if (!clock_range.empty()) std::tie(r.initial_clock, r.final_clock) = pair(clock_range, "--clock-range");
    return dsl::animation_clock(r);
}

bool SceneOptions::failed_strict() const {
    if (!strict || warnings == 0) return false;
    std::cerr << "photon: " << warnings << " warning" << (warnings == 1 ? "" : "s") << " (--strict)\n";
    return true;
}

}  // namespace photon::cli
