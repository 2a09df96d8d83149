// SPDX-License-Identifier: MIT
#pragma once
// POV-Ray's media and density blocks (Parser::Parse_Media, Parse_Media_Density_Pattern), read as
// written; build/media.hpp makes them the library's Medium. A declared media (`#declare M =
// media {...}`) is a value `media { M ... }` starts from; a declared density is a pigment.

#include "parser_class.hpp"

namespace photon::dsl::detail {

// MEDIA: media { [MEDIA_IDENT] { absorption COLOR | emission COLOR
//        | scattering { TYPE, COLOR [eccentricity F] [extinction F] } | density { DENSITY_BODY }
//        | method 1|2|3 | intervals N | samples MIN [, MAX] | jitter F | aa_threshold F | aa_level N
//        | confidence F | variance F | ratio F | collect BOOL | TRANSFORMATION } }
// The transformations move the densities given before them (POV-Ray's Transform_Density).
inline MediaDescription Parser::parse_media_block(const Token& kw) {
    const Nest nest(*this, kw.location);
    open_block(kw);
    MediaDescription m;
    take_identifier(m, "a media identifier");
    m.at = kw.location;
    for (;;) {
        const Token t = peek();
        if (t.kind != TokenKind::identifier) break;
        const std::string& w = t.text;
        if (Transform step; try_transform(step)) {
            for (Pigment& d : m.density) d.transform = d.transform.then(step);
            continue;
        }
        if (w == "absorption" || w == "emission") {
            next();
            (w == "absorption" ? m.absorption : m.emission) = parse_color("the media's " + w).rgb;
        } else if (w == "scattering") {
            next();
            const Nest inner(*this, t.location);
            open_block(t);
            SourceLocation type_at;
            m.scattering_type = int(parse_float("the scattering type", &type_at));
            if (m.scattering_type < 1 || m.scattering_type > 5) {
                warn(type_at, "unknown scattering type " + std::to_string(m.scattering_type) +
                                  ": POV-Ray and photon scatter isotropically (type 1)");
                m.scattering_type = 1;
            }
            optional_comma();
            m.scattering = parse_color("the scattering colour").rgb;
            for (;;) {
                const Token s = peek();
                if (s.is_identifier("eccentricity")) {
                    next();
                    if (m.scattering_type != 5)
                        fail(s.location, "`eccentricity` needs scattering type 5 (Henyey-Greenstein), as in POV-Ray");
                    m.eccentricity = parse_float("the eccentricity");
                } else if (s.is_identifier("extinction")) {
                    next();
                    m.extinction = parse_float("the extinction");
                } else {
                    break;
                }
            }
            close_block(t, "`eccentricity` or `extinction`", {"eccentricity", "extinction"});
        } else if (w == "density") {
            m.density.push_back(parse_density(next()));
        } else if (w == "method") {
            next();
            m.method = int(parse_integer("the media method", 1, 3));
            if (m.method != 3)
                degrade(t.location, degraded::ignored_effect, w,
                        "media `method " + std::to_string(m.method) +
                            "` is sampled as photon samples every media (stratified steps, intervals x samples): "
                            "the same media, with different noise");
        } else if (w == "intervals") {
            next();
            m.intervals = int(parse_integer("the media intervals", 1, 1e6));
        } else if (w == "samples") {
            next();
            m.samples_min = int(parse_integer("the media samples", 1, 1e6));
            m.samples_max = m.samples_min;
            if (accept_symbol(",") || starts_expression(peek()))
                m.samples_max = int(parse_integer("the maximum media samples", m.samples_min, 1e6));
        } else if (w == "jitter") {
            next();
            m.jitter = parse_float("the media jitter");
        } else if (w == "aa_threshold") {
            next();
            m.aa_threshold = parse_float("the media aa_threshold");
        } else if (w == "aa_level") {
            next();
            m.aa_level = int(parse_integer("the media aa_level", 1, 1e6));
        } else if (w == "confidence" || w == "variance" || w == "ratio") {
            next();
            (w == "confidence" ? m.confidence : w == "variance" ? m.variance : m.ratio) = parse_float("the media " + w);
        } else if (w == "collect") {
            next();
            m.collect = parse_optional_bool();
        } else {
            break;
        }
        m.written[w] = t.location;
    }
    close_block(kw, "`absorption`, `emission`, `scattering`, `density`, a sampling setting or a transformation",
                {"absorption", "emission", "scattering", "density", "method", "intervals", "samples", "jitter",
                 "aa_threshold", "aa_level", "confidence", "variance", "ratio", "collect"});
    return m;
}

// DENSITY: density { [DENSITY_IDENT] PIGMENT_BODY }, its `density_map` a pigment_map (patterns.hpp)
inline Pigment Parser::parse_density(const Token& kw) {
    return parse_pigment(kw, Pigment{});  // POV-Ray's Create_Pigment: black until a colour or pattern
}

}  // namespace photon::dsl::detail
