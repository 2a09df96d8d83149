// SPDX-License-Identifier: MIT
#pragma once
// Graceful degradation: constructs photon reads but cannot render. Each is read with POV-Ray's
// syntax (its own where it is short, else as a balanced block through the token stream, so that
// directives inside still run), then skipped or approximated with a warning at its place that
// says what photon does instead. The warning's kind and keyword feed `photon check`'s summary;
// --strict makes every one of them an error. Syntax errors stay errors.

#include "parser_class.hpp"

namespace photon::dsl::detail {

/// Kinds of the warnings about constructs photon reads but does not render.
namespace degraded {
inline constexpr std::string_view skipped_object = "skipped object";
inline constexpr std::string_view approximated_pigment = "approximated pigment";
inline constexpr std::string_view approximated_texture = "approximated texture";
inline constexpr std::string_view approximated_object = "approximated object";
inline constexpr std::string_view approximated_camera = "approximated camera";
inline constexpr std::string_view approximated_light = "approximated light";
inline constexpr std::string_view ignored_effect = "ignored effect";
}  // namespace degraded

inline void Parser::degrade(const SourceLocation& at, std::string_view kind, std::string_view keyword,
                            const std::string& message) {
    if (!warned_.insert(at.str() + '\x1f' + message).second) return;
    if (options_.diagnostics)
        options_.diagnostics({Severity::warning, at, message, std::string(kind), std::string(keyword)});
}

/// What photon lacks, for "`x` is skipped: photon has no ... yet".
inline std::string missing_shape(const std::string& keyword) {
    return keyword;
}

// SKIPPED_OBJECT: KEYWORD { balanced tokens }
inline Object Parser::parse_skipped_object(const Token& kw) {
    const std::string& w = kw.text;
    Object obj;
    obj.at = kw.location;
    obj.shape = SkippedShape{w, {}};
    degrade(kw.location, degraded::skipped_object, w,
            "`" + w + "` is skipped: photon has no " + missing_shape(w) + " yet");
    skip_block(kw);
    return obj;
}

inline bool Parser::is_object_keyword(std::string_view w) const {
    return one_of(w, object_keywords) || one_of(w, unsupported_objects);
}

// BOUNDED_BY: bounded_by { OBJECT {OBJECT} | clipped_by }   CLIPPED_BY: clipped_by { OBJECT {OBJECT} | bounded_by }
// `obj`: the object so far (the bound is written in its space at this point; later
// transformations move both).
inline void Parser::parse_bound_or_clip(const Token& kw, const Object& obj) {
    const Nest nest(*this, kw.location);
    open_block(kw);
    const char* other = kw.text == "bounded_by" ? "clipped_by" : "bounded_by";
    bool other_named = false;
    std::vector<Object> objects;
    if (peek().is_identifier(other)) {
        next();
        other_named = true;
    } else {
        while (peek().kind == TokenKind::identifier && is_object_keyword(peek().text)) objects.push_back(parse_object(next()));
    }
    close_block(kw, std::string("an object or `") + other + "`");
    if (kw.text == "bounded_by") {
        // POV-Ray only skips the rays that miss the bound: a bound that holds the whole object
        // changes nothing (`bounded_by { clipped_by }` bounds by the clip, which clips anyway).
        if (other_named) return;
        if (bound_contains(obj, objects)) return;
        degrade(kw.location, degraded::ignored_effect, kw.text,
                "`bounded_by` is ignored: photon bounds every object itself; the image is the same unless the bound "
                "cuts the object (POV-Ray then clips the object to it), which photon could not rule out here");
    } else
        degrade(kw.location, degraded::ignored_effect, kw.text,
                "`clipped_by` is ignored: photon renders the whole object, unclipped");
}

/// What photon does instead of the effect `keyword` (rainbow, ...).
inline std::string effect_instead(const std::string& keyword) {
    if (keyword == "fog") return "photon renders without fog";
    if (keyword == "rainbow") return "photon renders no rainbow";
    if (keyword == "normal") return "photon does not perturb normals";
    return "photon does not render it";
}

// EFFECT: rainbow { balanced tokens }
inline void Parser::skip_effect(const Token& kw) {
    const Nest nest(*this, kw.location);
    skip_block(kw);
    degrade(kw.location, degraded::ignored_effect, kw.text, "`" + kw.text + "` is ignored: " + effect_instead(kw.text));
}

}  // namespace photon::dsl::detail
