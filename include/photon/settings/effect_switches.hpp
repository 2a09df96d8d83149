// SPDX-License-Identifier: MIT
#pragma once
// Forcing the light-path plan (plan/effects_plan.hpp): each effect the plan decides can be left to it
// (auto), forced on (the pass runs even where the plan finds nothing for it) or forced off. A
// scene file's `effects "caustics=off,indirect=on"` and `photon render --effects` both read
// this text, so they share one spelling and one set of messages.

#include <array>
#include <cstdint>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>

namespace photon {

enum class EffectSwitch : std::uint8_t { automatic, on, off };

/// What the user forces. `lights = on` makes every light with power emit photons, also one the
/// plan finds hidden from the camera (forcing lights off would be forcing every map off).
struct EffectSwitches {
    EffectSwitch caustics = EffectSwitch::automatic;  ///< the caustic pass and the caustic maps (L S+ D E)
    EffectSwitch indirect = EffectSwitch::automatic;  ///< the global pass, precomputation, cache, final gather
    EffectSwitch lights = EffectSwitch::automatic;    ///< photons from lights the plan finds hidden

    friend bool operator==(const EffectSwitches&, const EffectSwitches&) = default;
};

namespace detail {
struct EffectName {
    std::string_view name;
    EffectSwitch EffectSwitches::*member;
    bool can_be_off;
};
inline constexpr std::array<EffectName, 3> effect_names{{{"caustics", &EffectSwitches::caustics, true},
                                                         {"indirect", &EffectSwitches::indirect, true},
                                                         {"lights", &EffectSwitches::lights, false}}};
[[nodiscard]] inline std::string_view switch_name(EffectSwitch s) noexcept {
    return s == EffectSwitch::on ? "on" : s == EffectSwitch::off ? "off" : "auto";
}
}  // namespace detail

/// Why `text` is not a list of EFFECT=on|off|auto separated by commas (EFFECT: caustics,
/// indirect, lights; lights only on or auto), as the end of a sentence, or nothing when it is
/// one. The empty text leaves everything to the plan.
[[nodiscard]] inline std::optional<std::string> effect_switches_problem(std::string_view text) {
    const auto not_a_list = [&] {
        return "must be EFFECT=on|off|auto items separated by commas, EFFECT one of caustics, indirect, lights; found `" +
               std::string(text) + "`";
    };
    if (!text.empty() && text.back() == ',') return not_a_list();
    std::size_t at = 0;
    while (at < text.size()) {
        const std::size_t comma = std::min(text.find(',', at), text.size());
        const std::string_view item = text.substr(at, comma - at);
        const std::size_t eq = item.find('=');
        const std::string_view name = item.substr(0, eq), value = eq == item.npos ? "" : item.substr(eq + 1);
        const detail::EffectName* effect = nullptr;
        for (const auto& e : detail::effect_names)
            if (e.name == name) effect = &e;
        if (!effect) return not_a_list();
        if (value != "on" && value != "auto" && (value != "off" || !effect->can_be_off))
            return std::string(effect->can_be_off ? "must be on, off or auto for " : "must be on or auto for ") +
                   std::string(name) + ", found `" + std::string(item) + "`";
        at = comma + 1;
    }
    return std::nullopt;
}

/// The switches `text` sets (later items win); throws std::invalid_argument with
/// effect_switches_problem()'s words.
[[nodiscard]] inline EffectSwitches parse_effect_switches(std::string_view text) {
    if (const auto problem = effect_switches_problem(text)) throw std::invalid_argument("effects " + *problem);
    EffectSwitches s;
    std::size_t at = 0;
    while (at < text.size()) {
        const std::size_t comma = std::min(text.find(',', at), text.size());
        const std::string_view item = text.substr(at, comma - at);
        const std::size_t eq = item.find('=');
        const std::string_view value = item.substr(eq + 1);
        for (const auto& e : detail::effect_names)
            if (e.name == item.substr(0, eq))
                s.*e.member = value == "on" ? EffectSwitch::on : value == "off" ? EffectSwitch::off : EffectSwitch::automatic;
        at = comma + 1;
    }
    return s;
}

/// The text parse_effect_switches() reads back as `s`: the forced effects only ("" when none).
[[nodiscard]] inline std::string to_string(const EffectSwitches& s) {
    std::string text;
    for (const auto& e : detail::effect_names)
        if (s.*e.member != EffectSwitch::automatic)
            text.append(text.empty() ? "" : ",").append(e.name).append("=").append(detail::switch_name(s.*e.member));
    return text;
}

}  // namespace photon
