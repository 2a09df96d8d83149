// SPDX-License-Identifier: MIT
#pragma once
// Materials: texture, pigment, finish (with reflection) and interior blocks, and declared ones.

#include "degradation.hpp"
#include "parser_class.hpp"
#include "patterns.hpp"
#include "pigment_pattern.hpp"

namespace photon::dsl::detail {

/// BLOCK_IDENT: [T_IDENT], a declared `T` at the start of a block.
/// A declared `T` at the start of a block (`texture { T_Ident ...`), copied into `out`. Any
/// other declared type is an error naming `what` was expected, except numbers and colours
/// where `numbers_allowed`.
template <class T>
bool Parser::take_identifier(T& out, const std::string& what, bool numbers_allowed) {
    const Token t = peek();
    if (t.kind != TokenKind::identifier) return false;
    const Value* v = lookup(t.text);
    if (!v) return false;
    if (const T* typed = std::get_if<T>(&v->data)) {
        next();
        out = *typed;
        return true;
    }
    if (numbers_allowed && std::holds_alternative<Numeric>(v->data)) return false;
    fail(t.location, "expected " + what + ", found `" + t.text + "` (" + type_name(v->data) + ", declared at " +
                         position_in(v->at, t.location) + ")");
}

// PIGMENT: pigment { PIGMENT_BODY }
inline Pigment Parser::parse_pigment(const Token& kw, Pigment p) {
    const Nest nest(*this, kw.location);
    open_block(kw);
    p = parse_pigment_body(kw, p);
    close_block(kw, "a colour or a pattern", {"color", "rgb", "rgbf", "rgbt", "rgbft"});
    return p;
}

// PIGMENT_BODY: [PIGMENT_IDENT] {COLOR | PATTERN_ITEM | TRANSFORMATION | quick_color COLOR}
inline Pigment Parser::parse_pigment_body(const Token& kw, Pigment p) {
    p.at = kw.location;
    take_identifier(p, "a colour or a pigment identifier", true);
    PatternState st;
    if (p.pattern) st.base = *p.pattern;
    for (;;) {
        const Token t = peek();
        if (t.is_symbol("}") || t.is_symbol("]")) break;
        if (try_transform(p.transform)) continue;
        if (t.is_identifier("quick_color") || t.is_identifier("quick_colour")) {
            next();
            parse_color("the quick colour");
            continue;
        }
        if (parse_pattern_item(st)) continue;
        if (starts_expression(t) || t.is_identifier("color") || t.is_identifier("colour")) {
            p.color = parse_color("the colour of the pigment");
            if (st.pattern.text.empty()) p.pattern = nullptr, st.base.reset();  // one colour everywhere now
            continue;
        }
        if (t.kind == TokenKind::identifier) {
            if (const Value* v = lookup(t.text))
                fail(t.location,
                     "expected a colour or pigment in `pigment`, found `" + t.text + "` (" + type_name(v->data) + ")");
        }
        break;
    }
    if (st.base && st.pattern.text.empty() && modifies_pattern(st)) {  // `pigment { Declared turbulence 0.5 }`
        st.pattern.text = st.base->name;
        st.pattern.location = kw.location;
    }
    if (!st.pattern.text.empty() || st.map) {
        const std::string name = st.pattern.text.empty() ? st.map->keyword : st.pattern.text;
        const SourceLocation at = st.pattern.text.empty() ? kw.location : st.pattern.location;
        std::string why_not;
        if (auto pattern = evaluated_pattern(st, why_not)) {
            p.color = average_color(*pattern);
            p.pattern = std::move(pattern);
            return p;
        }
        p.pattern = nullptr;
        std::string how;
        p.color = pattern_average(st, p.color, how);
        degrade(at, degraded::approximated_pigment, name,
                name == "image_map" ? "`image_map` is approximated by " + how + ": " + why_not
                                    : "`" + name + "` is approximated by " + how + ", " + describe_average(p.color) +
                                          ": " + why_not);
    }
    return p;
}

// FINISH: finish { [FINISH_IDENT] {ITEM} }, ITEM one of the finish_keywords with its value
inline Finish Parser::parse_finish(const Token& kw, Finish f) {
    const Nest nest(*this, kw.location);
    open_block(kw);
    f.at = kw.location;
    take_identifier(f, "a finish identifier or a finish item");
    bool phong_albedo = false, specular_albedo = false;
    for (;;) {
        const Token t = peek();
        if (t.kind != TokenKind::identifier || !one_of(t.text, finish_keywords)) break;
        next();
        const std::string& w = t.text;
        f.written[w] = t.location;
        if (w == "ambient") {
            f.ambient = to_color(parse_expression_for("the ambient colour")).rgb;  // < 0 too: build says what photon uses
        } else if (w == "diffuse") {
            f.diffuse_albedo = peek().is_identifier("albedo");
            if (f.diffuse_albedo) next();
            f.diffuse = parse_nonnegative("`diffuse`");
            if (accept_symbol(",")) {
                f.diffuse_back = parse_nonnegative("the back-side `diffuse`");
                f.written["diffuse_back"] = t.location;
            }
        } else if (w == "brilliance") {
            f.brilliance = parse_nonnegative("`brilliance`");
        } else if (w == "specular") {
            specular_albedo = peek().is_identifier("albedo");
            if (specular_albedo) next();
            f.specular = parse_nonnegative("`specular`");
        } else if (w == "roughness") {
            SourceLocation at;
            f.roughness = parse_float("`roughness`", &at);
            if (!(f.roughness > 0) || !std::isfinite(f.roughness))
                fail(at, "`roughness` must be > 0 and finite (the Blinn exponent is 1 / roughness), found " +
                             format_number(f.roughness));
        } else if (w == "phong") {
            phong_albedo = peek().is_identifier("albedo");
            if (phong_albedo) next();
            f.phong = parse_nonnegative("`phong`");
        } else if (w == "phong_size") {
            SourceLocation at;
            f.phong_size = parse_float("`phong_size`", &at);  // <= 0 too, as POV-Ray (build.hpp says what photon uses)
            if (!std::isfinite(f.phong_size)) fail(at, "`phong_size` must be finite, found " + format_number(f.phong_size));
        } else if (w == "metallic") {
            SourceLocation at = t.location;
            f.metallic = starts_expression(peek()) ? parse_float("`metallic`", &at) : 1.0;
            if (!(f.metallic >= 0 && f.metallic <= 1))
                fail(at, "`metallic` must be between 0 and 1, found " + format_number(f.metallic));
        } else if (w == "reflection") {
            f.reflection = parse_reflection(t);
        } else if (w == "reflection_exponent") {
            if (!f.reflection) f.reflection = Reflection{};
            f.reflection->exponent = parse_float("`reflection_exponent`");
        } else if (w == "conserve_energy") {
            f.conserve_energy = parse_optional_bool();
        } else if (w == "emission") {
            f.emission = to_color(parse_expression_for("the emission colour")).rgb;
        } else if (w == "irid") {
            skip_block(t);
        } else if (w == "crand") {
            parse_float("`crand`");
        } else {  // subsurface { translucency COLOR ... }
            const Nest inner(*this, t.location);
            skip_block(t);
            degrade(t.location, degraded::ignored_effect, "subsurface",
                    "`subsurface` is ignored: photon has no subsurface light transport");
        }
    }
    close_block(kw,
                "a finish item (ambient, diffuse, brilliance, specular, phong, phong_size, reflection, "
                "conserve_energy, emission)",
                finish_keywords);
    // `albedo` scales the strength written in this block, with the block's final size, as POV-Ray
    // 3.7 does (parstxtr.cpp) so that strength 1 reflects all the light the highlight receives.
    if (phong_albedo) f.phong *= (f.phong_size + 1) / 2;
    if (specular_albedo) {
        const double e = 1 / f.roughness;
        f.specular *= (e + 2) / (4 * (2 - std::pow(2.0, -e / 2)));
    }
    return f;
}

// REFLECTION: reflection COLOR | reflection { COLOR [[,] COLOR] {fresnel BOOL | falloff F
//   | exponent F | metallic [F]} }   (COLOR any expression: a float is grey; each >= 0)
inline Reflection Parser::parse_reflection(const Token& kw) {
    Reflection r;
    r.at = kw.location;
    auto reflectance = [&](const char* what) {
        SourceLocation at;
        at = peek().location;
        const Vector3 v = to_color(parse_expression_for(what)).rgb;
        if (v.x < 0 || v.y < 0 || v.z < 0)
            fail(at, std::string(what) + " must be >= 0, found " + describe(Numeric::vector(v)));
        return v;
    };
    if (!peek().is_symbol("{")) {
        r.max = r.min = reflectance("the reflection colour");
        return r;
    }
    const Nest nest(*this, kw.location);
    open_block(kw);
    r.max = r.min = reflectance("the reflection");
    if (accept_symbol(",") || starts_expression(peek())) {
        r.max = reflectance("the maximum reflection");
        r.variable = true;
    }
    for (;;) {
        const Token t = peek();
        if (t.is_identifier("fresnel")) {
            next();
            r.fresnel = parse_optional_bool();
        } else if (t.is_identifier("falloff")) {
            next();
            r.falloff = parse_float("`falloff`");
        } else if (t.is_identifier("exponent")) {
            next();
            r.exponent = parse_float("`exponent`");
        } else if (t.is_identifier("metallic")) {
            next();
            r.metallic = starts_expression(peek()) ? parse_float("`metallic`") : 1.0;
        } else {
            break;
        }
    }
    close_block(kw, "`fresnel`, `falloff`, `exponent` or `metallic`", {"fresnel", "falloff", "exponent", "metallic"});
    return r;
}

// INTERIOR: interior { [INTERIOR_IDENT] {ior F | fade_distance F | fade_power F | fade_color COLOR
//                     | caustics F | dispersion F | dispersion_samples F | MEDIA} }
inline Interior Parser::parse_interior(const Token& kw, Interior in) {
    const Nest nest(*this, kw.location);
    open_block(kw);
    in.at = kw.location;
    take_identifier(in, "an interior identifier or `ior`");
    for (;;) {
        const Token t = peek();
        if (t.is_identifier("ior")) {
            next();
            SourceLocation at;
            in.ior = parse_float("the index of refraction after `ior`", &at);
            if (!(in.ior > 0)) fail(at, "ior must be positive, found " + format_number(in.ior));
            in.written["ior"] = t.location;
        } else if (t.is_identifier("fade_distance") || t.is_identifier("fade_power")) {
            next();
            (t.text == "fade_distance" ? in.fade_distance : in.fade_power) = parse_float("`" + t.text + "`");
            in.written[t.text] = t.location;
        } else if (t.is_identifier("fade_color") || t.is_identifier("fade_colour")) {
            next();
            in.fade_color = parse_color("the fade colour").rgb;
            in.written["fade_color"] = t.location;
        } else if (t.kind == TokenKind::identifier && one_of(t.text, {"caustics", "dispersion", "dispersion_samples"})) {
            next();
            const double v = parse_float("`" + t.text + "`");
            if (v != 0 && !(t.text == "dispersion" && v == 1) && t.text != "dispersion_samples")
                degrade(t.location, degraded::ignored_effect, t.text,
                        "interior `" + t.text + "` is ignored: " +
                            (t.text == "caustics" ? std::string("photon's caustics come from its photons")
                                                  : std::string("photon's glass has one ior for all colours")));
        } else if (t.is_identifier("media")) {
            in.media.push_back(parse_media_block(next()));
        } else {
            break;
        }
    }
    close_block(kw, "`ior`", {"ior", "caustics", "dispersion", "fade_distance", "fade_power", "fade_color"});
    return in;
}

// TEXTURE: texture { TEXTURE_BODY }
inline Texture Parser::parse_texture(const Token& kw, Texture tex) {
    const Nest nest(*this, kw.location);
    open_block(kw);
    tex = parse_texture_body(kw, tex);
    close_block(kw, "`pigment`, `finish` or `normal`", {"pigment", "finish", "normal"});
    return tex;
}

// TEXTURE_BODY: [TEXTURE_IDENT] {pigment {..} | finish {..} | normal {..} | TRANSFORMATION}
//             | PATTERN_ITEM (checker TEXTURE TEXTURE, texture_map, ...) | tiles { TEXTURE_BODY tile2 TEXTURE_BODY }
//             | material_map { BITMAP_TYPE "file" [MODIFIERS] {texture {..}} }
inline Texture Parser::parse_texture_body(const Token& kw, Texture tex) {
    tex.at = kw.location;
    take_identifier(tex, "a texture identifier, `pigment` or `finish`");
    tex.at = kw.location;
    PatternState st;
    for (;;) {
        const Token t = peek();
        if (t.is_identifier("pigment")) {
            tex.pigment = parse_pigment(next(), tex.pigment);
        } else if (t.is_identifier("finish")) {
            tex.finish = parse_finish(next(), tex.finish);
        } else if (t.is_identifier("normal")) {
            tex.normal = parse_normal(next(), tex.normal.value_or(Normal{}));
        } else if (t.is_identifier("tiles")) {
            st.pattern = next();
            const Nest nest(*this, t.location);
            open_block(t);
            const Texture a = parse_texture_body(t, default_texture_);
            // Each tile may be a layered texture: photon keeps its first layer, as elsewhere.
            while (peek().is_identifier("texture")) parse_texture(next(), default_texture_);
            const Token tile2 = next();
            if (!tile2.is_identifier("tile2")) fail_expected("`tile2` and the second texture in `tiles`", tile2);
            const Texture b = parse_texture_body(tile2, default_texture_);
            while (peek().is_identifier("texture")) parse_texture(next(), default_texture_);
            close_block(t, "the second texture");
            st.listed = {a.pigment.color, b.pigment.color};
            st.finish = a.finish;
        } else if (t.is_identifier("material_map")) {
            st.pattern = next();
            const Nest nest(*this, t.location);
            open_block(t);
            while (!peek().is_identifier("texture") && !peek().is_symbol("}")) {  // the image and its options
                if (peek().kind == TokenKind::end_of_file) break;
                next();
            }
            while (peek().is_identifier("texture")) {
                const Texture x = parse_texture(next(), default_texture_);
                st.listed.push_back(x.pigment.color);
                if (!st.finish) st.finish = x.finish;
            }
            close_block(t, "a `texture`");
        } else if (Transform step; try_transform(step)) {
            // The texture's transformations move its pigment, its normal and its layers alike.
            transform_texture(tex, step);
        } else if (parse_pattern_item(st)) {
            continue;
        } else {
            break;
        }
    }
    if (!st.pattern.text.empty() || st.map) {
        const std::string name = st.pattern.text.empty() ? st.map->keyword : st.pattern.text;
        const SourceLocation at = st.pattern.text.empty() ? kw.location : st.pattern.location;
        std::string how;
        if (name == "material_map" || name == "tiles") {
            Color sum;
            for (const Color& c : st.listed) sum.rgb += c.rgb, sum.filter += c.filter, sum.transmit += c.transmit;
            const double n = double(std::max<std::size_t>(1, st.listed.size()));
            tex.pigment.color = {sum.rgb / n, sum.filter / n, sum.transmit / n};
            how = "the mean of its textures' colours";
        } else {
            tex.pigment.color = pattern_average(st, tex.pigment.color, how);
        }
        tex.pigment.pattern = nullptr;
        if (st.finish) tex.finish = *st.finish;
        if (st.map && st.map->finish) tex.finish = *st.map->finish;
        degrade(at, degraded::approximated_texture, name,
                "`" + name + "` is approximated by one texture: " + how + ", " + describe_average(tex.pigment.color) +
                    ", with the first texture's finish: photon has no patterned textures yet");
    }
    return tex;
}

}  // namespace photon::dsl::detail
