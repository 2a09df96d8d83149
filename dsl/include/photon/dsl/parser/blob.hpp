// SPDX-License-Identifier: MIT
#pragma once
// The blob, with POV-Ray 3.7's reading of it (source/parser/parser.cpp Parse_Blob and
// Parse_Blob_Element_Mods): the threshold (1 unless given), components in either syntax, each
// with its own transformations, and POV-Ray's checks.

#include <cmath>
#include <memory>
#include <vector>

#include "degradation.hpp"
#include "parser_class.hpp"

namespace photon::dsl::detail {

// BLOB: blob { BLOB_ITEM {BLOB_ITEM} MODIFIERS }
//   BLOB_ITEM: threshold FLOAT | component STRENGTH, RADIUS, CENTRE
//            | sphere { CENTRE, RADIUS, [strength] STRENGTH COMPONENT_MODIFIERS }
//            | cylinder { END1, END2, RADIUS, [strength] STRENGTH COMPONENT_MODIFIERS }
//            | sturm [BOOL] | hierarchy [BOOL]
//   COMPONENT_MODIFIERS: {translate | rotate | scale | matrix | transform | texture | pigment | normal | finish}
inline void Parser::parse_blob(const Token& kw, Object& obj) {
    auto components = std::make_shared<std::vector<BlobShape::Component>>();
    BlobShape blob;
    SourceLocation threshold_at = kw.location;
    bool warned_texture = false;
    int written = 0;  // components, also those of radius 0
    // POV-Ray squares the radius; 0 makes a component that adds nothing (it divides by it).
    auto radius = [&](const std::string& what) {
        SourceLocation at;
        const double r = parse_float("the radius of the " + what, &at);
        if (!std::isfinite(r)) fail(at, "the radius of the " + what + " must be finite");
        if (r == 0) warn(at, "a blob " + what + " of radius 0 adds nothing to the blob");
        return r;
    };
    auto strength = [&](const std::string& what) {
        if (peek().is_identifier("strength")) next();
        SourceLocation at;
        const double s = parse_float("the strength of the " + what, &at);
        if (!std::isfinite(s)) fail(at, "the strength of the " + what + " must be finite");
        return s;
    };
    for (;;) {
        const Token t = peek();
        if (t.is_identifier("threshold")) {
            next();
            blob.threshold = parse_float("the threshold of the blob", &threshold_at);
        } else if (t.is_identifier("component")) {  // the old syntax: strength, radius, centre
            next();
            BlobShape::Component c;
            c.strength = strength("sphere component");
            optional_comma();
            c.radius = radius("sphere component");
            optional_comma();
            c.a = parse_vector("the centre of the sphere component");
            if (c.radius != 0) components->push_back(c);
            ++written;
            add_primitives(obj, 1, t.location);
        } else if (t.is_identifier("sphere") || t.is_identifier("cylinder")) {
            next();
            const Nest nest(*this, t.location);
            open_block(t);
            BlobShape::Component c;
            c.cylinder = t.text == "cylinder";
            const std::string what = c.cylinder ? "cylinder component" : "sphere component";
            SourceLocation end_at;
            c.a = parse_vector(c.cylinder ? "the first end of the cylinder component" : "the centre of the sphere component");
            optional_comma();
            if (c.cylinder) {
                c.b = parse_vector("the second end of the cylinder component", &end_at);
                optional_comma();
                if (glm::length(c.b - c.a) < 1e-10)  // POV-Ray's EPSILON
                    fail(end_at, "degenerate cylindrical component in blob: its ends coincide (POV-Ray stops here too)");
            }
            c.radius = radius(what);
            optional_comma();
            c.strength = strength(what);
            for (;;) {  // the component's own modifiers
                if (try_transform(c.transform)) continue;
                const Token m = peek();
                if (!(m.is_identifier("texture") || m.is_identifier("pigment") || m.is_identifier("normal") ||
                      m.is_identifier("finish")))
                    break;
                next();
                if (m.text == "texture") parse_texture(m, default_texture_);
                else if (m.text == "pigment") parse_pigment(m, default_texture_.pigment);
                else if (m.text == "finish") parse_finish(m, default_texture_.finish);
                else parse_normal(m, Normal{});
                if (!warned_texture)
                    degrade(m.location, degraded::approximated_texture, "blob",
                            "a blob component's own `" + m.text +
                                "` is ignored: photon gives the blob one texture (POV-Ray blends the components' "
                                "textures by their fields)");
                warned_texture = true;
            }
            close_block(t, "a component modifier (translate, rotate, scale, matrix, transform, texture, pigment, "
                           "normal, finish)",
                        {"translate", "rotate", "scale", "matrix", "transform", "texture", "pigment", "normal", "finish"});
            if (c.radius != 0) components->push_back(c);
            ++written;
            add_primitives(obj, 1, t.location);
        } else if (t.is_identifier("sturm") || t.is_identifier("hierarchy")) {
            // Sturm sequences and POV-Ray's bounding tree: photon's roots are bracketed anyway.
            next();
            parse_optional_bool();
        } else {
            break;
        }
    }
    if (written == 0)
        fail(kw.location, "a blob needs at least one component (sphere, cylinder or component)");
    // POV-Ray renders a threshold <= 0 as the region outside every component: photon's blob is
    // bounded by its components.
    if (!(blob.threshold > 0) || !std::isfinite(blob.threshold))
        fail(threshold_at, "the threshold of the blob must be positive, found " + format_number(blob.threshold) +
                               ": the blob is where the components' field exceeds it");
    blob.components = std::move(components);
    obj.shape = std::move(blob);
}

}  // namespace photon::dsl::detail
