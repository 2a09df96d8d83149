// SPDX-License-Identifier: MIT
#pragma once
// POV-Ray's built-in functions in expressions: the float ones of builtin_math.hpp, select and
// defined, rand and seed, and the vector ones (vcross, vrotate, vaxis_rotate, ...); the string
// ones are in strings.hpp, the object queries (inside, trace, min_extent, max_extent) in object_queries.hpp.

#include "parser_class.hpp"

namespace photon::dsl::detail {

// BUILTIN: defined ( IDENTIFIER ) | select ( FLOAT , EXPRESSION , EXPRESSION [, EXPRESSION] )
//   | rand ( FLOAT ) | seed ( FLOAT ) | FLOAT_FUNCTION ( [EXPRESSION {, EXPRESSION}] ) | VECTOR_FUNCTION
//   | STRING_MEASURE (strings.hpp) | INSIDE (object_queries.hpp)
inline Numeric Parser::parse_function(const Token& f) {
    const std::string& w = f.text;
    if (one_of(w, {"strlen", "val", "asc", "strcmp", "file_exists"})) return parse_string_measure(f);
    if (w == "inside") return parse_inside(f);
    expect_symbol("(", "after `" + w + "`");
    const bool saved = in_vector_;
    in_vector_ = false;
    if (w == "defined") {
        Token id;
        {
            const ReadingName reading(*this);  // `defined(M)` does not call the macro M
            id = next();
        }
        if (id.kind != TokenKind::identifier) fail_expected("an identifier in `defined( )`", id);
        if (id.text == "photon_version") mentions_photon_version_ = true;
        expect_symbol(")", "to close `defined(`");
        in_vector_ = saved;
        return Numeric::scalar(lookup(id.text) != nullptr || macros_.count(id.text) > 0);
    }
    std::vector<Numeric> args;
    std::vector<SourceLocation> at;
    if (!peek().is_symbol(")")) {
        for (;;) {
            at.push_back(peek().location);
            args.push_back(parse_expression_for("an argument of `" + w + "`"));
            if (!accept_symbol(",")) break;
        }
    }
    expect_symbol(")", "to close the arguments of `" + w + "`");
    in_vector_ = saved;
    auto arity = [&](std::size_t lo, std::size_t hi) {
        if (args.size() < lo || args.size() > hi)
            fail(f.location, "`" + w + "` takes " +
                                 (lo == hi           ? std::to_string(lo)
                                  : hi == many_args ? "at least " + std::to_string(lo)
                                                    : std::to_string(lo) + " to " + std::to_string(hi)) +
                                 " argument" + (hi == 1 ? "" : "s") + ", found " + std::to_string(args.size()));
    };
    auto num = [&](std::size_t i) {
        return to_float(args[i], "a number as argument " + std::to_string(i + 1) + " of `" + w + "`", at[i]);
    };
    Numeric r;
    if (w == "select") {
        // select keeps vectors and colours (POV-Ray's select of expressions); in functions it is a float.
        arity(3, 4);
        const double s = num(0);
        if (args.size() == 3)
            r = s < 0 ? args[1] : args[2];
        else
            r = s < 0 ? args[1] : (s == 0 ? args[2] : args[3]);
    } else if (const FloatBuiltinInfo* b = find_float_builtin(w)) {
        arity(b->min_args, b->max_args);
        std::vector<double> values(args.size());
        for (std::size_t i = 0; i < args.size(); ++i) values[i] = num(i);
        if (const auto zero = zero_divisor(b->id, values)) fail(at[*zero], "division by zero in `" + w + "`");
        r = Numeric::scalar(apply_float_builtin(b->id, values));
    } else if (w == "rand") {
        arity(1, 1);
        const auto v = random_.next(num(0));
        if (!v)
            fail(at[0], "`rand` of " + format_number(num(0)) + ": no such random stream (" +
                            std::to_string(random_.size()) + " made by `seed` so far; write `#declare S = seed(N);` "
                            "and `rand(S)`)");
        r = Numeric::scalar(*v);
    } else if (w == "seed") {
        arity(1, 1);
        r = Numeric::scalar(random_.add(num(0)));
    } else {
        r = parse_vector_builtin(f, args, at);
    }
    if (!r.finite()) fail(f.location, "the result of `" + w + "` is not a finite number");
    return r;
}

// VECTOR_FUNCTION: vlength | vnormalize | vdot | vcross | vrotate | vaxis_rotate | vturbulence ( ARGS )
inline Numeric Parser::parse_vector_builtin(const Token& f, const std::vector<Numeric>& args,
                                            const std::vector<SourceLocation>& at) {
    const std::string& w = f.text;
    const std::size_t n = w == "vlength" || w == "vnormalize" ? 1 : (w == "vaxis_rotate" ? 3 : (w == "vturbulence" ? 4 : 2));
    if (args.size() != n)
        fail(f.location, "`" + w + "` takes " + std::to_string(n) + " argument" + (n == 1 ? "" : "s") + ", found " +
                             std::to_string(args.size()));
    auto vec = [&](std::size_t i) {
        return to_vector(args[i], "a vector as argument " + std::to_string(i + 1) + " of `" + w + "`", at[i]);
    };
    if (w == "vlength") return Numeric::scalar(glm::length(vec(0)));
    if (w == "vnormalize") {
        const Vector3 a = vec(0);
        if (glm::length(a) == 0.0) fail(at[0], "`vnormalize` of a zero vector");
        return Numeric::vector(glm::normalize(a));
    }
    if (w == "vdot") return Numeric::scalar(glm::dot(vec(0), vec(1)));
    if (w == "vcross") return Numeric::vector(glm::cross(vec(0), vec(1)));
    if (w == "vrotate") return Numeric::vector(Transform::rotate(vec(1)).vector(vec(0)));
    if (w == "vaxis_rotate") {
        // Rodrigues' rotation of A about the axis by the angle in degrees, right-handed like `rotate`.
        const Vector3 a = vec(0), axis = vec(1);
        const double angle = to_float(args[2], "an angle in degrees as argument 3 of `vaxis_rotate`", at[2]);
        if (glm::length(axis) == 0.0) fail(at[1], "`vaxis_rotate` about a zero vector");
        const Vector3 k = glm::normalize(axis);
        const double r = angle * 3.14159265358979323846 / 180.0, c = std::cos(r), s = std::sin(r);
        return Numeric::vector(a * c + glm::cross(k, a) * s + k * glm::dot(k, a) * (1 - c));
    }
    // vturbulence needs POV-Ray's own noise table to give POV-Ray's values; photon has none.
    fail(f.location, "`vturbulence` is not supported by photon's scene language (it needs POV-Ray's noise function)");
}

}  // namespace photon::dsl::detail
