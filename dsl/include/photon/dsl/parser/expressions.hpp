// SPDX-License-Identifier: MIT
#pragma once
// Expressions: POV-Ray's operator grammar over floats, vectors and colours, with identifiers,
// constants (the animation clock among them) and calls of user functions.

#include "parser_class.hpp"

namespace photon::dsl::detail {

// NAMED_EXPRESSION: EXPRESSION, with `what` naming it in messages ("expected WHAT, found ...").
inline Numeric Parser::parse_expression_for(const std::string& what) {
    const std::string saved = expecting_;
    expecting_ = what;
    Numeric n = parse_expression();
    expecting_ = saved;
    return n;
}

// EXPRESSION: OR [? EXPRESSION : EXPRESSION]   (the condition a float, true when not 0)
inline Numeric Parser::parse_expression() {
    const Nest nest(*this, peek().location);
    Numeric c = parse_or();
    if (peek().is_symbol("?")) {
        const Token q = next();
        const bool cond = to_float(c, "a condition before `?`", q.location) != 0.0;
        Numeric a = parse_expression();
        expect_symbol(":", "in `condition ? a : b`");
        Numeric b = parse_expression();
        return cond ? a : b;
    }
    return c;
}

// OR: AND {| AND}   (floats, true when not 0)
inline Numeric Parser::parse_or() {
    Numeric a = parse_and();
    while (peek().is_symbol("|")) {
        const Token op = next();
        const Numeric b = parse_and();
        a = Numeric::scalar(to_float(a, "a number", op.location) != 0.0 || to_float(b, "a number", op.location) != 0.0);
    }
    return a;
}

// AND: RELATION {& RELATION}   (floats, true when not 0)
inline Numeric Parser::parse_and() {
    Numeric a = parse_relation();
    while (peek().is_symbol("&")) {
        const Token op = next();
        const Numeric b = parse_relation();
        a = Numeric::scalar(to_float(a, "a number", op.location) != 0.0 && to_float(b, "a number", op.location) != 0.0);
    }
    return a;
}

// RELATION: SUM {(< | <= | = | != | >= | >) SUM}, component by component on vectors | STRING_RELATION
inline Numeric Parser::parse_relation() {
    // STRING_RELATION: STRING (< | <= | = | != | >= | >) STRING, compared as strcmp (POV-Ray's
    // Parse_Rel_String_Term): `#if (Name != "")`.
    if (starts_string(peek())) {
        const std::string a = parse_string_expression("a string");
        const Token op = next();
        if (!(op.kind == TokenKind::symbol && one_of(op.text, {"<", "<=", "=", "!=", ">=", ">"})))
            fail_expected("a comparison (`=`, `!=`, `<`, ...) after a string", op);
        const int c = a.compare(parse_string_expression("a string to compare with"));
        const bool r = op.text == "<" ? c < 0 : op.text == "<=" ? c <= 0 : op.text == "=" ? c == 0
                     : op.text == "!=" ? c != 0 : op.text == ">=" ? c >= 0 : c > 0;
        return Numeric::scalar(r);
    }
    Numeric a = parse_sum();
    while (!in_vector_) {
        const Token& t = peek();
        if (!(t.kind == TokenKind::symbol && one_of(t.text, {"<", "<=", "=", "!=", ">=", ">"}))) break;
        const Token op = next();
        const Numeric b = parse_sum();
        // Component by component on vectors, as POV-Ray's Parse_Rel_Term (a float is promoted).
        const auto compare = [&](double x, double y) {
            return op.text == "<" ? x < y : op.text == "<=" ? x <= y : op.text == "=" ? x == y
                 : op.text == "!=" ? x != y : op.text == ">=" ? x >= y : x > y;
        };
        Numeric r;
        r.dim = std::max(a.dim, b.dim);
        for (int i = 0; i < std::max(r.dim, 1); ++i) r.c[std::size_t(i)] = compare(a.at(i), b.at(i)) ? 1.0 : 0.0;
        a = r;
    }
    return a;
}

// a + b, a - b, a * b or a / b, component by component (a float promoted); a division by zero or a
// result that is not finite is an error at `op`.
inline Numeric Parser::combine(const Numeric& a, const Numeric& b, const Token& op) {
    Numeric r;
    r.dim = std::max(a.dim, b.dim);
    r.color = a.color || b.color;
    const int n = r.dim == 0 ? 1 : r.dim;
    for (int i = 0; i < n; ++i) {
        const double x = a.at(i), y = b.at(i);
        double v = 0;
        switch (op.text[0]) {
            case '+':
                v = x + y;
                break;
            case '-':
                v = x - y;
                break;
            case '*':
                v = x * y;
                break;
            default:
                if (y == 0.0) fail(op.location, "division by zero");
                v = x / y;
        }
        r.c[std::size_t(i)] = v;
    }
    if (!r.finite()) fail(op.location, "the result of `" + op.text + "` is not a finite number");
    return r;
}

// SUM: PRODUCT {(+ | -) PRODUCT}
inline Numeric Parser::parse_sum() {
    Numeric a = parse_product();
    while (peek().is_symbol("+") || peek().is_symbol("-")) {
        const Token op = next();
        a = combine(a, parse_product(), op);
    }
    return a;
}

// PRODUCT: UNARY {(* | /) UNARY}
inline Numeric Parser::parse_product() {
    Numeric a = parse_unary();
    while (peek().is_symbol("*") || peek().is_symbol("/")) {
        const Token op = next();
        a = combine(a, parse_unary(), op);
    }
    return a;
}

// UNARY: (- | + | !) UNARY | POSTFIX
inline Numeric Parser::parse_unary() {
    const Token& t = peek();
    if (t.is_symbol("-") || t.is_symbol("+") || t.is_symbol("!")) {
        const Token op = next();
        const Nest nest(*this, op.location);
        Numeric v = parse_unary();
        if (op.text == "-")
            for (double& c : v.c) c = -c;
        else if (op.text == "!")
            v = Numeric::scalar(to_float(v, "a number after `!`", op.location) == 0.0);
        return v;
    }
    return parse_postfix();
}

// POSTFIX: PRIMARY {. (x | y | z | t | u | v | red | green | blue | gray | grey | filter | transmit)}
inline Numeric Parser::parse_postfix() {
    Numeric v = parse_primary();
    while (peek().is_symbol(".")) {
        const Token dot = next();
        const Token m = next();
        static const std::map<std::string, int, std::less<>> members = {
            {"x", 0},   {"y", 1},     {"z", 2},    {"t", 3},      {"u", 0},       {"v", 1},
            {"red", 0}, {"green", 1}, {"blue", 2}, {"filter", 3}, {"transmit", 4}};
        if (m.is_identifier("gray") || m.is_identifier("grey")) {
            if (v.dim == 0)
                fail(dot.location, "expected a vector or colour before `." + m.text + "`, found " + describe(v));
            // POV-Ray's grey value of a colour (its GREY_SCALE weights).
            v = Numeric::scalar(0.297 * v.c[0] + 0.589 * v.c[1] + 0.114 * v.c[2]);
            continue;
        }
        const auto it = m.kind == TokenKind::identifier ? members.find(m.text) : members.end();
        if (it == members.end())
            fail_expected("a component (x, y, z, t, red, green, blue, gray, filter, transmit) after `.`", m);
        if (v.dim == 0)
            fail(dot.location, "expected a vector or colour before `." + m.text + "`, found " + describe(v));
        if (it->second >= v.dim)
            fail(m.location,
                 "`." + m.text + "` is beyond the " + std::to_string(v.dim) + " components of " + describe(v));
        v = Numeric::scalar(v.c[std::size_t(it->second)]);
    }
    return v;
}

// PRIMARY: NUMBER | ( EXPRESSION ) | < EXPRESSION {[,] EXPRESSION} [,] > | IDENTIFIER_VALUE
//   (a vector has 2 to 5 float components, comparisons in them in parentheses), or the call of a
//   function whose name #declare has read
inline Numeric Parser::parse_primary() {
    if (pending_call_) {  // a function call whose name #declare has read already
        const Token f = std::move(*pending_call_);
        pending_call_.reset();
        const auto callee = std::get<std::shared_ptr<const UserFunction>>(lookup(f.text)->data);
        return call_function_value(f, *callee);
    }
    const Token t = peek();
    if (t.kind == TokenKind::number) {
        next();
        return Numeric::scalar(t.number);
    }
    if (t.is_symbol("(")) {
        next();
        const bool saved = in_vector_;
        in_vector_ = false;
        Numeric v = parse_expression();
        in_vector_ = saved;
        expect_symbol(")", "to close the `(` at " + position(t.location));
        return v;
    }
    if (t.is_symbol("<")) {
        next();
        Numeric v;
        const bool saved = in_vector_;
        for (;;) {
            in_vector_ = true;
            const SourceLocation at = peek().location;
            const Numeric c = parse_expression();
            in_vector_ = saved;
            if (!c.is_float()) fail(at, "expected a number as a component of the vector, found " + describe(c));
            if (v.dim == 5) fail(at, "a vector has at most 5 components");
            v.c[std::size_t(v.dim++)] = c.c[0];
            // POV-Ray reads an optional comma after each component, so `<1, 2, 3,>` is a vector.
            if (accept_symbol(",") && !peek().is_symbol(">")) continue;
            if (peek().is_symbol(">")) break;
            if (starts_expression(peek())) continue;  // POV-Ray's commas between components are optional
            fail_expected("`,` or `>` in the vector opened at " + position(t.location), peek());
        }
        next();
        if (v.dim < 2) fail(t.location, "a vector needs at least 2 components, found 1");
        return v;
    }
    if (t.kind == TokenKind::identifier) return parse_identifier_value(t);
    fail_expected(expecting_.empty() ? std::string("a number or vector") : expecting_, t);
}

// IDENTIFIER_VALUE: COLOR | CONSTANT | ARRAY_FUNCTION | BUILTIN ( ARGS ) | OBJECT_QUERY
//   | FLOAT_IDENT | VECTOR_IDENT | FUNCTION_IDENT ( ARGS ) | SPLINE_CALL
// CONSTANT: pi | tau | x | y | z | t | u | v | true | yes | on | false | no | off | version | clock
//   | clock_on | clock_delta | initial_clock | final_clock | frame_number | initial_frame | final_frame
//   | image_width | image_height
inline Numeric Parser::parse_identifier_value(const Token& t) {
    const std::string& w = t.text;
    if (color_words().contains(w)) return Numeric::from_color(parse_color(expecting_));
    if (constant_words().contains(w)) {
        next();
        if (w == "pi") return Numeric::scalar(3.14159265358979323846);
        if (w == "tau") return Numeric::scalar(2 * 3.14159265358979323846);
        if (w == "x") return Numeric::vector({1, 0, 0});
        if (w == "y") return Numeric::vector({0, 1, 0});
        if (w == "z") return Numeric::vector({0, 0, 1});
        if (w == "t") {
            Numeric n;
            n.c = {0, 0, 0, 1, 0};
            n.dim = 4;
            return n;
        }
        if (w == "u" || w == "v") {
            Numeric n;
            n.c = {w == "u" ? 1.0 : 0.0, w == "v" ? 1.0 : 0.0, 0, 0, 0};
            n.dim = 2;
            return n;
        }
        if (w == "true" || w == "yes" || w == "on") return Numeric::scalar(1);
        if (w == "false" || w == "no" || w == "off") return Numeric::scalar(0);
        if (w == "version") return Numeric::scalar(version_);
        const AnimationClock& a = options_.animation;
        if (w == "clock") return Numeric::scalar(a.clock);
        if (w == "clock_on") return Numeric::scalar(a.clock_on ? 1.0 : 0.0);
        if (w == "clock_delta") return Numeric::scalar(a.clock_delta);
        if (w == "initial_clock") return Numeric::scalar(a.initial_clock);
        if (w == "final_clock") return Numeric::scalar(a.final_clock);
        if (w == "frame_number") return Numeric::scalar(a.frame_number);
        if (w == "initial_frame") return Numeric::scalar(a.initial_frame);
        if (w == "final_frame") return Numeric::scalar(a.final_frame);
        if (w == "image_width") return Numeric::scalar(options_.image_width);
        return Numeric::scalar(options_.image_height);
    }
    if (w == "dimensions" || w == "dimension_size") return parse_array_function(next());
    if (builtin_function_words().contains(w)) return parse_function(next());
    if (one_of(w, object_query_functions)) return parse_object_query(next());
    if (const Value* v = lookup(w)) {
        if (w == "photon_version") mentions_photon_version_ = true;
        if (const auto* n = std::get_if<Numeric>(&v->data)) {
            next();
            return *n;
        }
        if (const auto* f = std::get_if<std::shared_ptr<const UserFunction>>(&v->data)) {
            const auto keep = *f;  // the call may redeclare the identifier (a directive in its arguments)
            return call_function_value(next(), *keep);
        }
        if (const auto* sp = std::get_if<Spline>(&v->data)) {
            const Spline spline = *sp;  // the call may redeclare it
            return parse_spline_call(next(), spline);
        }
        fail(t.location, "expected " + (expecting_.empty() ? std::string("a number or vector") : expecting_) +
                             ", found `" + w + "` (" + type_name(v->data) + ", declared at " +
                             position_in(v->at, t.location) + ")");
    }
    if (is_reserved(w) || one_of(w, photon_keywords) || one_of(w, light_keywords))
        fail_expected(expecting_.empty() ? std::string("a number or vector") : expecting_, t);
    std::string best;
    std::size_t best_d = 3;
    for (const auto& scope : scopes_)
        for (const auto& [name, value] : scope) {
            const std::size_t d = edit_distance(w, name);
            if (d < best_d && d <= std::max<std::size_t>(1, w.size() / 3)) best_d = d, best = name;
        }
    fail(t.location, "undefined identifier `" + w + "`" + (best.empty() ? "" : " (did you mean `" + best + "`?)"));
}

}  // namespace photon::dsl::detail
