// SPDX-License-Identifier: MIT
#pragma once
// Patterns with their blend maps (color_map, pigment_map, texture_map, ...) and modifiers. A
// pigment pattern photon evaluates (evaluated_patterns) keeps its modifiers for the build
// (pigment_pattern.hpp); any other patterned pigment or texture becomes one colour: the pattern's
// average as POV-Ray would colour it (a listed pattern's mean colour, a map's average over [0, 1]
// as POV-Ray interpolates it), said in a warning. A patterned pigment records its average too.

#include <cstdio>

#include "degradation.hpp"
#include "parser_class.hpp"

namespace photon::dsl::detail {

/// Patterns whose colours (pigments, textures) are listed after the keyword.
inline constexpr std::string_view listed_patterns[] = {"checker", "hexagon",    "brick",
                                                       "cubic",   "triangular", "square"};
/// Patterns whose value in [0, 1] picks a colour from a map; `object` and `average` are read apart.
inline constexpr std::string_view mapped_patterns[] = {
    "gradient",  "bozo",    "spotted",   "granite",     "marble",  "wood",    "agate",  "leopard",
    "onion",     "radial",  "ripples",   "waves",       "wrinkles", "bumps",  "dents",  "crackle",
    "cells",     "planar",  "spherical", "cylindrical", "boxed",   "spiral1", "spiral2", "quilted",
    "julia",     "mandel",  "magnet",    "pavement",    "tiling",  "aoi",     "slope",  "function",
    "facets",    "pigment_pattern", "image_pattern", "density_file"};
/// Pattern and wave modifiers followed by one number or vector.
inline constexpr std::string_view valued_modifiers[] = {
    "turbulence", "octaves", "omega",  "lambda", "frequency", "phase",  "mortar",          "brick_size",
    "agate_turb", "metric",  "offset", "form",   "control0",  "control1", "number_of_sides", "number_of_tiles",
    "exponent",   "orientation", "dist_exp", "noise_generator"};
/// Pattern and wave modifiers without a value.
inline constexpr std::string_view bare_modifiers[] = {"ramp_wave",  "triangle_wave", "sine_wave", "scallop_wave",
                                                      "cubic_wave", "solid",         "uv_mapping", "planar_mapping"};

struct Parser::PatternState {
    Token pattern;                  ///< the pattern keyword; empty text when none was written
    std::vector<Color> listed;      ///< colours listed after checker, hexagon, brick, object ...
    std::optional<Finish> finish;   ///< the first listed texture's finish (texture patterns)
    std::optional<BlendMap> map;
    Vector3 brick_size{8, 3, 4.5};  ///< POV-Ray's defaults
    double mortar = 0.5;
    // What an evaluated pattern needs, as written (unset: the pattern's or the declared pigment's).
    std::optional<PigmentPattern> base;  ///< a declared pigment's pattern this body modifies
    std::optional<Vector3> gradient, turbulence;
    std::optional<int> octaves, noise_generator;
    std::optional<double> omega, lambda, frequency, phase, agate_turb, exponent;
    std::optional<Vector3> form;             ///< crackle's `form`
    std::optional<double> metric, offset;    ///< crackle's `metric` and `offset`
    bool solid = false;                      ///< crackle's `solid`
    std::optional<int> iterations;           ///< mandel's iteration count
    std::optional<int> arms;                 ///< spiral1's and spiral2's
    std::optional<double> control0, control1;  ///< quilted's
    std::optional<std::pair<int, double>> interior, exterior;  ///< mandel's TYPE, FACTOR
    std::string wave;                     ///< `sine_wave`, ... as written
    std::vector<Token> unsupported;       ///< modifiers photon does not evaluate (warp, uv_mapping, ...)
    bool reduced = false;  ///< a listed colour was itself patterned, and is reduced to its average
    std::shared_ptr<const ImageMapDesc> image;  ///< image_map's image and options
};

/// `rgb <r, g, b>` with three decimals, for messages.
inline std::string describe_average(const Color& c) {
    char buf[96];
    std::snprintf(buf, sizeof buf, "rgb <%.3g, %.3g, %.3g>", c.rgb.x, c.rgb.y, c.rgb.z);
    std::string s = buf;
    if (c.filter != 0 || c.transmit != 0) {
        std::snprintf(buf, sizeof buf, " (filter %.3g, transmit %.3g)", c.filter, c.transmit);
        s += buf;
    }
    return s;
}

/// The colour a fraction `t` of the way from `a` to `b`, filter and transmit too.
inline Color mix(const Color& a, const Color& b, double t) {
    return {a.rgb + (b.rgb - a.rgb) * t, a.filter + (b.filter - a.filter) * t,
            a.transmit + (b.transmit - a.transmit) * t};
}

/// The colour POV-Ray's blend map gives at `x`: the first entry's below it, the last's above,
/// linear between neighbours (entries in the order written, as POV-Ray searches them).
inline Color blend_at(const std::vector<std::pair<double, Color>>& entries, double x) {
    if (x <= entries.front().first) return entries.front().second;
    for (std::size_t i = 1; i < entries.size(); ++i) {
        const auto& [v0, c0] = entries[i - 1];
        const auto& [v1, c1] = entries[i];
        if (x < v1) return v1 > v0 ? mix(c0, c1, (x - v0) / (v1 - v0)) : c1;
    }
    return entries.back().second;
}

/// The map's average over [0, 1]. The map is linear between the entries' values, so the
/// value at each piece's midpoint times its width is exact (and never falls on a step).
inline Color blend_average(const std::vector<std::pair<double, Color>>& entries) {
    if (entries.empty()) return {};
    std::vector<double> cuts{0.0, 1.0};
    for (const auto& e : entries)
        if (e.first > 0 && e.first < 1) cuts.push_back(e.first);
    std::sort(cuts.begin(), cuts.end());
    Color sum;
    for (std::size_t i = 1; i < cuts.size(); ++i) {
        const double w = cuts[i] - cuts[i - 1];
        if (w <= 0) continue;
        const Color c = blend_at(entries, 0.5 * (cuts[i - 1] + cuts[i]));
        sum.rgb += c.rgb * w, sum.filter += c.filter * w, sum.transmit += c.transmit * w;
    }
    return sum;
}

/// POV-Ray's own colour map for a pattern written without one (core/material/pattern.cpp).
inline std::vector<std::pair<double, Color>> default_color_map(const std::string& pattern) {
    auto rgb = [](double r, double g, double b) { return Color{{r, g, b}, 0, 0}; };
    if (pattern == "agate")
        return {{0.0, rgb(1, 1, 1)},      {0.5, rgb(0.95, 0.75, 0.5)}, {0.5, rgb(0.9, 0.7, 0.5)},
                {0.6, rgb(0.9, 0.7, 0.4)}, {0.6, rgb(1.0, 0.7, 0.4)},  {1.0, rgb(0.6, 0.3, 0.0)}};
    if (pattern == "bozo")
        return {{0.4, rgb(1, 1, 1)}, {0.4, rgb(0, 1, 0)}, {0.6, rgb(0, 1, 0)},
                {0.6, rgb(0, 0, 1)}, {0.8, rgb(0, 0, 1)}, {0.8, rgb(1, 0, 0)}};
    if (pattern == "marble") return {{0.0, rgb(0.9, 0.8, 0.8)}, {0.9, rgb(0.9, 0.08, 0.08)}, {0.9, rgb(0, 0, 0)}};
    if (pattern == "radial")
        return {{0.0, rgb(0, 1, 1)}, {0.333, rgb(1, 1, 0)}, {0.666, rgb(1, 0, 1)}, {1.0, rgb(0, 1, 1)}};
    if (pattern == "wood") return {{0.6, rgb(0.666, 0.312, 0.2)}, {0.6, rgb(0.4, 0.1333, 0.066)}};
    if (pattern == "mandel")
        return {{0.001, rgb(0, 0, 0)}, {0.001, rgb(0, 1, 1)}, {0.012, rgb(1, 1, 0)}, {0.015, rgb(1, 0, 1)}, {0.1, rgb(0, 1, 1)}};
    return {{0.0, rgb(0, 0, 0)}, {1.0, rgb(1, 1, 1)}};
}

/// POV-Ray's colours for a listed pattern's entries that were not written.
inline std::vector<Color> default_listed_colors(const std::string& pattern) {
    auto rgb = [](double r, double g, double b) { return Color{{r, g, b}, 0, 0}; };
    if (pattern == "checker" || pattern == "object") return {rgb(0, 0, 1), rgb(0, 1, 0)};
    if (pattern == "hexagon") return {rgb(0, 0, 1), rgb(0, 1, 0), rgb(1, 0, 0)};
    if (pattern == "brick") return {rgb(0.5, 0.5, 0.5), rgb(0.6, 0.15, 0.15)};
    if (pattern == "square") return {rgb(1, 0, 0), rgb(0, 1, 0), rgb(0, 0, 1), rgb(1, 1, 0)};
    return {rgb(1, 0, 0), rgb(0, 1, 0), rgb(0, 0, 1), rgb(1, 1, 0), rgb(0, 1, 1), rgb(1, 0, 1)};
}

// LIST_ITEM: COLOR | pigment { PIGMENT } | PIGMENT_IDENT | texture { TEXTURE } | TEXTURE_IDENT
// `*patterned` is set when the item is a patterned pigment (its average colour is returned).
inline Color Parser::parse_list_color(const std::string& what, bool* patterned) {
    const Token t = peek();
    auto color_of = [&](const Pigment& p) {
        if (p.pattern && patterned) *patterned = true;
        return p.color;
    };
    if (t.is_identifier("pigment")) return color_of(parse_pigment(next(), Pigment{}));
    if (t.is_identifier("texture")) return color_of(parse_texture(next(), default_texture_).pigment);
    if (t.kind == TokenKind::identifier) {
        if (const Value* v = lookup(t.text)) {
            // Copied before next(), which may run a directive that changes the declarations.
            if (const auto* p = std::get_if<Pigment>(&v->data)) {
                const Color c = color_of(*p);
                next();
                return c;
            }
            if (const auto* tx = std::get_if<Texture>(&v->data)) {
                const Color c = color_of(tx->pigment);
                next();
                return c;
            }
        }
    }
    return parse_color(what);
}

/// True when `t` may start an entry of a listed pattern.
inline bool starts_list_item(const Token& t, bool expression, const Value* v) {
    if (expression || t.is_identifier("color") || t.is_identifier("colour") || t.is_identifier("pigment") ||
        t.is_identifier("texture"))
        return true;
    return v && (std::holds_alternative<Pigment>(v->data) || std::holds_alternative<Texture>(v->data));
}

// PATTERN_ITEM: LISTED_PATTERN [ITEM {[,] ITEM}] | object { OBJECT [ITEM [,] ITEM] } | MAPPED_PATTERN [ARGS]
//             | average | image_map { ... } | BLEND_MAP | MODIFIER [VALUE] | warp { ... }
inline bool Parser::parse_pattern_item(PatternState& st) {
    const Token t = peek();
    if (t.kind != TokenKind::identifier) return false;
    const std::string& w = t.text;
    auto list_items = [&] {
        for (;;) {
            const Token& n = peek();
            const Value* v = n.kind == TokenKind::identifier ? lookup(n.text) : nullptr;
            if (!starts_list_item(n, starts_expression(n), v)) return;
            const bool texture = n.is_identifier("texture") || (v && std::holds_alternative<Texture>(v->data));
            if (texture && !st.finish) {
                Texture tx;
                if (n.is_identifier("texture")) {
                    tx = parse_texture(next(), default_texture_);
                } else {
                    tx = std::get<Texture>(v->data);
                    next();
                }
                st.listed.push_back(tx.pigment.color);
                st.reduced = st.reduced || tx.pigment.pattern != nullptr;
                st.finish = tx.finish;
            } else {
                st.listed.push_back(parse_list_color("a colour of `" + st.pattern.text + "`", &st.reduced));
            }
            optional_comma();
        }
    };
    if (one_of(w, listed_patterns)) {
        st.pattern = next();
        list_items();
    } else if (w == "object") {
        st.pattern = next();
        const Nest nest(*this, t.location);
        open_block(t);
        const Token o = next();
        const Value* v = o.kind == TokenKind::identifier ? lookup(o.text) : nullptr;
        if (v && std::holds_alternative<Object>(v->data)) {
        } else if (o.kind == TokenKind::identifier && is_object_keyword(o.text)) {
            parse_object(o);
        } else {
            fail_expected("an object in the `object` pattern", o);
        }
        list_items();
        close_block(t, "the pattern's two colours");
    } else if (one_of(w, mapped_patterns) || w == "average") {
        st.pattern = next();
        if (one_of(w, {"function", "image_pattern"})) {
            const Nest nest(*this, t.location);
            skip_block(t);
        } else if (w == "pigment_pattern") {
            parse_pigment(t, Pigment{});
        } else if (w == "density_file") {
            const Token type = next();
            if (!type.is_identifier("df3")) fail_expected("`df3` after `density_file`", type);
            const Token file = next();
            if (file.kind != TokenKind::string) fail_expected("a file name in double quotes after `df3`", file);
            // density_file df3 "file" [interpolate N]: N = 0 none, 1 trilinear, 2 tricubic
            if (peek().is_identifier("interpolate")) {
                next();
                parse_integer("the interpolation type after `interpolate` (0, 1 or 2)", 0, 2);
            }
        } else if (w == "slope" && peek().is_symbol("{")) {
            const Nest nest(*this, t.location);
            skip_block(t);
        } else if (w == "mandel") {
            st.iterations = int(parse_integer("mandel's iteration count", 1, 1e7));  // mandel ITERATIONS
        } else if (w == "magnet") {
            // magnet TYPE mandel ITERATIONS | magnet TYPE julia COMPLEX, ITERATIONS: not a mandel
            parse_float("the type of `magnet`");
            const Token form = peek();
            if (form.is_identifier("mandel") || form.is_identifier("julia")) {
                next();
                parse_expression_for("the value of `magnet " + form.text + "`");
                while (accept_symbol(",")) parse_expression_for("the value of `magnet " + form.text + "`");
            }
        } else if (w == "spiral1" || w == "spiral2") {
            st.arms = parse_spiral_arms(w);  // spiral1 ARMS
        } else if (starts_expression(peek())) {  // gradient V, julia V, N, slope V, F, F, tiling N, ...
            const Numeric n = parse_expression_for("the value of `" + w + "`");
            if (w == "gradient") st.gradient = n.is_float() ? Vector3(n.at(0)) : Vector3(n.at(0), n.at(1), n.at(2));
            while (accept_symbol(",")) parse_expression_for("the value of `" + w + "`");
        }
    } else if (w == "image_map") {
        st.pattern = next();
        st.image = parse_image_map_block(t);
    } else if (one_of(w, blend_map_keywords)) {
        st.map = parse_blend_map(next());
    } else if (one_of(w, valued_modifiers)) {
        next();
        const Numeric n = parse_expression_for("the value of `" + w + "`");
        const Vector3 v = n.is_float() ? Vector3(n.at(0)) : Vector3(n.at(0), n.at(1), n.at(2));
        if (w == "mortar") st.mortar = n.at(0);
        if (w == "brick_size") st.brick_size = v;
        if (w == "turbulence" && st.pattern.text.starts_with("spiral")) st.unsupported.push_back(t);  // theirs differs
        else if (w == "turbulence") st.turbulence = v;
        else if (w == "octaves") st.octaves = int(std::lround(n.at(0)));
        else if (w == "noise_generator") st.noise_generator = int(std::lround(n.at(0)));
        else if (w == "omega") st.omega = n.at(0);
        else if (w == "lambda") st.lambda = n.at(0);
        else if (w == "frequency") st.frequency = n.at(0);
        else if (w == "phase") st.phase = n.at(0);
        else if (w == "agate_turb") st.agate_turb = n.at(0);
        else if (w == "form" && st.pattern.text == "crackle") st.form = v;
        else if (w == "offset" && st.pattern.text == "crackle") st.offset = n.at(0);
        else if (w == "control0" && st.pattern.text == "quilted") st.control0 = n.at(0);
        else if (w == "control1" && st.pattern.text == "quilted") st.control1 = n.at(0);
        else if (w == "exponent" && st.pattern.text == "mandel" && n.at(0) == 2.0) {
            // mandel's exponent: 2, its default, is the one photon evaluates
        } else if (w == "metric" && st.pattern.text == "crackle") {
            if (!(n.at(0) > 0)) fail(t.location, "crackle's `metric` must be positive, found " + format_number(n.at(0)));
            st.metric = n.at(0);
        } else st.unsupported.push_back(t);
    } else if ((w == "interior" || w == "exterior") && one_of(st.pattern.text, {"mandel", "julia", "magnet"})) {
        next();  // a fractal's colouring inside and outside the set: TYPE, FACTOR
        const int most = w == "interior" ? 6 : 8;  // POV-Ray's parser's limits
        const int type = int(parse_integer("the type of `" + w + "` (0 to " + std::to_string(most) + ")", 0, most));
        optional_comma();
        SourceLocation at;
        const double factor = parse_float("the factor of `" + w + "`", &at);
        if (w == "exterior" && type == 7 && !(factor >= 1.0))
            fail(at, "`exterior 7` takes the iteration count modulo its factor, which must be at least 1, found " + format_number(factor));
        (w == "interior" ? st.interior : st.exterior) = std::pair(type, factor);
    } else if (w == "poly_wave") {
        next();
        st.wave = w;
        if (starts_expression(peek())) st.exponent = parse_float("the exponent of `poly_wave`");
    } else if (one_of(w, bare_modifiers)) {
        next();
        if (w.ends_with("_wave")) st.wave = w;
        else if (w == "solid") st.solid = st.solid || st.pattern.text == "crackle";  // crackle's; other patterns ignore it
        else st.unsupported.push_back(t);
    } else if (w == "warp") {
        const Nest nest(*this, t.location);
        st.unsupported.push_back(t);
        skip_block(next());
    } else {
        return false;
    }
    return true;
}

// SPIRAL_ARMS: FLOAT after spiral1 or spiral2: the number of arms, truncated to a whole number as
// POV-Ray's short.
inline int Parser::parse_spiral_arms(const std::string& pattern) {
    SourceLocation at;
    const double arms = parse_float("the number of arms of `" + pattern + "`", &at);
    if (!(std::fabs(arms) < 32768.0)) fail(at, "`" + pattern + "` takes -32767 to 32767 arms, found " + format_number(arms));
    return int(arms);
}

// BLEND_MAP: KEYWORD { [MAP_IDENT] {[ FLOAT [,] ENTRY ]} }
inline BlendMap Parser::parse_blend_map(const Token& kw) {
    const Nest nest(*this, kw.location);
    open_block(kw);
    BlendMap map;
    // POV-Ray reads a density_map's entries as densities, which are pigments: a pigment_map.
    map.keyword = kw.text == "colour_map" ? "color_map" : kw.text == "density_map" ? "pigment_map" : kw.text;
    if (peek().kind == TokenKind::identifier) {
        const Token id = peek();
        const Value* v = lookup(id.text);
        if (!v) fail(id.location, "undefined identifier `" + id.text + "`");
        const auto* declared = std::get_if<BlendMap>(&v->data);
        if (!declared || declared->keyword != map.keyword)
            fail(id.location, "expected a " + map.keyword + " identifier, found `" + id.text + "` (" +
                                  type_name(v->data) + ", declared at " + position_in(v->at, id.location) + ")");
        next();
        map = *declared;
    }
    while (peek().is_symbol("[")) {
        const Token open = next();
        parse_blend_entry_body(open, map);
        expect_symbol("]", "to close the `" + map.keyword + "` entry opened at " + position(open.location));
    }
    close_block(kw, "`[` starting an entry");
    return map;
}

// ENTRY: FLOAT [,] (COLOR | FLOAT, COLOR COLOR (old colour maps) | PIGMENT_BODY | TEXTURE_BODY | OTHER_BODY)
inline void Parser::parse_blend_entry_body(const Token& open, BlendMap& map) {
    const Nest nest(*this, open.location);
    // An `average` map's weight may be left out (POV-Ray's teak_37.pov writes `[function { ... }
    // color_map { ... }]`, txtravg.pov `[pigment { ... } finish { ... }]`): it weighs 1 then.
    const bool weightless =
        one_of(map.keyword, {"pigment_map", "texture_map", "normal_map"}) && !starts_expression(peek());
    const double v = weightless ? 1.0 : parse_float("the value of the `" + map.keyword + "` entry");
    const bool comma = accept_symbol(",");
    if (map.keyword == "color_map") {
        (void)comma;
        if (peek().kind == TokenKind::number) {  // [v1[,] v2 color C1 color C2], POV-Ray's old form
            const double v2 = parse_float("the second value of the `color_map` entry");
            const Color c1 = parse_color("the first colour of the entry");
            const Color c2 = parse_color("the second colour of the entry");
            map.entries.push_back({v, c1});
            map.entries.push_back({v2, c2});
        } else {
            map.entries.push_back({v, parse_color("the colour of the `color_map` entry")});
        }
    } else if (map.keyword == "pigment_map") {
        Pigment p = parse_pigment_body(open, Pigment{});
        map.entries.push_back({v, p.color});
        map.pigments.resize(map.entries.size() - 1);  // entries before it were colours
        map.pigments.push_back(p.pattern ? std::make_shared<const Pigment>(std::move(p)) : nullptr);
        map.reduced = map.reduced || map.pigments.back() != nullptr;
    } else if (map.keyword == "texture_map") {
        Texture tex = parse_texture_body(open, default_texture_);
        map.entries.push_back({v, tex.pigment.color});
        if (!map.finish) map.finish = tex.finish;
    } else {  // normal_map, slope_map: photon uses neither; balanced up to the `]`
        int depth = 0;
        for (;;) {
            const Token& t = peek();
            if (t.kind == TokenKind::end_of_file) fail_expected("`]` to close the `" + map.keyword + "` entry", t);
            if (depth == 0 && t.is_symbol("]")) return;
            if (t.is_symbol("{") || t.is_symbol("[")) ++depth;
            if (t.is_symbol("}") || t.is_symbol("]")) --depth;
            next();
        }
    }
}

/// The colour that stands for the pattern in `st`, and in `how` the words saying how it was found.
inline Color Parser::pattern_average(const PatternState& st, const Color& fallback, std::string& how) {
    const std::string& w = st.pattern.text;
    if (w == "image_map") {
        how = "mid grey, rgb <0.5, 0.5, 0.5>";
        return {Vector3(0.5), st.image ? st.image->filter_all : 0, st.image ? st.image->transmit_all : 0};
    }
    if (one_of(w, listed_patterns) || w == "object") {
        std::vector<Color> colors = default_listed_colors(w);
        for (std::size_t i = 0; i < st.listed.size() && i < colors.size(); ++i) colors[i] = st.listed[i];
        if (w == "brick") {
            // Mortar of width `mortar` between bricks of `brick_size`: its share of the volume.
            const Vector3& s = st.brick_size;
            double brick = 1;
            for (int k = 0; k < 3; ++k) brick *= s[k] > 0 ? std::max(0.0, s[k] - st.mortar) / s[k] : 0.0;
            how = "its mortar and brick colours weighted by volume (" + std::to_string(int(std::lround(100 * (1 - brick)))) +
                  "% mortar)";
            return mix(colors[0], colors[1], brick);
        }
        Color sum;
        for (const Color& c : colors) sum.rgb += c.rgb, sum.filter += c.filter, sum.transmit += c.transmit;
        const double n = double(colors.size());
        how = "the mean of its " + std::to_string(colors.size()) + " colours";
        return {sum.rgb / n, sum.filter / n, sum.transmit / n};
    }
    if (w == "average") {
        if (!st.map || st.map->entries.empty()) {
            how = "the colour before it: `average` needs a pigment_map";
            return fallback;
        }
        Color sum;
        double total = 0;
        for (const auto& [weight, c] : st.map->entries)
            sum.rgb += c.rgb * weight, sum.filter += c.filter * weight, sum.transmit += c.transmit * weight,
                total += weight;
        how = "the weighted mean of its " + st.map->keyword + "'s entries";
        if (total == 0) return fallback;
        return {sum.rgb / total, sum.filter / total, sum.transmit / total};
    }
    if (st.map && !st.map->entries.empty()) {
        how = "its " + st.map->keyword + "'s average over [0, 1]";
        return blend_average(st.map->entries);
    }
    how = "its default colour map's average over [0, 1]";
    return blend_average(default_color_map(w));
}

}  // namespace photon::dsl::detail
