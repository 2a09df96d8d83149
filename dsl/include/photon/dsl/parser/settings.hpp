// SPDX-License-Identifier: MIT
#pragma once
// global_settings: POV-Ray's own items, its photons block, and the items of the settings table
// (settings_table.hpp: photon's own settings and POV-Ray's max_trace_level and adc_bailout).

#include "degradation.hpp"
#include "parser_class.hpp"

namespace photon::dsl::detail {

// GLOBAL_SETTINGS: global_settings { {ITEM} }, ITEM one of POV-Ray's or a settings-table item
inline void Parser::parse_global_settings(const Token& kw) {
    const Nest nest(*this, kw.location);
    open_block(kw);
    GlobalSettings& g = scene_.settings;
    if (!g.at.known()) g.at = kw.location;
    for (;;) {
        const Token t = peek();
        if (t.kind != TokenKind::identifier) break;
        const std::string& w = t.text;
        const RenderSetting* setting = find_setting_item("", w);
        const bool block = is_settings_block(w);
        const bool photon_own = (setting && !setting->povray) || block;
        if (!setting && !block && !one_of(w, global_keywords)) break;
        next();
        g.written[w] = t.location;
        if (photon_own && !in_photon_guard())
            warn(t.location, "`" + w +
                                 "` is photon's own setting and POV-Ray stops at it: write it inside "
                                 "`#ifdef (photon_version) ... #end`");
        if (setting) {
            parse_table_setting(*setting, t);
        } else if (block) {
            parse_settings_block(t);
        } else if (w == "assumed_gamma") {
            // assumed_gamma FLOAT: the gamma of the space the scene's colours are numbers in; the
            // output converts to linear (BuiltScene::working_space), as POV-Ray 3.7 does.
            SourceLocation at;
            g.assumed_gamma = parse_float("`assumed_gamma`", &at);
            if (!(*g.assumed_gamma > 0.0) || !std::isfinite(*g.assumed_gamma))
                fail(at, "`assumed_gamma` must be a positive number, found " + format_number(*g.assumed_gamma));
        } else if (w == "ambient_light") {
            g.ambient_light = to_color(parse_expression_for("the ambient light colour")).rgb;
        } else if (w == "radiosity") {
            skip_block(t);
            g.radiosity = true;
        } else if (w == "photons") {
            parse_pov_photons(t);
        } else if (w == "subsurface") {
            skip_block(t);
            degrade(t.location, degraded::ignored_effect, "subsurface",
                    "`subsurface` is ignored: photon has no subsurface light transport");
        } else {  // charset, noise_generator, number_of_waves, max_intersections, irid_wavelength, hf_gray_16, mm_per_unit
            if (w == "irid_wavelength")
                parse_color("the wavelengths");
            else if (w == "charset")
                next();
            else if (w == "hf_gray_16")
                parse_optional_bool();
            else
                parse_float("`" + w + "`");
        }
    }
    static const std::vector<std::string_view> known = [] {
        std::vector<std::string_view> k = {"assumed_gamma", "ambient_light", "max_trace_level", "adc_bailout",
                                           "radiosity", "photons"};
        k.insert(k.end(), photon_keywords.begin(), photon_keywords.end());
        return k;
    }();
    close_block(kw,
                "a global setting (assumed_gamma, ambient_light, max_trace_level, adc_bailout, radiosity, photons"
                ", or photon's own: global_photons, caustic_photons, global_estimate, ...)",
                known);
}

// SETTING_VALUE: WHOLE_NUMBER | FLOAT | MODE_NAME | STRING, as the settings table says for the item just read
inline void Parser::parse_table_setting(const RenderSetting& s, const Token& kw) {
    // Messages name a top-level item by its keyword, an item of a block by what it is.
    const std::string subject = s.block.empty() ? "`" + kw.text + "`" : std::string(s.noun);
    SettingValue v;
    if (s.kind == SettingKind::integer) {
        v = std::uint64_t(parse_integer(subject, s.lo, s.hi));
    } else if (s.kind == SettingKind::real) {
        SourceLocation at;
        const double x = parse_float(subject, &at);
        if (const auto problem = setting_value_problem(s, x)) fail(at, subject + " " + *problem);
        v = x;
    } else if (s.kind == SettingKind::text) {
        const SourceLocation at = peek().location;
        std::string text = parse_string_expression("a string after `" + kw.text + "`");
        if (const auto problem = setting_value_problem(s, text)) fail(at, subject + " " + *problem);
        v = std::move(text);
    } else {
        const Token m = next();
        const RenderModeName* mode = m.kind == TokenKind::string || m.kind == TokenKind::identifier
                                         ? find_render_mode(m.text)
                                         : nullptr;
        if (!mode || !mode->in_scene) {
            std::vector<std::string> names;  // each mode once, as photon writes it
            for (const RenderModeName& n : render_mode_names)
                if (n.in_scene && render_mode_name(n.mode) == n.name)
                    names.push_back(std::string("`").append(n.name).append("`"));
            std::string list;
            for (std::size_t i = 0; i < names.size(); ++i)
                list.append(i == 0 ? "" : i + 1 == names.size() ? " or " : ", ").append(names[i]);
            fail_expected(list + " after `" + kw.text + "`", m);
        }
        v = std::string(render_mode_name(mode->mode));
    }
    scene_.settings.render[std::string(s.key)] = WrittenSetting{std::move(v), kw.location};
}

// SETTINGS_BLOCK: global_estimate { {ITEM} } | caustic_estimate { {ITEM} }, ITEM one of the block's in the table
inline void Parser::parse_settings_block(const Token& kw) {
    const Nest nest(*this, kw.location);
    open_block(kw);
    for (;;) {
        const Token t = peek();
        const RenderSetting* s = t.kind == TokenKind::identifier ? find_setting_item(kw.text, t.text) : nullptr;
        if (!s) break;
        next();
        parse_table_setting(*s, t);
    }
    std::vector<std::string_view> items;
    for (const RenderSetting& s : render_settings_table)
        if (s.block == kw.text) items.push_back(s.keyword);
    std::string list;
    for (std::size_t i = 0; i < items.size(); ++i)
        list.append(i == 0 ? "" : i + 1 == items.size() ? " or " : ", ").append("`").append(items[i]).append("`");
    close_block(kw, list, items);
}

// POV_PHOTONS: photons { {spacing F | count N | gather MIN, MAX | max_trace_level N | radius R[, ...] | ...} }
// Not in the settings table: its items map onto photon's caustic settings with other meanings.
inline void Parser::parse_pov_photons(const Token& kw) {
    const Nest nest(*this, kw.location);
    open_block(kw);
    PovPhotons ph = scene_.settings.photons.value_or(PovPhotons{});
    ph.at = kw.location;
    for (;;) {
        const Token t = peek();
        if (t.kind != TokenKind::identifier) break;
        const std::string& w = t.text;
        if (w == "count") {
            next();
            ph.count = std::uint64_t(parse_integer("the photon count", 0, 1e12));
        } else if (w == "spacing") {
            next();
            ph.spacing = parse_nonnegative("`spacing`");
        } else if (w == "gather") {
            next();
            ph.gather_min = unsigned(parse_integer("the minimum of `gather`", 0, 1e6));
            optional_comma();
            ph.gather_max = unsigned(parse_integer("the maximum of `gather`", 1, 1e6));
        } else if (w == "max_trace_level") {
            next();
            ph.max_trace_level = unsigned(parse_integer("`max_trace_level`", 1, 256));
        } else if (w == "radius") {
            next();
            double values[4] = {0, 0, 0, 0};
            int n = 0;
            while (n < 4 && starts_expression(peek())) {
                values[n++] = parse_float("the values of `radius`");
                if (!accept_symbol(",")) break;
            }
            if (n > 0 && values[0] > 0) ph.radius = values[0];
        } else if (one_of(w, {"jitter", "autostop", "adc_bailout"})) {
            next();
            parse_float("`" + w + "`");
            ph.ignored[w] = t.location;
        } else if (w == "expand_thresholds") {
            next();
            parse_float("`expand_thresholds`");
            optional_comma();
            parse_float("`expand_thresholds`");
            ph.ignored[w] = t.location;
        } else if (w == "media") {
            next();
            parse_float("`media`");
            while (accept_symbol(",")) parse_float("`media`");
            degrade(t.location, degraded::ignored_effect, w,
                    "photons `media` is ignored: photon's media scatter light sources once, and no photons");
        } else if (w == "save_file" || w == "load_file") {
            next();
            const Token s = next();
            if (s.kind != TokenKind::string) fail_expected("a file name in double quotes", s);
            warn(t.location, "`" + w + "` is ignored: photon always traces its photons");
        } else {
            break;
        }
    }
    close_block(
        kw, "a photons setting (spacing, count, gather, max_trace_level, radius, autostop, jitter)",
        {"spacing", "count", "gather", "max_trace_level", "radius", "autostop", "jitter", "expand_thresholds"});
    scene_.settings.photons = ph;
}

}  // namespace photon::dsl::detail
