// SPDX-License-Identifier: MIT
#pragma once
// `function` declarations and calls: the body is read once, at the declaration, into a tree of
// FunctionNode (user_function.hpp) with POV-Ray's function grammar (floats only; parameters; the
// float built-ins, select, sum and prod; calls of earlier functions; declared floats as
// constants), and a call `F(1, 2, 3)` in an expression evaluates that tree.

#include "../user_function.hpp"
#include "parser_class.hpp"

namespace photon::dsl::detail {

// FUNCTION: function [ ( IDENTIFIER {, IDENTIFIER} ) ] { EXPRESSION | internal ( FLOAT )
//                                                       | pigment { } | pattern { } | transform { } }
inline std::shared_ptr<const UserFunction> Parser::parse_user_function(const Token& kw, const std::string& name) {
    auto f = std::make_shared<UserFunction>();
    f->name = name;
    f->at = kw.location;
    bool named = false;
    if (accept_symbol("(")) {
        named = true;
        for (;;) {
            const Token p = next();
            if (p.kind != TokenKind::identifier) fail_expected("a parameter name in `function ( )`", p);
            if (std::find(f->parameters.begin(), f->parameters.end(), p.text) != f->parameters.end())
                fail(p.location, "parameter `" + p.text + "` is named twice");
            f->parameters.push_back(p.text);
            if (accept_symbol(",")) continue;
            expect_symbol(")", "to close the parameters of `function`");
            break;
        }
    } else {
        f->parameters = {"x", "y", "z"};
    }
    open_block(kw);
    const Token first = peek();
    if (first.is_identifier("pigment") || first.is_identifier("pattern") || first.is_identifier("transform")) {
        const Token block = next();
        if (block.text == "pigment") {
            f->kind = UserFunction::Kind::pigment;
            f->pigment = parse_pigment(block, Pigment{});
        } else if (block.text == "transform") {
            f->kind = UserFunction::Kind::transform;
            f->transform = parse_transform_block(block);
        } else {
            f->kind = UserFunction::Kind::pattern;
            skip_block(block);
        }
        if (!named) f->parameters = {"x", "y", "z"};
    } else if (first.is_identifier("internal")) {
        next();
        expect_symbol("(", "after `internal`");
        f->kind = UserFunction::Kind::internal;
        f->internal_number = int(parse_integer("the number of an internal function", 0, 1000));
        expect_symbol(")", "to close `internal(`");
        f->parameters.clear();  // POV-Ray's internal functions take x, y, z and their own extras
    } else if (first.is_identifier("spline")) {
        fail(first.location, "`function { spline }` is not supported by photon's scene language");
    } else {
        FunctionScope scope{*f, {}, {}};
        for (std::uint32_t i = 0; i < f->parameters.size(); ++i) scope.names.emplace_back(f->parameters[i], i);
        // POV-Ray's u and v are x and y in a function with the default parameters.
        if (!named) scope.names.emplace_back("u", 0), scope.names.emplace_back("v", 1);
        f->slots = std::uint32_t(f->parameters.size());
        const bool saved = in_vector_;
        in_vector_ = false;
        f->root = fn_expression(scope);
        in_vector_ = saved;
    }
    close_block(kw, "an operator");
    return f;
}

// Adds node `n` to the body, within max_function_body_height, so that evaluating it cannot overflow
// the stack.
inline std::uint32_t Parser::fn_node(FunctionScope& s, FunctionNode n) {
    std::uint32_t height = 1;
    for (const std::uint32_t c : n.children) height = std::max(height, s.heights[c] + 1);
    if (height > max_function_body_height)
        fail(n.at, "function body too deep: more than " + std::to_string(max_function_body_height) +
                       " operations inside each other (a long chain of `+` counts as deep)");
    s.heights.push_back(height);
    s.f.nodes.push_back(std::move(n));
    return std::uint32_t(s.f.nodes.size() - 1);
}

// A node of two operands, `a` and `b`, at the operator `op`.
inline std::uint32_t Parser::fn_binary(FunctionScope& s, FunctionNode::Kind kind, const Token& op,
                                       std::uint32_t a, std::uint32_t b) {
    FunctionNode n;
    n.kind = kind;
    n.children = {a, b};
    n.at = op.location;
    return fn_node(s, std::move(n));
}

// FN_EXPRESSION: FN_OR [ ? FN_EXPRESSION : FN_EXPRESSION ]
inline std::uint32_t Parser::fn_expression(FunctionScope& s) {
    const Nest nest(*this, peek().location);
    const std::uint32_t c = fn_or(s);
    if (!peek().is_symbol("?")) return c;
    const Token q = next();
    const std::uint32_t a = fn_expression(s);
    expect_symbol(":", "in `condition ? a : b`");
    const std::uint32_t b = fn_expression(s);
    FunctionNode n;
    n.kind = FunctionNode::Kind::conditional;
    n.children = {c, a, b};
    n.at = q.location;
    return fn_node(s, std::move(n));
}

// FN_OR: FN_AND { | FN_AND }
inline std::uint32_t Parser::fn_or(FunctionScope& s) {
    std::uint32_t a = fn_and(s);
    while (peek().is_symbol("|")) {
        const Token op = next();
        a = fn_binary(s, FunctionNode::Kind::logical_or, op, a, fn_and(s));
    }
    return a;
}

// FN_AND: FN_RELATION { & FN_RELATION }
inline std::uint32_t Parser::fn_and(FunctionScope& s) {
    std::uint32_t a = fn_relation(s);
    while (peek().is_symbol("&")) {
        const Token op = next();
        a = fn_binary(s, FunctionNode::Kind::logical_and, op, a, fn_relation(s));
    }
    return a;
}

// FN_RELATION: FN_SUM { (< | <= | = | != | >= | >) FN_SUM }
inline std::uint32_t Parser::fn_relation(FunctionScope& s) {
    using K = FunctionNode::Kind;
    std::uint32_t a = fn_sum(s);
    for (;;) {
        const Token& t = peek();
        if (t.kind != TokenKind::symbol) return a;
        const K kind = t.text == "<"    ? K::less
                       : t.text == "<=" ? K::less_equal
                       : t.text == "="  ? K::equal
                       : t.text == "!=" ? K::not_equal
                       : t.text == ">=" ? K::greater_equal
                       : t.text == ">"  ? K::greater
                                        : K::constant;
        if (kind == K::constant) return a;
        const Token op = next();
        a = fn_binary(s, kind, op, a, fn_sum(s));
    }
}

// FN_SUM: FN_PRODUCT { (+ | -) FN_PRODUCT }
inline std::uint32_t Parser::fn_sum(FunctionScope& s) {
    std::uint32_t a = fn_product(s);
    while (peek().is_symbol("+") || peek().is_symbol("-")) {
        const Token op = next();
        a = fn_binary(s, op.text == "+" ? FunctionNode::Kind::add : FunctionNode::Kind::subtract, op, a, fn_product(s));
    }
    return a;
}

// FN_PRODUCT: FN_UNARY { (* | /) FN_UNARY }
inline std::uint32_t Parser::fn_product(FunctionScope& s) {
    std::uint32_t a = fn_unary(s);
    while (peek().is_symbol("*") || peek().is_symbol("/")) {
        const Token op = next();
        a = fn_binary(s, op.text == "*" ? FunctionNode::Kind::multiply : FunctionNode::Kind::divide, op, a, fn_unary(s));
    }
    return a;
}

// FN_UNARY: (- | + | !) FN_UNARY | FN_PRIMARY
inline std::uint32_t Parser::fn_unary(FunctionScope& s) {
    const Token& t = peek();
    if (!(t.is_symbol("-") || t.is_symbol("+") || t.is_symbol("!"))) return fn_primary(s);
    const Token op = next();
    const Nest nest(*this, op.location);
    const std::uint32_t a = fn_unary(s);
    if (op.text == "+") return a;
    FunctionNode n;
    n.kind = op.text == "-" ? FunctionNode::Kind::negate : FunctionNode::Kind::logical_not;
    n.children = {a};
    n.at = op.location;
    return fn_node(s, std::move(n));
}

/// FN_ARGUMENTS: ( [FN_EXPRESSION {, FN_EXPRESSION}] ) after a function's name.
inline std::vector<std::uint32_t> Parser::fn_arguments(FunctionScope& s, const Token& f) {
    expect_symbol("(", "after `" + f.text + "`");
    std::vector<std::uint32_t> args;
    if (!peek().is_symbol(")"))
        for (;;) {
            args.push_back(fn_expression(s));
            if (!accept_symbol(",")) break;
        }
    expect_symbol(")", "to close the arguments of `" + f.text + "`");
    return args;
}

// FN_PRIMARY: NUMBER | ( FN_EXPRESSION ) | PARAMETER | CONSTANT | DECLARED_FLOAT
//           | BUILTIN ( ARGS ) | sum|prod ( IDENTIFIER , FROM , TO , FN_EXPRESSION )
//           | FUNCTION_IDENTIFIER ( ARGS ) [ . COMPONENT ]
inline std::uint32_t Parser::fn_primary(FunctionScope& s) {
    const Token t = next();
    FunctionNode n;
    n.at = t.location;
    if (t.kind == TokenKind::number) {
        n.value = t.number;
        return fn_node(s, std::move(n));
    }
    if (t.is_symbol("(")) {
        const std::uint32_t a = fn_expression(s);
        expect_symbol(")", "to close the `(` at " + position(t.location));
        return a;
    }
    if (t.kind != TokenKind::identifier) fail_expected("a number, a parameter or a function in the function body", t);
    const std::string& w = t.text;
    for (auto it = s.names.rbegin(); it != s.names.rend(); ++it)
        if (it->first == w) {
            n.kind = FunctionNode::Kind::parameter;
            n.index = it->second;
            return fn_node(s, std::move(n));
        }
    if (w == "sum" || w == "prod") {
        expect_symbol("(", "after `" + w + "`");
        const Token var = next();
        if (var.kind != TokenKind::identifier) fail_expected("the name of the variable of `" + w + "`", var);
        expect_symbol(",", "after the variable of `" + w + "`");
        const std::uint32_t from = fn_expression(s);
        expect_symbol(",", "after the start of `" + w + "`");
        const std::uint32_t to = fn_expression(s);
        expect_symbol(",", "after the end of `" + w + "`");
        n.index = s.f.slots++;
        s.names.emplace_back(var.text, n.index);
        const std::uint32_t term = fn_expression(s);
        s.names.pop_back();
        expect_symbol(")", "to close `" + w + "(`");
        n.kind = w == "sum" ? FunctionNode::Kind::sum : FunctionNode::Kind::product;
        n.children = {from, to, term};
        return fn_node(s, std::move(n));
    }
    if (const FloatBuiltinInfo* b = find_float_builtin(w)) {
        n.children = fn_arguments(s, t);
        if (n.children.size() < b->min_args || n.children.size() > b->max_args)
            fail(t.location, "`" + w + "` takes " +
                                 (b->max_args == many_args ? "at least " + std::to_string(b->min_args)
                                  : b->min_args == b->max_args
                                      ? std::to_string(b->min_args)
                                      : std::to_string(b->min_args) + " to " + std::to_string(b->max_args)) +
                                 " arguments, found " + std::to_string(n.children.size()));
        n.kind = FunctionNode::Kind::builtin;
        n.builtin = b->id;
        return fn_node(s, std::move(n));
    }
    if (w == "internal")
        fail(t.location, "`internal(N)` must be the whole body of a function, as in functions.inc");
    if (const Value* v = lookup(w)) {
        if (const auto* callee = std::get_if<std::shared_ptr<const UserFunction>>(&v->data)) {
            n.kind = FunctionNode::Kind::call;
            n.callee = *callee;
            n.children = fn_arguments(s, t);
            check_arity(**callee, n.children.size(), t);
            if ((*callee)->vector_valued()) n.index = fn_component(t, **callee);
            return fn_node(s, std::move(n));
        }
        if (const auto* num = std::get_if<Numeric>(&v->data)) {
            Numeric c = *num;
            while (c.dim > 0 && peek().is_symbol(".")) {
                next();
                const Token m = next();
                const int k = component_index(m.text, c.dim);
                if (k < 0) fail_expected("a component of " + describe(c) + " after `.`", m);
                c = Numeric::scalar(c.c[std::size_t(k)]);
            }
            if (!c.is_float())
                fail(t.location, "a function body takes numbers only: `" + w + "` is " + describe(c) +
                                     " (use `" + w + ".x`, ...)");
            n.value = c.c[0];
            return fn_node(s, std::move(n));
        }
        fail(t.location, "`" + w + "` is " + type_name(v->data) + " (declared at " + position_in(v->at, t.location) +
                             "), not a number a function body can use");
    }
    if (one_of(w, constants) && !one_of(w, {"x", "y", "z", "t", "u", "v"})) {
        lookahead_ = t;  // read the constant as an ordinary expression would
        const Numeric c = parse_identifier_value(t);
        n.value = c.c[0];
        return fn_node(s, std::move(n));
    }
    if (one_of(w, constants))
        fail(t.location, "`" + w + "` is not a parameter of this function (its parameters: " +
                             join_names(s.f.parameters) + ")");
    if (one_of(w, functions) || one_of(w, string_functions))
        fail(t.location, "`" + w + "` cannot be used in a function body: POV-Ray's functions take numbers only");
    fail(t.location, "undefined identifier `" + w + "` in the function body (its parameters: " +
                         join_names(s.f.parameters) + ")");
}

// The parameters' names for a message: "x, y, z", or "none".
inline std::string Parser::join_names(const std::vector<std::string>& names) {
    std::string r;
    for (const auto& n : names) r += (r.empty() ? "" : ", ") + n;
    return r.empty() ? "none" : r;
}

/// Index of component `m` (x, y, z, t, u, v, red, green, blue, filter, transmit, gray) of a
/// value of `dim` components; -1 when there is none. `gray` is -2: a weighted sum, not an index.
inline int Parser::component_index(const std::string& m, int dim) {
    static const std::map<std::string, int, std::less<>> members = {
        {"x", 0},   {"y", 1},     {"z", 2},    {"t", 3},      {"u", 0},        {"v", 1},
        {"red", 0}, {"green", 1}, {"blue", 2}, {"filter", 3}, {"transmit", 4}, {"gray", 5}};
    const auto it = members.find(m);
    if (it == members.end()) return -1;
    if (it->second == 5) return dim == 5 ? 5 : -1;
    return it->second < dim ? it->second : -1;
}

/// FN_COMPONENT: . COMPONENT after a call of a pigment or transform function inside a body
/// (POV-Ray requires it: a body's values are numbers); COMPONENT one of x y z u v red green blue,
/// and t filter transmit of a pigment's colour.
inline std::uint32_t Parser::fn_component(const Token& call, const UserFunction& f) {
    if (!peek().is_symbol("."))
        fail_expected("`.` and a component after `" + call.text + "(...)`: `" + f.name +
                          "` gives a " + (f.kind == UserFunction::Kind::pigment ? "colour" : "vector"),
                      peek());
    next();
    const Token m = next();
    const int k = component_index(m.text, f.kind == UserFunction::Kind::pigment ? 5 : 3);
    if (k < 0 || k == 5) fail_expected("a component (x, y, z, red, green, blue, filter, transmit) after `.`", m);
    return std::uint32_t(k);
}

// Fails unless the call of `f` at `call` has as many arguments as `f` has parameters.
inline void Parser::check_arity(const UserFunction& f, std::size_t n, const Token& call) const {
    if (f.kind == UserFunction::Kind::internal) return;  // its extra parameters are its own
    const std::size_t want = f.parameters.size();
    if (n != want)
        fail(call.location, "`" + call.text + "` takes " + std::to_string(want) + " argument" +
                                (want == 1 ? "" : "s") + " (" + join_names(f.parameters) + "), found " +
                                std::to_string(n));
}

// CALL: FUNCTION_IDENTIFIER ( [FLOAT {, FLOAT}] ), in an expression: evaluated now.
inline Numeric Parser::call_function_value(const Token& t, const UserFunction& f) {
    expect_symbol("(", "after the function `" + t.text + "`");
    const bool saved = in_vector_;
    in_vector_ = false;
    std::vector<double> args;
    if (!peek().is_symbol(")"))
        for (;;) {
            args.push_back(parse_float("a number as argument " + std::to_string(args.size() + 1) + " of `" + t.text + "`"));
            if (!accept_symbol(",")) break;
        }
    expect_symbol(")", "to close the arguments of `" + t.text + "`");
    in_vector_ = saved;
    check_arity(f, args.size(), t);
    FunctionBudget budget{options_.max_tokens > function_steps_ ? options_.max_tokens - function_steps_ : 0,
                          max_function_calls_deep};
    const std::uint64_t before = budget.steps_left;
    try {
        const Numeric r = call_user_function(f, args, budget, t.location);
        function_steps_ += before - budget.steps_left;
        return r;
    } catch (const Error& e) {
        if (e.location().file == t.location.file && e.location().line == t.location.line &&
            e.location().column == t.location.column)
            throw;
        fail(e.location(), e.message() + " (in the call of `" + t.text + "` at " + t.location.str() + ")");
    }
}

}  // namespace photon::dsl::detail
