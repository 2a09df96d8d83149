// SPDX-License-Identifier: MIT
#pragma once
// `normal { ... }`: POV-Ray's bump patterns, which photon renders as a tilted shading normal
// (texture/normal_pattern.hpp). bumps, dents, ripples, waves and wrinkles, and the slope of any
// pattern photon evaluates as a pigment; any other normal is ignored, said in a warning.

#include <optional>
#include <string>

#include "degradation.hpp"
#include "parser_class.hpp"
#include "patterns.hpp"
#include "pigment_pattern.hpp"

namespace photon::dsl::detail {

// NORMAL: normal { [NORMAL_IDENT] [PATTERN [[,] AMOUNT]] {PATTERN_MODIFIER | bump_size FLOAT
//         | accuracy FLOAT | no_bump_scale | TRANSFORMATION} }
//   PATTERN: bumps | dents | ripples | waves | wrinkles | an evaluated pattern (gradient VECTOR [,])
//          | bump_map { ... } (images.hpp)
inline Normal Parser::parse_normal(const Token& kw, Normal n) {
    const Nest nest(*this, kw.location);
    open_block(kw);
    n.at = kw.location;
    take_identifier(n, "a normal identifier or a normal pattern");
    PatternState st;
    if (n.pattern) st.base = *n.pattern;
    std::optional<Token> stray;  ///< the first token photon could not read
    for (;;) {
        const Token t = peek();
        if (t.is_symbol("}")) break;
        if (try_transform(n.transform)) continue;
        if (t.is_symbol(",")) {  // POV-Ray's optional comma before the bump size
            next();
            continue;
        }
        if (t.kind != TokenKind::identifier) {
            if (!starts_expression(t)) break;
            n.amount = parse_float("the bump size");  // after a pattern photon reads for its syntax
            continue;
        }
        if (one_of(t.text, normal_patterns) || one_of(t.text, evaluated_patterns)) {
            st.pattern = next();
            if (t.text == "gradient" && starts_expression(peek())) {
                const Numeric g = parse_expression_for("the direction of `gradient`");
                st.gradient = g.is_float() ? Vector3(g.at(0)) : Vector3(g.at(0), g.at(1), g.at(2));
                if (!accept_symbol(",")) continue;
            }
            if (t.text == "mandel") st.iterations = int(parse_integer("mandel's iteration count", 1, 1e7));
            if (t.text == "spiral1" || t.text == "spiral2") {
                st.arms = parse_spiral_arms(t.text);
                if (!accept_symbol(",")) continue;
            }
            if (starts_expression(peek())) n.amount = parse_float("the bump size after `" + t.text + "`");
        } else if (t.is_identifier("bump_map")) {
            st.pattern = next();
            st.image = parse_bump_map_block(t, n.amount);
        } else if (t.is_identifier("bump_size")) {
            next();
            n.amount = parse_float("the bump size after `bump_size`");
        } else if (t.is_identifier("accuracy")) {
            next();
            SourceLocation at;
            n.accuracy = parse_float("the accuracy after `accuracy`", &at);
            if (!(n.accuracy > 0)) fail(at, "accuracy must be positive, found " + format_number(n.accuracy));
        } else if (t.is_identifier("no_bump_scale")) {
            next();
            degrade(t.location, degraded::approximated_texture, t.text,
                    "`no_bump_scale` is ignored: photon's bumps keep their steepness when the normal is scaled");
        } else if (parse_pattern_item(st)) {
            continue;
        } else if (starts_expression(t)) {  // a declared float: the bump size
            n.amount = parse_float("the bump size");
        } else {
            // Syntax photon does not know here (bump_map, facets' coords, ...): the rest of the
            // block is read as balanced tokens, and the normal is ignored.
            stray = t;
            for (int depth = 0;;) {
                const Token& u = peek();
                if (u.kind == TokenKind::end_of_file) fail_expected("`}` to close `normal`", u);
                if (depth == 0 && u.is_symbol("}")) break;
                if (u.is_symbol("{") || u.is_symbol("[")) ++depth;
                if (u.is_symbol("}") || u.is_symbol("]")) --depth;
                next();
            }
            break;
        }
    }
    close_block(kw, "a normal pattern or modifier", {"bumps", "dents", "ripples", "waves", "wrinkles", "bump_size"});
    const std::string& name = st.pattern.text;
    if (name.empty() && !stray && !modifies_pattern(st)) return n;  // the identifier's, or bump_size alone
    std::string why_not;
    const std::string shown = !name.empty() ? name : stray ? stray->text : "";
    if (!name.empty() && name != "bump_map" && !one_of(name, normal_patterns) && !one_of(name, evaluated_patterns)) {
        why_not = "photon does not evaluate this pattern (it tilts normals by bumps, dents, ripples, waves, wrinkles, quilted "
                  "and the slope of the patterns it evaluates)";
    } else if (stray) {
        why_not = "photon does not read `" + stray->text + "` (at " + position(stray->location) + ")";
    } else if (!st.unsupported.empty()) {
        why_not = "photon does not evaluate `" + st.unsupported.front().text + "` (at " +
                  position(st.unsupported.front().location) + ")";
    } else if (st.map) {
        why_not = "photon does not evaluate a normal's `" + st.map->keyword + "`";
    }
    const SourceLocation at = !name.empty() ? st.pattern.location : stray ? stray->location : kw.location;
    if (!why_not.empty()) {
        degrade(at, degraded::ignored_effect, "normal",
                "`normal" + (shown.empty() ? std::string() : " { " + shown + " }") + "` is ignored: " + why_not);
        n.pattern = nullptr;
        return n;
    }
    if (name == "bump_map") {  // the image's heights, placed as the normal's other patterns are
        if (st.turbulence || !st.wave.empty()) {
            degrade(at, degraded::ignored_effect, "normal",
                    "`normal { bump_map }` is ignored: photon does not warp a bump map by turbulence or a wave");
            n.pattern = nullptr;
            return n;
        }
        PigmentPattern p;
        p.name = name;
        p.image = st.image;
        n.pattern = std::make_shared<const PigmentPattern>(std::move(p));
        return n;
    }
    PigmentPattern p = st.base && (name.empty() || st.base->name == name) ? *st.base : PigmentPattern{};
    if (!name.empty()) p.name = name;
    if (p.name.empty()) return n;
    apply_pattern_modifiers(st, p);
    if (p.noise_generator < 0 || p.noise_generator > 3)
        fail(at, "`noise_generator " + std::to_string(p.noise_generator) + "` is not 1, 2 or 3");
    n.pattern = std::make_shared<const PigmentPattern>(std::move(p));
    return n;
}

}  // namespace photon::dsl::detail
