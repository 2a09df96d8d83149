// SPDX-License-Identifier: MIT
#pragma once
// POV-Ray's sky_sphere: pigments evaluated on the unit direction of a ray that leaves the scene,
// which photon makes the sky light (build/sky.hpp). A declared one (`#declare S = sky_sphere
// {...}`) is a value that `sky_sphere { S ... }` starts from.

#include "degradation.hpp"
#include "parser_class.hpp"

namespace photon::dsl::detail {

// SKY_SPHERE: sky_sphere { [SKY_SPHERE_IDENT] {pigment { PIGMENT_BODY } | emission COLOR | TRANSFORMATION} }
inline SkySphere Parser::parse_sky_sphere_block(const Token& kw) {
    const Nest nest(*this, kw.location);
    open_block(kw);
    SkySphere sky;
    take_identifier(sky, "a sky_sphere identifier");  // a declared one, to add to
    sky.at = kw.location;
    for (;;) {
        const Token t = peek();
        if (t.is_symbol("}")) break;
        if (try_transform(sky.transform)) continue;
        if (t.is_identifier("pigment")) {
            // The sky_sphere's transformations move every pigment, also those written after
            // them (POV-Ray composes them into one transform of the sky, Transform_Skysphere).
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
    return sky;
}

// SKY_SPHERE_STATEMENT: sky_sphere {..}, the scene's sky, replacing any earlier one.
inline void Parser::parse_sky_sphere(const Token& kw) { scene_.sky_sphere = parse_sky_sphere_block(kw); }

}  // namespace photon::dsl::detail
