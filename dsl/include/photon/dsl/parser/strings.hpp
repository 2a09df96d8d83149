// SPDX-License-Identifier: MIT
#pragma once
// String expressions, read as POV-Ray's Parse_String does: a literal, a declared string or a
// string function (concat, str, chr, substr, strupr, strlwr, vstr, datetime); and the float
// functions of strings (strlen, val, asc, strcmp, file_exists). Strings are bytes; POV-Ray's are
// UCS-2, which is the same for the ASCII that scene files use.

#include <cstdio>
#include <cstdlib>
#include <ctime>

#include "parser_class.hpp"

namespace photon::dsl::detail {

/// printf's `%[0][width][.precision]f` as POV-Ray's str() builds it (width < 0: zero-padded to
/// -width; precision < 0: printf's default of 6), with its fallback to %g when the text would
/// pass 255 characters.
[[nodiscard]] inline std::string pov_format_float(double v, std::int32_t width, std::int32_t precision) {
    char out[256];
    const long long w = width;
    // Either form overflows at a width of 256 or more, and %f at such a precision; %g prints at
    // most the ~770 significant digits a double has, so a larger precision changes nothing.
    if (w >= 256 || w <= -256) return "<invalid>";
    std::string format = "%";
    if (w > 0) format += std::to_string(w);
    if (w < 0) format += "0" + std::to_string(-w);
    for (const char conversion : {'f', 'g'}) {
        if (conversion == 'f' && precision >= 256) continue;
        std::string f = format;
        if (precision >= 0) f += "." + std::to_string(std::min<std::int32_t>(precision, 800));
        f += conversion;
        const int n = std::snprintf(out, sizeof out, f.c_str(), v);
        if (n >= 0 && std::size_t(n) < sizeof out) return std::string(out, std::size_t(n));
    }
    return "<invalid>";
}

/// `c` in UTF-8 (chr() of a code above 127; 0 ends a POV-Ray string, so it gives "").
[[nodiscard]] inline std::string utf8_char(std::uint32_t c) {
    std::string s;
    if (c == 0) return s;
    if (c < 0x80) {
        s += char(c);
    } else if (c < 0x800) {
        s += char(0xC0 | (c >> 6)), s += char(0x80 | (c & 0x3F));
    } else {
        s += char(0xE0 | (c >> 12)), s += char(0x80 | ((c >> 6) & 0x3F)), s += char(0x80 | (c & 0x3F));
    }
    return s;
}

// Whether `t` starts a string expression: a string, a string function or a string identifier.
inline bool Parser::starts_string(const Token& t) const {
    if (t.kind == TokenKind::string) return true;
    if (t.kind != TokenKind::identifier) return false;
    if (one_of(t.text, string_functions)) return true;
    const Value* v = lookup(t.text);
    return v && std::holds_alternative<std::string>(v->data);
}

// A string made while reading, within the bounds on strings and on the scene's data.
inline std::string Parser::bounded_string(std::string s, const SourceLocation& at) {
    if (s.size() > options_.max_file_bytes)
        fail(at, "string too long: " + std::to_string(s.size()) + " bytes, photon's strings hold at most " +
                     std::to_string(options_.max_file_bytes));
    charge_bytes(s.size(), at);
    return s;
}

/// STRING_TOKEN: STRING where POV-Ray takes a file name or a message, kept as a string token
/// located where the expression starts.
inline Token Parser::parse_string_token(const std::string& what) {
    const Token& t = peek();
    if (!starts_string(t)) fail_expected(what, t);
    Token s{TokenKind::string, {}, 0, t.location};
    s.text = parse_string_expression(what);
    return s;
}

// STRING: "literal" | STRING_IDENTIFIER | concat ( STRING {, STRING} ) | str ( FLOAT , FLOAT , FLOAT )
//       | chr ( FLOAT ) | substr ( STRING , FLOAT , FLOAT ) | strupr ( STRING ) | strlwr ( STRING )
//       | vstr ( FLOAT , VECTOR , STRING , FLOAT , FLOAT ) | datetime ( FLOAT [, STRING] )
inline std::string Parser::parse_string_expression(const std::string& what) {
    const Token t = peek();
    const Nest nest(*this, t.location);
    if (t.kind == TokenKind::string) return next().text;
    if (t.kind == TokenKind::identifier && !one_of(t.text, string_functions)) {
        if (const Value* v = lookup(t.text)) {
            if (const auto* s = std::get_if<std::string>(&v->data)) {
                next();
                return *s;
            }
            fail(t.location, "expected " + what + ", found `" + t.text + "` (" + type_name(v->data) +
                                 ", declared at " + position_in(v->at, t.location) + ")");
        }
    }
    if (t.kind != TokenKind::identifier || !one_of(t.text, string_functions)) fail_expected(what, t);
    const Token f = next();
    const std::string& w = f.text;
    expect_symbol("(", "after `" + w + "`");
    const bool saved = in_vector_;
    in_vector_ = false;
    auto comma = [&] { expect_symbol(",", "between the arguments of `" + w + "`"); };
    auto string_arg = [&](int i) {
        return parse_string_expression("a string as argument " + std::to_string(i) + " of `" + w + "`");
    };
    auto float_arg = [&](int i) { return parse_float("a number as argument " + std::to_string(i) + " of `" + w + "`"); };
    std::string r;
    if (w == "concat") {
        r = string_arg(1);
        for (int i = 2; accept_symbol(","); ++i) r = bounded_string(r + string_arg(i), f.location);
    } else if (w == "str") {
        const double v = float_arg(1);
        comma();
        const std::int32_t width = pov_int(float_arg(2));
        comma();
        r = pov_format_float(v, width, pov_int(float_arg(3)));
    } else if (w == "chr") {
        SourceLocation at;
        const double c = parse_float("a character code as the argument of `chr`", &at);
        if (!(c >= 0 && c < 65536)) fail(at, "`chr` takes a character code from 0 to 65535, found " + format_number(c));
        r = utf8_char(std::uint32_t(c));
    } else if (w == "substr") {
        const std::string s = string_arg(1);
        comma();
        SourceLocation at;
        const double start = parse_float("the start of `substr` (1 for the first character)", &at);
        comma();
        const double length = float_arg(3);
        const std::int32_t l = pov_int(start), d = pov_int(length);
        if (l < 1 || d < 0 || double(l) + double(d) - 1 > double(s.size()))
            fail(at, "`substr`: characters " + format_number(start) + " to " + format_number(start + length - 1) +
                         " are not in a string of " + std::to_string(s.size()));
        r = s.substr(std::size_t(l - 1), std::size_t(d));
    } else if (w == "strupr" || w == "strlwr") {
        r = string_arg(1);
        for (char& c : r)
            if (w == "strupr" && c >= 'a' && c <= 'z')
                c = char(c - 'a' + 'A');
            else if (w == "strlwr" && c >= 'A' && c <= 'Z')
                c = char(c - 'A' + 'a');
    } else if (w == "vstr") {
        const int dims = std::clamp<std::int32_t>(pov_int(float_arg(1)), 2, 5);
        comma();
        const Numeric v = parse_expression_for("a vector as argument 2 of `vstr`");
        comma();
        const std::string sep = string_arg(3);
        comma();
        const std::int32_t width = pov_int(float_arg(4));
        comma();
        const std::int32_t precision = pov_int(float_arg(5));
        // A float is not promoted here: POV-Ray prints it as the first component, the rest 0.
        for (int i = 0; i < dims; ++i)
            r += (i ? sep : "") + pov_format_float(i < std::max(v.dim, 1) ? v.c[std::size_t(i)] : 0.0, width, precision);
    } else {  // datetime
        SourceLocation at;
        const double days = parse_float("days since 2000-01-01 as the argument of `datetime`", &at);
        std::string format = "%Y-%m-%d %H:%M:%SZ";
        if (accept_symbol(",")) {
            const SourceLocation fat = peek().location;
            format = string_arg(2);
            if (format.empty()) fail(fat, "`datetime`: empty format string");
            if (format.size() > 200) fail(fat, "`datetime`: format string longer than 200 characters");
        }
        // POV-Ray's day 0 is 2000-01-01 00:00 UTC: 30 years and 7 leap days after the Unix epoch.
        const double seconds = std::floor((days + (365 * 30 + 7)) * 24 * 60 * 60 + 0.5);
        if (!(seconds > -6e13 && seconds < 6e13)) fail(at, "`datetime`: " + format_number(days) + " days is out of range");
        const std::time_t stamp = std::time_t(seconds);
        std::tm tm{};
        char out[201];
        const std::size_t n = gmtime_r(&stamp, &tm) ? std::strftime(out, sizeof out - 1, format.c_str(), &tm) : 0;
        if (n == 0) fail(f.location, "`datetime`: the format gives an empty or too long text");
        r.assign(out, n);
    }
    expect_symbol(")", "to close the arguments of `" + w + "`");
    in_vector_ = saved;
    return bounded_string(std::move(r), f.location);
}

/// POV-Ray's file_exists: the file is found where `#include` would find it. A file the I/O
/// restrictions refuse is not looked for: false, as POV-Ray answers when it may not open it.
inline bool Parser::file_exists_here(const std::string& name) const {
    if (options_.read_include) return options_.read_include(name).has_value();
    if (name.empty()) return false;
    std::error_code ec;
    for (const auto& place : search_places(name, true)) {
        const std::filesystem::path resolved = resolved_path(place);
        if (access_.permits(resolved, FileAccess::read) && std::filesystem::is_regular_file(resolved, ec)) return true;
    }
    return false;
}

// STRING_MEASURE: strlen ( STRING ) | val ( STRING ) | asc ( STRING ) | strcmp ( STRING , STRING )
//               | file_exists ( STRING )
inline Numeric Parser::parse_string_measure(const Token& f) {
    const std::string& w = f.text;
    expect_symbol("(", "after `" + w + "`");
    const bool saved = in_vector_;
    in_vector_ = false;
    const SourceLocation at = peek().location;
    const std::string a = parse_string_expression("a string as argument 1 of `" + w + "`");
    double r = 0;
    if (w == "strlen") {
        r = double(a.size());
    } else if (w == "asc") {
        r = a.empty() ? 0.0 : double(static_cast<unsigned char>(a[0]));
    } else if (w == "val") {
        r = std::strtod(a.c_str(), nullptr);  // C's atof, as POV-Ray: the longest number at the start, else 0
        if (!std::isfinite(r)) fail(at, "`val(\"" + a + "\")` is not a finite number");
    } else if (w == "strcmp") {
        expect_symbol(",", "between the arguments of `strcmp`");
        const std::string b = parse_string_expression("a string as argument 2 of `strcmp`");
        // POV-Ray returns the difference of the first characters that differ, not just the sign.
        std::size_t i = 0;
        while (i < a.size() && i < b.size() && a[i] == b[i]) ++i;
        const int ca = i < a.size() ? static_cast<unsigned char>(a[i]) : 0;
        const int cb = i < b.size() ? static_cast<unsigned char>(b[i]) : 0;
        r = double(ca - cb);
    } else {  // file_exists
        r = file_exists_here(a) ? 1.0 : 0.0;
    }
    expect_symbol(")", "to close the arguments of `" + w + "`");
    in_vector_ = saved;
    return Numeric::scalar(r);
}

}  // namespace photon::dsl::detail
