// SPDX-License-Identifier: MIT
#pragma once
// POV-Ray's sky_sphere: pigments evaluated on the unit direction of a ray that leaves the scene,
// which photon makes the sky light (build/sky.hpp).

#include "degradation.hpp"
#include "parser_class.hpp"

namespace photon::dsl::detail {

// SKY_SPHERE: sky_sphere { [SKY_SPHERE_IDENT] {pigment { PIGMENT_BODY } | emission COLOR | TRANSFORMATION} }
inline void Parser::parse_sky_sphere(const Token& kw) {
    const Nest nest(*this, kw.location);
    open_block(kw);
    const Token first = peek();
    if (first.kind == TokenKind::identifier) {
        if (const Value* v = lookup(first.text); v && std::holds_alternative<IgnoredBlock>(v->data)) {
            // A declared sky_sphere was skipped when declared (keywords.hpp): only its use is known.
            for (int depth = 1; depth > 0;) {
                const Token t = next();
                if (t.kind == TokenKind::end_of_file)
                    fail_expected("`}` to close `" + kw.text + "` (opened at " + position_in(kw.location, t.location) + ")", t);
                if (t.is_symbol("{")) ++depth;
                if (t.is_symbol("}")) --depth;
            }
            degrade(kw.location, degraded::ignored_effect, kw.text, "`" + kw.text + "` is ignored: " + effect_instead(kw.text));
            return;
        }
    }
    SkySphere sky;
    sky.at = kw.location;
    for (;;) {
        const Token t = peek();
        if (t.is_symbol("}")) break;
        if (try_transform(sky.transform)) continue;
        if (t.is_identifier("pigment")) {
            sky.pigments.push_back(parse_pigment(next(), Pigment{}));
            continue;
        }
        if (t.is_identifier("emission")) {
            next();
            sky.emission = parse_color("the sky_sphere's emission").rgb;
            continue;
        }
        break;
    }
    close_block(kw, "a pigment, `emission` or a transformation", {"pigment", "emission"});
    scene_.sky_sphere = std::move(sky);
}

}  // namespace photon::dsl::detail
