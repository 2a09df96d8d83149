// SPDX-License-Identifier: MIT
#pragma once
// Typed readers over expressions: a float, a vector, a whole number in bounds, `on`/`off`, a
// colour.

#include "parser_class.hpp"

namespace photon::dsl::detail {

// A value that must be a float: a vector or colour is an error naming `what`.
inline double Parser::to_float(const Numeric& n, const std::string& what, const SourceLocation& at) const {
    if (!n.is_float()) fail(at, "expected " + what + " (a number), found " + describe(n));
    return n.c[0];
}

// A value that must be a vector: a float f is <f, f, f> (POV-Ray's promotion), a 2-vector has z 0,
// a 4- or 5-vector is an error naming `what`.
inline Vector3 Parser::to_vector(const Numeric& n, const std::string& what, const SourceLocation& at) const {
    if (n.dim == 0) return Vector3(n.c[0]);
    if (n.dim == 2 || n.dim == 3) return {n.c[0], n.c[1], n.c[2]};
    fail(at, "expected " + what + " (a vector), found " + describe(n));
}

/// POV-Ray's promotion: a float sets all five components; a 3-vector is rgb.
inline Color Parser::to_color(const Numeric& n) {
    if (n.dim == 0) return {Vector3(n.c[0]), n.c[0], n.c[0]};
    return {{n.at(0), n.at(1), n.at(2)}, n.at(3), n.at(4)};
}

/// PARAMETER: FLOAT | VECTOR, an EXPRESSION whose comparisons need parentheses.
/// A float or vector parameter of a block: POV-Ray reads it at the level of sums (Parse_Float and
/// Parse_Vector call Parse_Rel_Factor), so comparisons need parentheses there and
/// `box { <0,0,0><1,1,1> }` is two corners, not `<0,0,0> < <1,1,1>`.
inline Numeric Parser::parse_parameter_for(const std::string& what) {
    const bool saved = in_vector_;
    in_vector_ = true;
    Numeric n = parse_expression_for(what);
    in_vector_ = saved;
    return n;
}

// FLOAT: a PARAMETER that is a float; `where` receives where it starts.
inline double Parser::parse_float(const std::string& what, SourceLocation* where) {
    const SourceLocation at = peek().location;
    if (where) *where = at;
    return to_float(parse_parameter_for(what), what, at);
}

// VECTOR: a PARAMETER that is a float (promoted to <f, f, f>) or a 2- or 3-vector.
inline Vector3 Parser::parse_vector(const std::string& what, SourceLocation* where) {
    const SourceLocation at = peek().location;
    if (where) *where = at;
    return to_vector(parse_parameter_for(what), what, at);
}

/// INT: FLOAT, a whole number in [lo, hi] (fractions are truncated, as POV-Ray does).
inline std::int64_t Parser::parse_integer(const std::string& what, double lo, double hi) {
    SourceLocation at;
    const double v = parse_float(what, &at);
    // Whole numbers in full (1000000, not 1e+06), so the bound reads as it would be written.
    auto whole = [](double x) {
        return x == std::floor(x) && std::abs(x) < 1e15 ? std::to_string(std::int64_t(x)) : format_number(x);
    };
    if (!(v >= lo && v <= hi))
        fail(at, what + " must be a whole number from " + whole(lo) + " to " + whole(hi) + ", found " + whole(v));
    return std::int64_t(v);
}

// NONNEGATIVE: FLOAT >= 0
inline double Parser::parse_nonnegative(const std::string& what) {
    SourceLocation at;
    const double v = parse_float(what, &at);
    if (v < 0) fail(at, what + " must be >= 0, found " + format_number(v));
    return v;
}

// Whether `t` can start an expression: a number, ( < - + !, a word of the expressions, or an
// identifier of a float, vector, colour, spline or function.
inline bool Parser::starts_expression(const Token& t) const {
    if (t.kind == TokenKind::number) return true;
    if (t.kind == TokenKind::symbol) return one_of(t.text, {"(", "<", "-", "+", "!"});
    if (t.kind != TokenKind::identifier) return false;
    if (expression_words().contains(t.text)) return true;
    const Value* v = lookup(t.text);
    return v && (std::holds_alternative<Numeric>(v->data) || std::holds_alternative<Spline>(v->data) ||
                 std::holds_alternative<std::shared_ptr<const UserFunction>>(v->data));
}

/// BOOL: [FLOAT]: `on`, `off`, any number, or nothing (meaning on).
inline bool Parser::parse_optional_bool() {
    if (!starts_expression(peek())) return true;
    return parse_float("`on` or `off`") != 0.0;
}

/// COLOR: [color|colour] followed by rgb/rgbf/rgbt/rgbft VECTOR, red/green/blue/filter/transmit
/// FLOAT, or a colour expression, in any combination, with one rgb... at most and only first.
inline Color Parser::parse_color(const std::string& what) {
    Color c;
    bool any = false;
    const Token first = peek();
    if (first.is_identifier("color") || first.is_identifier("colour")) next();
    for (;;) {
        const Token t = peek();
        if (t.kind == TokenKind::identifier && one_of(t.text, {"rgb", "rgbf", "rgbt", "rgbft"})) {
            // A second one starts the next colour, as in POV-Ray (Parse_Colour): `checker rgb 1 rgb 0.5`.
            if (any) break;
            next();
            const SourceLocation at = peek().location;
            const Numeric n = parse_expression_for("the value of `" + t.text + "`");
            const int need = t.text == "rgb" ? 3 : (t.text == "rgbft" ? 5 : 4);
            if (n.dim != 0 && n.dim < need)
                fail(at,
                     "expected " + std::to_string(need) + " components after `" + t.text + "`, found " + describe(n));
            c.rgb = {n.at(0), n.at(1), n.at(2)};
            if (t.text == "rgbf") c.filter = n.at(3);
            if (t.text == "rgbt") c.transmit = n.at(3);
            if (t.text == "rgbft") c.filter = n.at(3), c.transmit = n.at(4);
        } else if (t.kind == TokenKind::identifier && one_of(t.text, {"red", "green", "blue", "filter", "transmit"})) {
            next();
            const double v = parse_float("the value of `" + t.text + "`");
            if (t.text == "red")
                c.rgb.x = v;
            else if (t.text == "green")
                c.rgb.y = v;
            else if (t.text == "blue")
                c.rgb.z = v;
            else if (t.text == "filter")
                c.filter = v;
            else
                c.transmit = v;
        } else if (!any && starts_expression(t) && !t.is_identifier("color") && !t.is_identifier("colour")) {
            c = to_color(parse_expression_for(what.empty() ? "a colour" : what));
        } else {
            break;
        }
        any = true;
    }
    if (!any) fail_expected(what.empty() ? std::string("a colour") : what + " (a colour)", peek());
    return c;
}

}  // namespace photon::dsl::detail
