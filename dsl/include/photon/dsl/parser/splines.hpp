// SPDX-License-Identifier: MIT
#pragma once
// POV-Ray's `spline { }` declarations and their calls `S(t)` in expressions.

#include "parser_class.hpp"

namespace photon::dsl::detail {

/// `linear_spline`, `quadratic_spline`, `cubic_spline` or `natural_spline` when `t` is one.
inline std::optional<Spline::Kind> spline_kind(const Token& t) {
    if (t.kind != TokenKind::identifier) return std::nullopt;
    if (t.text == "linear_spline") return Spline::Kind::linear;
    if (t.text == "quadratic_spline") return Spline::Kind::quadratic;
    if (t.text == "cubic_spline") return Spline::Kind::cubic;
    if (t.text == "natural_spline") return Spline::Kind::natural;
    return std::nullopt;
}

// SPLINE: spline { [SPLINE_ID] [linear_spline | quadratic_spline | cubic_spline | natural_spline]
//                  T, VALUE [,] T, VALUE ... }
inline Spline Parser::parse_spline(const Token& kw) {
    const Nest nest(*this, kw.location);
    open_block(kw);
    Spline s;
    take_identifier(s, "a spline identifier or the spline's points");
    for (;;) {
        if (const auto k = spline_kind(peek())) {
            next();
            s.kind = *k;
            continue;
        }
        if (!starts_expression(peek())) break;
        const double t = parse_float("the parameter of a spline point");
        expect_symbol(",", "between the parameter and the value of a spline point");
        const SourceLocation at = peek().location;
        const Numeric v = parse_parameter_for("the value of a spline point");
        if (v.dim != 0 && s.dim == 0 && !s.t.empty())
            fail(at, "expected a number as in the spline's other points, found " + describe(v));
        if (v.dim == 0 && s.dim != 0)
            fail(at, "expected a vector as in the spline's other points, found " + describe(v));
        s.dim = std::max(s.dim, v.dim);
        s.insert(t, {v.at(0), v.at(1), v.at(2), v.at(3), v.at(4)});
        if (s.t.size() > options_.max_primitives)
            fail(at, "the spline is too large: more than " + std::to_string(options_.max_primitives) + " points");
        optional_comma();
    }
    if (s.t.empty()) fail_expected("a spline point (parameter, value)", peek());
    close_block(kw, "a spline point (parameter, value)");
    return s;
}

// SPLINE_CALL: SPLINE_ID ( T [, linear_spline | quadratic_spline | cubic_spline | natural_spline] )
inline Numeric Parser::parse_spline_call(const Token& id, const Spline& s) {
    expect_symbol("(", "after the spline `" + id.text + "`");
    const bool saved = in_vector_;
    in_vector_ = false;
    const double t = parse_float("the parameter of the spline `" + id.text + "`");
    Spline::Kind kind = s.kind;
    if (accept_symbol(",")) {
        const Token k = next();
        const auto given = spline_kind(k);
        if (!given) fail_expected("`linear_spline`, `quadratic_spline`, `cubic_spline` or `natural_spline`", k);
        kind = *given;
    }
    expect_symbol(")", "to close the call of the spline `" + id.text + "`");
    in_vector_ = saved;
    const Spline::Point p = s.at(t, kind);
    Numeric r;
    r.dim = s.dim;
    for (std::size_t c = 0; c < 5; ++c) r.c[c] = p[c];
    if (!r.finite()) fail(id.location, "the spline `" + id.text + "` gives a value that is not a finite number");
    return r;
}

}  // namespace photon::dsl::detail
