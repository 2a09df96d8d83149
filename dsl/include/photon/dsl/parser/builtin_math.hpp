// SPDX-License-Identifier: MIT
#pragma once
// POV-Ray's float built-ins as plain functions of numbers: one table that the expression reader
// (builtins.hpp) and the user functions' evaluator (user_functions.hpp) share, so that `sin` or
// `mod` means the same in `#declare A = mod(7, 2);` and in `function { mod(x, 2) }`.

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>
#include <span>
#include <string_view>

namespace photon::dsl::detail {

enum class FloatBuiltin : std::uint8_t {
    abs, acos, acosh, asin, asinh, atan, atanh, ceil, cos, cosh, degrees, exp, floor, int_, ln, log, radians,
    sin, sinh, sqrt, tan, tanh, atan2, div, mod, pow, min, max, bitwise_and, bitwise_or, bitwise_xor, select
};

struct FloatBuiltinInfo {
    std::string_view name;
    FloatBuiltin id;
    unsigned min_args, max_args;
};

inline constexpr unsigned many_args = 1000;

inline constexpr FloatBuiltinInfo float_builtins[] = {
    {"abs", FloatBuiltin::abs, 1, 1},
    {"acos", FloatBuiltin::acos, 1, 1},
    {"acosh", FloatBuiltin::acosh, 1, 1},
    {"asin", FloatBuiltin::asin, 1, 1},
    {"asinh", FloatBuiltin::asinh, 1, 1},
    {"atan", FloatBuiltin::atan, 1, 1},
    {"atanh", FloatBuiltin::atanh, 1, 1},
    {"ceil", FloatBuiltin::ceil, 1, 1},
    {"cos", FloatBuiltin::cos, 1, 1},
    {"cosh", FloatBuiltin::cosh, 1, 1},
    {"degrees", FloatBuiltin::degrees, 1, 1},
    {"exp", FloatBuiltin::exp, 1, 1},
    {"floor", FloatBuiltin::floor, 1, 1},
    {"int", FloatBuiltin::int_, 1, 1},
    {"ln", FloatBuiltin::ln, 1, 1},
    {"log", FloatBuiltin::log, 1, 1},
    {"radians", FloatBuiltin::radians, 1, 1},
    {"sin", FloatBuiltin::sin, 1, 1},
    {"sinh", FloatBuiltin::sinh, 1, 1},
    {"sqrt", FloatBuiltin::sqrt, 1, 1},
    {"tan", FloatBuiltin::tan, 1, 1},
    {"tanh", FloatBuiltin::tanh, 1, 1},
    {"atan2", FloatBuiltin::atan2, 2, 2},
    {"div", FloatBuiltin::div, 2, 2},
    {"mod", FloatBuiltin::mod, 2, 2},
    {"pow", FloatBuiltin::pow, 2, 2},
    {"min", FloatBuiltin::min, 1, many_args},
    {"max", FloatBuiltin::max, 1, many_args},
    {"bitwise_and", FloatBuiltin::bitwise_and, 2, many_args},
    {"bitwise_or", FloatBuiltin::bitwise_or, 2, many_args},
    {"bitwise_xor", FloatBuiltin::bitwise_xor, 2, many_args},
    {"select", FloatBuiltin::select, 3, 4},
};

/// The float built-in named `name` (its arity and operation), or null when there is none.
[[nodiscard]] inline const FloatBuiltinInfo* find_float_builtin(std::string_view name) {
    for (const auto& b : float_builtins)
        if (b.name == name) return &b;
    return nullptr;
}

/// The name of `id` as written (a literal, so data() ends with a NUL).
[[nodiscard]] inline std::string_view float_builtin_name(FloatBuiltin id) {
    for (const auto& b : float_builtins)
        if (b.id == id) return b.name;
    return {};
}

/// C's `(int)x` as POV-Ray relies on it on x86-64: truncation, and INT_MIN for a value out of
/// range (the processor's answer), so that seeds and bit masks match POV-Ray's.
[[nodiscard]] inline std::int32_t pov_int(double v) noexcept {
    if (!(v > -2147483649.0 && v < 2147483648.0)) return std::numeric_limits<std::int32_t>::min();
    return std::int32_t(v);
}

/// The index of a zero divisor of `div` or `mod` (an error in POV-Ray); other domain errors show
/// as a result that is not finite.
[[nodiscard]] inline std::optional<std::size_t> zero_divisor(FloatBuiltin f, std::span<const double> a) {
    if ((f == FloatBuiltin::div || f == FloatBuiltin::mod) && a.size() == 2 && a[1] == 0.0) return 1;
    return std::nullopt;
}

/// f(a...) for an argument count within the table's bounds. The result may be NaN or infinite
/// (asin(2), sqrt(-1)): callers report that at the call.
[[nodiscard]] inline double apply_float_builtin(FloatBuiltin f, std::span<const double> a) {
    constexpr double deg = 3.14159265358979323846 / 180.0;
    auto bitwise = [&](auto op) {
        std::int32_t r = pov_int(a[0]);
        for (std::size_t i = 1; i < a.size(); ++i) r = op(r, pov_int(a[i]));
        return double(r);
    };
    switch (f) {
        case FloatBuiltin::abs: return std::abs(a[0]);
        case FloatBuiltin::acos: return std::acos(a[0]);
        case FloatBuiltin::acosh: return std::acosh(a[0]);
        case FloatBuiltin::asin: return std::asin(a[0]);
        case FloatBuiltin::asinh: return std::asinh(a[0]);
        case FloatBuiltin::atan: return std::atan(a[0]);
        case FloatBuiltin::atanh: return std::atanh(a[0]);
        case FloatBuiltin::ceil: return std::ceil(a[0]);
        case FloatBuiltin::cos: return std::cos(a[0]);
        case FloatBuiltin::cosh: return std::cosh(a[0]);
        case FloatBuiltin::degrees: return a[0] / deg;
        case FloatBuiltin::exp: return std::exp(a[0]);
        case FloatBuiltin::floor: return std::floor(a[0]);
        case FloatBuiltin::int_: return std::trunc(a[0]);
        case FloatBuiltin::ln: return std::log(a[0]);
        case FloatBuiltin::log: return std::log10(a[0]);
        case FloatBuiltin::radians: return a[0] * deg;
        case FloatBuiltin::sin: return std::sin(a[0]);
        case FloatBuiltin::sinh: return std::sinh(a[0]);
        case FloatBuiltin::sqrt: return std::sqrt(a[0]);
        case FloatBuiltin::tan: return std::tan(a[0]);
        case FloatBuiltin::tanh: return std::tanh(a[0]);
        case FloatBuiltin::atan2: return std::atan2(a[0], a[1]);
        case FloatBuiltin::div: return std::trunc(a[0] / a[1]);
        case FloatBuiltin::mod: return std::fmod(a[0], a[1]);
        case FloatBuiltin::pow: return std::pow(a[0], a[1]);
        case FloatBuiltin::min: return *std::min_element(a.begin(), a.end());
        case FloatBuiltin::max: return *std::max_element(a.begin(), a.end());
        case FloatBuiltin::bitwise_and: return bitwise([](std::int32_t x, std::int32_t y) { return x & y; });
        case FloatBuiltin::bitwise_or: return bitwise([](std::int32_t x, std::int32_t y) { return x | y; });
        case FloatBuiltin::bitwise_xor: return bitwise([](std::int32_t x, std::int32_t y) { return x ^ y; });
        case FloatBuiltin::select:
            if (a.size() == 3) return a[0] < 0 ? a[1] : a[2];
            return a[0] < 0 ? a[1] : (a[0] == 0 ? a[2] : a[3]);
    }
    return 0;
}

}  // namespace photon::dsl::detail
