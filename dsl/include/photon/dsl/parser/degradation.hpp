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

// A warning about a construct photon reads but does not render, once for each place and message,
// with its kind and keyword for `photon check`'s summary (and --strict).
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

// Whether `w` starts an object: one photon renders or one it skips.
inline bool Parser::is_object_keyword(std::string_view w) const {
    return one_of(w, object_keywords) || one_of(w, unsupported_objects);
}

// BOUNDED_BY: bounded_by { OBJECT {OBJECT} | clipped_by }   CLIPPED_BY: clipped_by { OBJECT {OBJECT} | bounded_by }
// Both keep their objects in `obj`'s space at this point (later transformations move them with
// it). A clip is exact (the builder intersects the object with it, surfaces of the clip hidden);
// a bound changes the image only where POV-Ray keeps it and it cuts the object, which the
// builder judges (it knows where the object ends up). A polynomial surface keeps a sphere or box
// bound as its gate, exactly as POV-Ray renders it (parse_polynomial_gate).
inline void Parser::parse_bound_or_clip(const Token& kw, Object& obj) {
    const Nest nest(*this, kw.location);
    open_block(kw);
    const bool bound = kw.text == "bounded_by";
    const char* other = bound ? "clipped_by" : "bounded_by";
    bool other_named = false;
    std::vector<Object> objects;
    if (peek().is_identifier(other)) {
        next();
        other_named = true;
    } else {
        while (peek().kind == TokenKind::identifier && is_object_keyword(peek().text)) objects.push_back(parse_object(next()));
    }
    close_block(kw, std::string("an object or `") + other + "`");
    // Judged as written: the object and its bound in the same space, before either moves on.
    const bool holds = bound && !other_named && (bound_contains(obj, objects) || parse_polynomial_gate(obj, objects));
    const Transform to_object = obj.transform.inverse();
    std::vector<std::shared_ptr<const Object>> placed;
    for (Object& o : objects) {
        o.transform = o.transform.then(to_object);
        placed.push_back(std::make_shared<const Object>(std::move(o)));
    }
    if (bound) {
        // `bounded_by { clipped_by }` bounds by the clip, which clips anyway: nothing to judge.
        if (other_named) return;
        if (!holds) obj.bound_may_cut = kw.location;
        obj.bounded_by = std::move(placed);
        return;
    }
    if (other_named) {
        if (obj.bounded_by.empty())
            fail(kw.location, "`clipped_by { bounded_by }` needs a `bounded_by` written before it");
        placed = obj.bounded_by;
        obj.bound_may_cut.reset();  // the bound is the clip now: it cuts nothing the clip keeps
    }
    obj.clipped_by.insert(obj.clipped_by.end(), placed.begin(), placed.end());
    obj.clipped_at = kw.location;
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
