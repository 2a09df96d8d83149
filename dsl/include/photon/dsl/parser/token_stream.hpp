// SPDX-License-Identifier: MIT
#pragma once
// Token stream: the files being read (and macro bodies, read as frames of their own), `#include`,
// tokens with one of lookahead, and blocks. Macro calls and array elements are resolved here, as
// POV-Ray's tokenizer does, so they may come wherever a token may.

#include "parser_class.hpp"

namespace photon::dsl::detail {

// Every error is thrown from here, with the chain of macro calls it is inside.
inline void Parser::fail(const SourceLocation& at, std::string message) const {
    throw Error(at, std::move(message) + macro_trace());
}

// The usual error: what was expected, what was found, and a hint (a suggestion) if any.
inline void Parser::fail_expected(const std::string& expected, const Token& found, const std::string& hint) const {
    fail(found.location, "expected " + expected + ", found " + describe(found) + hint);
}

// A warning, once for each place and message (a loop must not repeat it), to ParseOptions::diagnostics.
inline void Parser::warn(const SourceLocation& at, const std::string& message, Severity severity) {
    if (!warned_.insert(at.str() + '\x1f' + message).second) return;
    if (options_.diagnostics) options_.diagnostics({severity, at, message, {}, {}});
}

// The message for a file over ParseOptions::max_file_bytes.
inline std::string Parser::too_large_message(std::size_t bytes) const {
    return "file too large: " + std::to_string(bytes) + " bytes, photon reads scene files of at most " +
           std::to_string(options_.max_file_bytes) + " bytes";
}

// The path an included file is known by, for include loops; absolute when it cannot be made canonical.
inline std::filesystem::path Parser::weakly_canonical(const std::filesystem::path& p) {
    std::error_code ec;
    auto c = std::filesystem::weakly_canonical(p, ec);
    return ec ? std::filesystem::absolute(p) : c;
}

// A scene file read whole, within the size bounds; `from` is the #include naming it (unknown for the
// main file).
inline std::shared_ptr<const SourceFile> Parser::load(const std::filesystem::path& path, std::string name,
                                                      const SourceLocation& from) {
    std::error_code ec;
    const SourceLocation where =
        from.known() ? from : SourceLocation{std::make_shared<SourceFile>(SourceFile{name, {}}), 0, 0};
    if (std::filesystem::is_directory(path, ec)) fail(where, "cannot read \"" + name + "\": it is a directory");
    const auto size = std::filesystem::file_size(path, ec);
    if (ec) fail(where, "cannot open \"" + name + "\": " + ec.message());
    if (size > options_.max_file_bytes) fail(where, too_large_message(std::size_t(size)));
    charge_bytes(size, where);
    std::ifstream in(path, std::ios::binary);
    if (!in) fail(where, "cannot open \"" + name + "\"");
    std::string text(std::size_t(size), '\0');
    in.read(text.data(), std::streamsize(size));
    if (!in) fail(where, "cannot read \"" + name + "\"");
    return std::make_shared<SourceFile>(SourceFile{std::move(name), std::move(text)});
}

// INCLUDE: #include STRING   (a file the scene wrote, else one read through ParseOptions::read_include,
// else one found beside the including file or in the include paths)
inline void Parser::directive_include(const Token& d) {
    const Token s = parse_string_token("a file name in double quotes after `#include`");
    if (files_.size() >= options_.max_include_depth)
        fail(s.location, "includes nested too deep: more than " + std::to_string(options_.max_include_depth) +
                             " files open at once");
    namespace fs = std::filesystem;
    // A file the scene wrote itself (`#fopen ... write`) is kept in memory: read it from there.
    if (const auto it = written_files_.find(s.text); it != written_files_.end()) {
        push_included_text(s, it->second, fs::path("<written>") / s.text);
        return;
    }
    if (options_.read_include) {
        include_from_reader(s);
        return;
    }
    const fs::path name(s.text);
    const std::vector<fs::path> candidates = search_places(name, true);
    const fs::path found = find_readable(candidates, s);
    if (found.empty()) {
        std::string where;
        for (const auto& c : candidates)
            where += (where.empty() ? "" : ", ") + c.parent_path().lexically_normal().string();
        // POV-Ray's standard includes are the usual miss: say where photon finds them.
        const bool pov_include = name.extension() == ".inc";
        fail(s.location, "cannot find the include file \"" + s.text + "\" (looked in " + where + ")" +
                             (pov_include ? "; POV-Ray's standard includes come with POV-Ray (Debian: povray-includes, "
                                            "read from /usr/share/povray-3.7/include), or name their folder with -I "
                                            "or PHOTON_INCLUDE_PATH"
                                          : ""));
    }
    check_include_loop(found, s);
    (void)d;
    std::error_code ec;
    std::string display = found.string();
    if (const auto rel = fs::proximate(found, ec); !ec && !rel.empty() && rel.native().rfind("..", 0) != 0)
        display = rel.lexically_normal().string();
    auto file = load(found, display, s.location);
    scene_.files.push_back(file);
    files_.push_back({Lexer(file), found, nullptr, {}});
    scopes_.emplace_back();
}

/// `#include` through ParseOptions::read_include: the name alone identifies the file.
inline void Parser::include_from_reader(const Token& s) {
    const std::filesystem::path key = std::filesystem::path("<memory>") / s.text;
    std::optional<std::string> text = options_.read_include(s.text);
    if (!text) fail(s.location, "cannot find the include file \"" + s.text + "\"");
    push_included_text(s, std::move(*text), key);
}

/// Reads `text` in place of the `#include` at `s`; `key` identifies it for include loops.
inline void Parser::push_included_text(const Token& s, std::string text, const std::filesystem::path& key) {
    check_include_loop(key, s);
    if (text.size() > options_.max_file_bytes) fail(s.location, too_large_message(text.size()));
    charge_bytes(text.size(), s.location);
    auto file = std::make_shared<SourceFile>(SourceFile{s.text, std::move(text)});
    scene_.files.push_back(file);
    files_.push_back({Lexer(file), key, nullptr, {}});
    scopes_.emplace_back();
}

/// Counts `bytes` of the scene's data made, failing at `at` past ParseOptions::max_parse_bytes.
inline void Parser::charge_bytes(std::uint64_t bytes, const SourceLocation& at) {
    parse_bytes_ += bytes;
    if (parse_bytes_ > options_.max_parse_bytes)
        fail(at, "the scene's data is too large: more than " + std::to_string(options_.max_parse_bytes) +
                     " bytes of file text, strings, arrays and written files made while it is read");
}

// Fails when `canonical` is a file already being read (not a macro body): an include loop.
inline void Parser::check_include_loop(const std::filesystem::path& canonical, const Token& s) const {
    for (std::size_t i = 0; i < files_.size(); ++i)
        if (!files_[i].macro && files_[i].path == canonical) {
            std::string chain;
            for (std::size_t j = i; j < files_.size(); ++j) chain += files_[j].lexer.file()->name + " includes ";
            fail(s.location, "include loop: " + chain + "\"" + s.text + "\" again");
        }
}

// The next token of the innermost frame, leaving macro bodies and included files at their end,
// within max_tokens and max_parse_seconds. Directives and macro calls are run by peek, not here.
inline Token Parser::raw_token() {
    for (;;) {
        if (++tokens_ > options_.max_tokens) {
            const Lexer& lexer = files_.back().lexer;
            fail({lexer.file(), lexer.state().line, lexer.state().column},
                 "the scene is too long: more than " + std::to_string(options_.max_tokens) + " tokens read");
        }
        // The clock every 1024 tokens: reading it costs more than a token.
        if ((tokens_ & 1023) == 0 && options_.max_parse_seconds > 0 &&
            std::chrono::duration<double>(std::chrono::steady_clock::now() - started_).count() > options_.max_parse_seconds) {
            const Lexer& lexer = files_.back().lexer;
            fail({lexer.file(), lexer.state().line, lexer.state().column},
                 "the scene takes too long to read: more than " + format_number(options_.max_parse_seconds) +
                     " seconds (max_parse_seconds, the photon program's --max-parse-seconds)");
        }
        if (const FileFrame& f = files_.back(); f.macro && f.lexer.state().pos >= f.macro->body_end) {
            return_from_macro();
            continue;
        }
        Token t = files_.back().lexer.next();
        if (t.kind != TokenKind::end_of_file) return t;
        if (!conds_.empty() && conds_.back().file_depth == files_.size()) {
            const CondFrame& c = conds_.back();
            const char* kinds[] = {"#if", "#while", "#for", "#switch"};
            fail(t.location, "expected `#end` to close the `" + std::string(kinds[int(c.kind)]) + "` opened at " +
                                 position(c.at) + ", found end of file");
        }
        if (files_.size() == 1) return t;
        files_.pop_back();
        scopes_.pop_back();
    }
}

// line:column, for a message about the same file.
inline std::string Parser::position(const SourceLocation& at) {
    return std::to_string(at.line) + ":" + std::to_string(at.column);
}

// `at` as line:column when it is in the file of `from`, else with its file name.
inline std::string Parser::position_in(const SourceLocation& at, const SourceLocation& from) const {
    if (at.file == from.file) return position(at);
    return at.str();
}

/// Directives are not run while reading a condition or a declared value, unless they are in the
/// body of a macro called there.
inline bool Parser::suppressed() const { return !suppress_.empty() && suppress_.back() == files_.size(); }

// The next token, once the directives (unless suppressed) and macro calls before it have run; an
// array element `A[i]` comes as one identifier token.
inline const Token& Parser::peek() {
    for (;;) {
        if (lookahead_) {
            if (lookahead_->kind != TokenKind::directive || suppressed()) return *lookahead_;
            Token d = std::move(*lookahead_);
            lookahead_.reset();
            directive(d);
            continue;
        }
        Token t = raw_token();
        if (t.kind == TokenKind::identifier) {
            if (reading_name_ == 0 && try_invoke_macro(t)) continue;
            expand_array_element(t);
        }
        lookahead_ = std::move(t);
    }
}

// The next token, taken (see peek).
inline Token Parser::next() {
    peek();
    Token t = std::move(*lookahead_);
    lookahead_.reset();
    return t;
}

// OPTIONAL_SYMBOL: [s]; whether it was there.
inline bool Parser::accept_symbol(std::string_view s) {
    if (!peek().is_symbol(s)) return false;
    next();
    return true;
}

// SYMBOL: s, else the error "expected `s` CONTEXT".
inline Token Parser::expect_symbol(std::string_view s, const std::string& context) {
    if (!peek().is_symbol(s)) fail_expected("`" + std::string(s) + "` " + context, peek());
    return next();
}

// OPTIONAL_COMMA: [,]
inline void Parser::optional_comma() { accept_symbol(","); }

/// OPEN_BLOCK: { after a block keyword.
inline void Parser::open_block(const Token& keyword) {
    if (!peek().is_symbol("{")) fail_expected("`{` after `" + keyword.text + "`", peek());
    next();
}

/// CLOSE_BLOCK: } closing the block of `keyword`; `items` names what else could come.
inline void Parser::close_block(const Token& keyword, const std::string& items, Words known) {
    const Token& t = peek();
    if (t.is_symbol("}")) {
        next();
        return;
    }
    const std::string close =
        "`}` to close `" + keyword.text + "` (opened at " + position_in(keyword.location, t.location) + ")";
    if (t.kind == TokenKind::end_of_file) fail_expected(close, t);
    std::string hint;
    if (t.kind == TokenKind::identifier && known.size() > 0) hint = suggest(t.text, known);
    fail_expected(items + " or " + close, t, hint);
}

/// SKIPPED_BLOCK: { balanced tokens } after `kw`, nested blocks included.
inline void Parser::skip_block(const Token& kw) {
    open_block(kw);
    int depth = 1;
    while (depth > 0) {
        const Token t = next();
        if (t.kind == TokenKind::end_of_file)
            fail_expected("`}` to close `" + kw.text + "` (opened at " + position_in(kw.location, t.location) + ")", t);
        if (t.is_symbol("{")) ++depth;
        if (t.is_symbol("}")) --depth;
    }
}

}  // namespace photon::dsl::detail
