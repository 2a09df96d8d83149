// SPDX-License-Identifier: MIT
#pragma once
// POV-Ray's fog (Parser::Parse_Fog), read as written; build/fog.hpp makes it the library's Fog.
// A declared one (`#declare F = fog {...}`) is a value that `fog { F ... }` starts from.

#include "parser_class.hpp"

namespace photon::dsl::detail {

// FOG: fog { [FOG_IDENT] { COLOR | [distance] FLOAT | fog_type 1|2 | fog_alt FLOAT | fog_offset FLOAT |
//      turb_depth FLOAT | up VECTOR | turbulence VECTOR | octaves FLOAT | omega FLOAT | lambda FLOAT |
//      rotate VECTOR | scale VECTOR | matrix <...> | transform {...} | translate VECTOR } }
// The transformations turn `up` only (POV-Ray's MTransDirection): a translation does nothing.
inline FogDescription Parser::parse_fog_block(const Token& kw) {
    const Nest nest(*this, kw.location);
    open_block(kw);
    FogDescription fog;
    take_identifier(fog, "a fog identifier", true);  // a declared one to add to (or a colour or distance)
    fog.at = kw.location;
    const auto turbulence = [&]() -> Vector3& {
        if (!fog.turbulence) fog.turbulence = Vector3(0.0);
        return *fog.turbulence;
    };
    for (;;) {
        const Token t = peek();
        if (t.is_symbol("}")) break;
        if (t.kind != TokenKind::identifier && !starts_expression(t)) break;
        const std::string& w = t.text;
        if (one_of(w, {"color", "colour", "rgb", "rgbf", "rgbt", "rgbft", "red", "green", "blue", "filter", "transmit"})) {
            fog.color = parse_color("the fog's colour");
        } else if (w == "distance") {
            next();
            fog.distance = parse_float("the fog's distance");
        } else if (w == "fog_type") {
            next();
            fog.type = int(parse_integer("the fog type", 1, 2));
        } else if (w == "fog_alt") {
            next();
            fog.altitude = parse_float("the ground fog's altitude");
        } else if (w == "fog_offset") {
            next();
            fog.offset = parse_float("the ground fog's offset");
        } else if (w == "turb_depth") {
            next();
            fog.turb_depth = parse_float("the fog's turb_depth");
        } else if (w == "up") {
            next();
            fog.up = parse_vector("the fog's up vector");
        } else if (w == "turbulence") {
            next();
            turbulence() = parse_vector("the fog's turbulence");
        } else if (w == "octaves") {
            next();
            turbulence();
            fog.octaves = std::clamp(int(parse_float("the fog's octaves")), 1, 10);  // POV-Ray clamps them so
        } else if (w == "omega") {
            next();
            turbulence();
            fog.omega = parse_float("the fog's omega");
        } else if (w == "lambda") {
            next();
            turbulence();
            fog.lambda = parse_float("the fog's lambda");
        } else if (one_of(w, {"rotate", "scale", "matrix", "transform", "translate"})) {
            Transform tr;
            if (!try_transform(tr)) break;
            if (w == "translate") warn(t.location, "a fog's up vector cannot be translated: `translate` does nothing here");
            fog.up = tr.linear * fog.up;
        } else if (starts_expression(t)) {
            // A bare number is the distance (POV-Ray 1.5's spelling); anything else, a colour.
            const Numeric n = parse_expression_for("the fog's distance or colour");
            if (n.dim <= 1)
                fog.distance = n.at(0);
            else
                fog.color = to_color(n);
        } else {
            break;
        }
    }
    close_block(kw, "a fog colour, `distance`, `fog_type`, `fog_alt`, `fog_offset`, `up`, `turbulence` or a transformation",
                {"distance", "fog_type", "fog_alt", "fog_offset", "turb_depth", "up", "turbulence", "octaves", "omega",
                 "lambda"});
    if (glm::length(fog.up) > 0.0) fog.up = glm::normalize(fog.up);  // as POV-Ray does; build rejects a zero one
    return fog;
}

}  // namespace photon::dsl::detail
