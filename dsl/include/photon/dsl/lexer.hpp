// SPDX-License-Identifier: MIT
#pragma once
// Tokens of POV-Ray's scene language: identifiers (keywords are identifiers the parser knows),
// numbers, strings, symbols and `#directives`, each with its location. Comments are `//` to the
// end of the line and `/* */`, which nest as in POV-Ray.

#include <charconv>
#include <cstdint>
#include <memory>
#include <string>
#include <system_error>
#include <utility>

#include "diagnostics.hpp"

namespace photon::dsl {

enum class TokenKind : std::uint8_t { identifier, number, string, symbol, directive, end_of_file };

struct Token {
    TokenKind kind = TokenKind::end_of_file;
    std::string text;   ///< identifier, symbol or directive name as written; string contents unescaped
    double number = 0;  ///< value of a number token
    SourceLocation location;

    [[nodiscard]] bool is(TokenKind k, std::string_view t) const noexcept { return kind == k && text == t; }
    [[nodiscard]] bool is_symbol(std::string_view t) const noexcept { return is(TokenKind::symbol, t); }
    [[nodiscard]] bool is_identifier(std::string_view t) const noexcept { return is(TokenKind::identifier, t); }
};

/// How a token reads in "found ..." messages.
[[nodiscard]] inline std::string describe(const Token& t) {
    switch (t.kind) {
        case TokenKind::identifier:
            return "`" + t.text + "`";
        case TokenKind::number:
            return "the number " + t.text;
        case TokenKind::string:
            return "the string \"" + t.text + "\"";
        case TokenKind::symbol:
            return "`" + t.text + "`";
        case TokenKind::directive:
            return "`#" + t.text + "`";
        case TokenKind::end_of_file:
            break;
    }
    return "end of file";
}

/// Splits one file into tokens on demand. Its state can be saved and restored (for `#while`).
class Lexer {
public:
    struct State {
        std::size_t pos = 0;
        std::uint32_t line = 1, column = 1;
    };

    explicit Lexer(std::shared_ptr<const SourceFile> file) : file_(std::move(file)), text_(file_->text) {}

    [[nodiscard]] const std::shared_ptr<const SourceFile>& file() const noexcept { return file_; }
    [[nodiscard]] State state() const noexcept { return state_; }
    void restore(const State& s) noexcept { state_ = s; }

    /// The next token; end_of_file forever at the end, located just after the last token (where
    /// a missing `}` belongs). Throws Error on malformed input.
    Token next() {
        Token t = lex();
        if (t.kind != TokenKind::end_of_file) {
            last_end_ = state_;
        } else if (last_end_.pos > 0) {
            t.location = {file_, last_end_.line, last_end_.column};
        }
        return t;
    }

private:
    Token lex() {
        skip_space_and_comments();
        Token t;
        t.location = here();
        if (at_end()) return t;
        const char c = peek_char();
        if (is_digit(c) || (c == '.' && is_digit(peek_char(1)))) return lex_number(std::move(t));
        if (is_ident_start(c)) {
            t.kind = TokenKind::identifier;
            t.text = lex_identifier();
            return t;
        }
        if (c == '"') return lex_string(std::move(t));
        if (c == '#') {
            advance();
            while (!at_end() && (peek_char() == ' ' || peek_char() == '\t')) advance();
            t.kind = TokenKind::directive;  // empty text: a `#` before no name, which the parser skips
            if (at_end() || !is_ident_start(peek_char())) return t;
            t.text = lex_identifier();
            return t;
        }
        static constexpr std::string_view two[] = {"<=", ">=", "!="};
        for (std::string_view s : two)
            if (text_.compare(state_.pos, 2, s) == 0) {
                advance(), advance();
                t.kind = TokenKind::symbol;
                t.text = s;
                return t;
            }
        static constexpr std::string_view one = "{}()[]<>,;=+-*/!?:.&|";
        if (one.find(c) != std::string_view::npos) {
            advance();
            t.kind = TokenKind::symbol;
            t.text = std::string(1, c);
            return t;
        }
        throw Error(t.location, "unexpected character " + char_description());
    }

    static bool is_digit(char c) noexcept { return c >= '0' && c <= '9'; }
    static bool is_ident_start(char c) noexcept { return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '_'; }
    static bool is_ident_char(char c) noexcept { return is_ident_start(c) || is_digit(c); }

    [[nodiscard]] bool at_end() const noexcept { return state_.pos >= text_.size(); }
    [[nodiscard]] char peek_char(std::size_t ahead = 0) const noexcept {
        return state_.pos + ahead < text_.size() ? text_[state_.pos + ahead] : '\0';
    }
    void advance() noexcept {
        if (text_[state_.pos] == '\n') {
            ++state_.line;
            state_.column = 1;
        } else {
            ++state_.column;
        }
        ++state_.pos;
    }
    [[nodiscard]] SourceLocation here() const { return {file_, state_.line, state_.column}; }
    [[nodiscard]] std::string char_description() const {
        if (at_end()) return "end of file";
        const auto c = static_cast<unsigned char>(peek_char());
        if (c == '\n' || c == '\r') return "end of line";
        if (c == ' ') return "a space";
        if (c == '\t') return "a tab";
        if (c < 32 || c >= 127) {
            static constexpr char hex[] = "0123456789abcdef";
            return std::string("byte 0x") + hex[c >> 4] + hex[c & 15];
        }
        return std::string("`") + char(c) + "`";
    }

    void skip_space_and_comments() {
        for (;;) {
            while (!at_end() && (peek_char() == ' ' || peek_char() == '\t' || peek_char() == '\n' ||
                                 peek_char() == '\r' || peek_char() == '\f' || peek_char() == '\v'))
                advance();
            if (peek_char() == '/' && peek_char(1) == '/') {
                while (!at_end() && peek_char() != '\n') advance();
            } else if (peek_char() == '/' && peek_char(1) == '*') {
                const SourceLocation open = here();
                advance(), advance();
                int depth = 1;
                while (depth > 0) {
                    if (at_end())
                        throw Error(
                            open,
                            "unterminated comment: expected `*/` to close the `/*` opened here, found end of file");
                    if (peek_char() == '/' && peek_char(1) == '*') {
                        advance(), advance();
                        ++depth;
                    } else if (peek_char() == '*' && peek_char(1) == '/') {
                        advance(), advance();
                        --depth;
                    } else {
                        advance();
                    }
                }
            } else {
                return;
            }
        }
    }

    std::string lex_identifier() {
        const std::size_t begin = state_.pos;
        while (!at_end() && is_ident_char(peek_char())) advance();
        return text_.substr(begin, state_.pos - begin);
    }

    Token lex_number(Token t) {
        const std::size_t begin = state_.pos;
        while (is_digit(peek_char())) advance();
        if (peek_char() == '.') {
            advance();
            while (is_digit(peek_char())) advance();
        }
        auto bad = [&](const std::string& expected) {
            std::size_t end = state_.pos;
            while (end < text_.size() && (is_ident_char(text_[end]) || text_[end] == '.')) ++end;
            throw Error(t.location, "bad number `" + text_.substr(begin, end - begin) + "`: expected " + expected +
                                        ", found " + char_description());
        };
        if (peek_char() == 'e' || peek_char() == 'E') {
            advance();
            if (peek_char() == '+' || peek_char() == '-') advance();
            if (!is_digit(peek_char())) bad("digits after the exponent");
            while (is_digit(peek_char())) advance();
        }
        if (is_ident_char(peek_char()) || (peek_char() == '.' && is_digit(peek_char(1))))
            bad("an operator, `,` or a space after the number");
        t.kind = TokenKind::number;
        t.text = text_.substr(begin, state_.pos - begin);
        const char* first = text_.data() + begin;
        const char* last = text_.data() + state_.pos;
        const auto [ptr, ec] = std::from_chars(first, last, t.number);
        if (ec == std::errc::result_out_of_range)
            throw Error(t.location, "bad number `" + t.text + "`: out of the range of a double");
        if (ec != std::errc() || ptr != last) throw Error(t.location, "bad number `" + t.text + "`");
        return t;
    }

    Token lex_string(Token t) {
        advance();
        std::string s;
        for (;;) {
            if (at_end() || peek_char() == '\n')
                throw Error(t.location, "unterminated string: expected `\"` before the end of the line, found " +
                                            char_description());
            const char c = peek_char();
            advance();
            if (c == '"') break;
            if (c == '\\' && !at_end() && peek_char() != '\n') {
                const char e = peek_char();
                advance();
                s += e == 'n' ? '\n' : (e == 't' ? '\t' : e);
            } else {
                s += c;
            }
        }
        t.kind = TokenKind::string;
        t.text = std::move(s);
        return t;
    }

    std::shared_ptr<const SourceFile> file_;
    const std::string& text_;
    State state_;
    State last_end_{0, 1, 1};
};

}  // namespace photon::dsl
