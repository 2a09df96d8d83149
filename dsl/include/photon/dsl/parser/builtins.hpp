// SPDX-License-Identifier: MIT
#pragma once
// POV-Ray's built-in functions in expressions (abs, sin, vcross, select, defined, ...).

#include "parser_class.hpp"

namespace photon::dsl::detail {

inline Numeric Parser::parse_function(const Token& f) {
    const std::string& w = f.text;
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
                                 (lo == hi ? std::to_string(lo) : std::to_string(lo) + " to " + std::to_string(hi)) +
                                 " argument" + (hi == 1 ? "" : "s") + ", found " + std::to_string(args.size()));
    };
    auto num = [&](std::size_t i) {
        return to_float(args[i], "a number as argument " + std::to_string(i + 1) + " of `" + w + "`", at[i]);
    };
    auto vec = [&](std::size_t i) {
        return to_vector(args[i], "a vector as argument " + std::to_string(i + 1) + " of `" + w + "`", at[i]);
    };
    Numeric r;
    constexpr double deg = 3.14159265358979323846 / 180.0;
    if (one_of(w, {"abs", "acos", "asin", "atan", "ceil", "cos", "cosh", "degrees", "exp", "floor", "int", "ln", "log",
                   "radians", "sin", "sinh", "sqrt", "tan", "tanh"})) {
        arity(1, 1);
        const double a = num(0);
        double v = 0;
        if (w == "abs")
            v = std::abs(a);
        else if (w == "acos")
            v = std::acos(a);
        else if (w == "asin")
            v = std::asin(a);
        else if (w == "atan")
            v = std::atan(a);
        else if (w == "ceil")
            v = std::ceil(a);
        else if (w == "cos")
            v = std::cos(a);
        else if (w == "cosh")
            v = std::cosh(a);
        else if (w == "degrees")
            v = a / deg;
        else if (w == "exp")
            v = std::exp(a);
        else if (w == "floor")
            v = std::floor(a);
        else if (w == "int")
            v = std::trunc(a);
        else if (w == "ln")
            v = std::log(a);
        else if (w == "log")
            v = std::log10(a);
        else if (w == "radians")
            v = a * deg;
        else if (w == "sin")
            v = std::sin(a);
        else if (w == "sinh")
            v = std::sinh(a);
        else if (w == "sqrt")
            v = std::sqrt(a);
        else if (w == "tan")
            v = std::tan(a);
        else
            v = std::tanh(a);
        r = Numeric::scalar(v);
    } else if (one_of(w, {"atan2", "div", "mod", "pow"})) {
        arity(2, 2);
        const double a = num(0), b = num(1);
        if ((w == "div" || w == "mod") && b == 0.0) fail(at[1], "division by zero in `" + w + "`");
        r = Numeric::scalar(w == "atan2" ? std::atan2(a, b)
                            : w == "div" ? std::trunc(a / b)
                            : w == "mod" ? std::fmod(a, b)
                                         : std::pow(a, b));
    } else if (w == "min" || w == "max") {
        arity(1, 1000);
        double v = num(0);
        for (std::size_t i = 1; i < args.size(); ++i) v = w == "min" ? std::min(v, num(i)) : std::max(v, num(i));
        r = Numeric::scalar(v);
    } else if (w == "select") {
        arity(3, 4);
        const double s = num(0);
        if (args.size() == 3)
            r = s < 0 ? args[1] : args[2];
        else
            r = s < 0 ? args[1] : (s == 0 ? args[2] : args[3]);
    } else if (w == "vlength") {
        arity(1, 1);
        r = Numeric::scalar(glm::length(vec(0)));
    } else if (w == "vnormalize") {
        arity(1, 1);
        const Vector3 a = vec(0);
        if (glm::length(a) == 0.0) fail(at[0], "`vnormalize` of a zero vector");
        r = Numeric::vector(glm::normalize(a));
    } else if (w == "vdot") {
        arity(2, 2);
        r = Numeric::scalar(glm::dot(vec(0), vec(1)));
    } else if (w == "vcross") {
        arity(2, 2);
        r = Numeric::vector(glm::cross(vec(0), vec(1)));
    } else {  // vrotate
        arity(2, 2);
        r = Numeric::vector(Transform::rotate(vec(1)).vector(vec(0)));
    }
    if (!r.finite()) fail(f.location, "the result of `" + w + "` is not a finite number");
    return r;
}

}  // namespace photon::dsl::detail
