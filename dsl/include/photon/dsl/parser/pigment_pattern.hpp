// SPDX-License-Identifier: MIT
#pragma once
// A pigment's pattern as photon evaluates it: the pattern keyword, its modifiers and its colours
// gathered from a PatternState, with POV-Ray's defaults, or the reason photon cannot evaluate it.

#include <algorithm>
#include <memory>
#include <string>

#include "parser_class.hpp"
#include "patterns.hpp"

namespace photon::dsl::detail {

/// The pattern in `st` as photon evaluates it, or null with `why_not` saying what it cannot
/// evaluate (the pattern, a modifier, a map of patterned pigments).
inline std::shared_ptr<const PigmentPattern> Parser::evaluated_pattern(const PatternState& st,
                                                                      std::string& why_not) const {
    const std::string& name = st.pattern.text;
    if (name == "image_map" && st.image) {
        if (!st.unsupported.empty()) {
            why_not = "photon does not evaluate `" + st.unsupported.front().text + "` (at " +
                      position(st.unsupported.front().location) + ")";
            return nullptr;
        }
        if (st.turbulence || st.map) {
            why_not = st.turbulence ? "photon does not warp an image map by `turbulence`" : "an image map takes no colour map";
            return nullptr;
        }
        PigmentPattern p;
        p.name = name;
        p.image = st.image;
        // Mid grey with the image's `filter all` and `transmit all`: the one colour that stands
        // for the image where photon needs one (the average pigment, its transmission).
        p.colors = {{0.0, Color{Vector3(0.5), st.image->filter_all, st.image->transmit_all}}};
        return std::make_shared<const PigmentPattern>(std::move(p));
    }
    if (name.empty() || !one_of(name, evaluated_patterns)) {
        why_not = "photon does not evaluate this pattern";
        return nullptr;
    }
    if (!st.unsupported.empty()) {
        why_not = "photon does not evaluate `" + st.unsupported.front().text + "` (at " +
                  position(st.unsupported.front().location) + ")";
        return nullptr;
    }
    if (st.map && st.map->keyword != "color_map" && st.map->keyword != "pigment_map") {
        why_not = "a `" + st.map->keyword + "` is not a pigment's colours";
        return nullptr;
    }
    // A pigment_map's patterned entries nest (build/layers.hpp); checker's or hexagon's listed
    // pigments do not yet.
    if ((st.map && st.map->reduced && st.map->keyword != "pigment_map") || st.reduced) {
        why_not = "its entries are patterned pigments, which photon does not nest";
        return nullptr;
    }
    if (st.map && st.map->entries.empty()) {
        why_not = "its `" + st.map->keyword + "` has no entries";
        return nullptr;
    }
    PigmentPattern p = st.base && st.base->name == name ? *st.base : PigmentPattern{};
    p.name = name;
    if (name == "checker" || name == "hexagon") {
        // The listed colours, spread over [0, 1] where the pattern's values pick them.
        if (!st.listed.empty() || !st.base) {
            std::vector<Color> colors = default_listed_colors(name);
            for (std::size_t i = 0; i < st.listed.size() && i < colors.size(); ++i) colors[i] = st.listed[i];
            p.colors.clear();
            p.nested.clear();
            for (std::size_t i = 0; i < colors.size(); ++i) p.colors.push_back({double(i) / double(colors.size() - 1), colors[i]});
        }
    } else if (st.map) {
        p.colors = st.map->entries;
        p.nested = st.map->reduced ? st.map->pigments : std::vector<std::shared_ptr<const Pigment>>{};
    } else if (!st.base || st.base->name != name) {
        p.colors = default_color_map(name);
    }
    apply_pattern_modifiers(st, p);
    if (p.noise_generator < 0 || p.noise_generator > 3) {
        why_not = "`noise_generator " + std::to_string(p.noise_generator) + "` is not 1, 2 or 3";
        return nullptr;
    }
    return std::make_shared<const PigmentPattern>(std::move(p));
}

/// The modifiers written in `st` (gradient, turbulence, octaves, ..., the wave) onto `p`.
inline void Parser::apply_pattern_modifiers(const PatternState& st, PigmentPattern& p) {
    if (p.name == "quilted" && !(st.base && st.base->name == "quilted")) p.frequency = 0;  // POV-Ray's default for it
    if (st.gradient) p.gradient = *st.gradient;
    if (st.turbulence) p.turbulence = *st.turbulence;
    if (st.octaves) p.octaves = *st.octaves;
    if (st.noise_generator) p.noise_generator = *st.noise_generator;
    if (st.omega) p.omega = *st.omega;
    if (st.lambda) p.lambda = *st.lambda;
    if (st.frequency) p.frequency = *st.frequency;
    if (st.phase) p.phase = *st.phase;
    if (st.agate_turb) p.agate_turb = *st.agate_turb;
    if (st.exponent) p.exponent = *st.exponent;
    if (!st.wave.empty()) p.wave = st.wave;
    if (st.form) p.crackle_form = *st.form;
    if (st.metric) p.crackle_metric = *st.metric;
    if (st.offset) p.crackle_offset = *st.offset;
    if (st.solid) p.crackle_solid = true;
    if (st.iterations) p.fractal_iterations = *st.iterations;
    if (st.arms) p.spiral_arms = *st.arms;
    if (st.control0) p.quilt_control0 = *st.control0;
    if (st.control1) p.quilt_control1 = *st.control1;
    if (st.interior) std::tie(p.interior_type, p.interior_factor) = *st.interior;
    if (st.exterior) std::tie(p.exterior_type, p.exterior_factor) = *st.exterior;
    p.octaves = std::clamp(p.octaves, 1, 10);  // as POV-Ray's parser clamps it
}

/// Whether the body wrote any pattern modifier or map (to a declared pigment's pattern).
inline bool Parser::modifies_pattern(const PatternState& st) {
    return st.map || st.gradient || st.turbulence || st.octaves || st.noise_generator || st.omega || st.lambda ||
           st.frequency || st.phase || st.agate_turb || st.exponent || !st.wave.empty() || !st.unsupported.empty() ||
           st.form || st.metric || st.offset || st.solid || st.iterations || st.interior || st.exterior ||
           st.arms || st.control0 || st.control1;
}

/// The colour a pattern averages to: checker's two colours' mean, a map's average over [0, 1].
inline Color average_color(const PigmentPattern& p) {
    if (p.name == "checker") return mix(p.colors[0].second, p.colors[1].second, 0.5);
    return blend_average(p.colors);
}

}  // namespace photon::dsl::detail
