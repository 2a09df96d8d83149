// SPDX-License-Identifier: MIT
#pragma once
// POV-Ray's data-file directives: #fopen, #read, #write, #fclose. A file the scene writes is
// kept in memory for the rest of the read (an `#include` or `#fopen ... read` of that name finds
// it there) and never reaches the disk: reading a scene has no side effects, and POV-Ray's own
// idiom of writing text and including it (strings.inc's Parse_String) still works. Reading and
// writing are checked against the I/O restrictions all the same (scene_files.hpp), so a scene
// that photon reads is one POV-Ray reads under the same povray.conf.

#include <cctype>
#include <cstdio>
#include <cstdlib>

#include "parser_class.hpp"

namespace photon::dsl::detail {

/// POV-Ray's `%g`, as #write prints numbers.
inline std::string pov_g(double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%g", v);
    return buf;
}

// FOPEN: #fopen FILE_ID STRING (read | write | append)
inline void Parser::directive_fopen(const Token& d) {
    const Token id = next();
    if (id.kind != TokenKind::identifier || is_reserved(id.text))
        fail_expected("an identifier for the file after `#fopen`", id);
    const Token name = parse_string_token("a file name (a string) after `#fopen " + id.text + "`");
    const Token mode = next();
    if (!mode.is_identifier("read") && !mode.is_identifier("write") && !mode.is_identifier("append"))
        fail_expected("`read`, `write` or `append` after the file name", mode);
    OpenFile f;
    f.name = name.text;
    f.writing = mode.text != "read";
    if (f.writing && !options_.read_include) check_writable(name);
    if (mode.text == "write") written_files_[f.name].clear();
    if (!f.writing) {
        if (const auto it = written_files_.find(f.name); it != written_files_.end()) {
            f.text = it->second;
        } else if (options_.read_include) {
            auto text = options_.read_include(f.name);
            if (!text) fail(name.location, "cannot find the data file \"" + f.name + "\"");
            f.text = std::move(*text);
        } else {
            const std::filesystem::path found = find_readable(search_places(f.name, true), name);
            if (found.empty()) fail(name.location, "cannot find the data file \"" + f.name + "\"");
            f.text = load(found, f.name, name.location)->text;
        }
    }
    (void)d;
    open_files_[id.text] = std::move(f);
    assign(id, std::string("file \"" + name.text + "\""), false);
}

// The file #fopen opened as `id`, else an error in `#directive`.
inline Parser::OpenFile& Parser::open_file(const Token& id, const std::string& directive) {
    const auto it = id.kind == TokenKind::identifier ? open_files_.find(id.text) : open_files_.end();
    if (it == open_files_.end()) fail_expected("a file opened with `#fopen` in `#" + directive + "`", id);
    return it->second;
}

// Forgets the file `id` and its identifier, in every scope.
inline void Parser::close_file(const std::string& id) {
    open_files_.erase(id);
    for (auto& scope : scopes_) scope.erase(id);
}

// FCLOSE: #fclose FILE_ID
inline void Parser::directive_fclose(const Token& d) {
    const Token id = next();
    if (id.kind != TokenKind::identifier) fail_expected("a file identifier after `#fclose`", id);
    (void)d;
    if (open_files_.count(id.text)) close_file(id.text);  // closing a closed file is harmless, as in POV-Ray
}

// WRITE: #write ( FILE_ID {[,] ITEM} )   ITEM: STRING | FLOAT | VECTOR
inline void Parser::directive_write(const Token& d) {
    suppress_.push_back(files_.size());
    expect_symbol("(", "after `#write`");
    const Token id = next();
    OpenFile& f = open_file(id, "write");
    if (!f.writing) fail(id.location, "cannot #write to \"" + f.name + "\": it is open for reading");
    std::string out;
    // POV-Ray's commas here are optional (Parse_Comma): `#write (F Header)` is read too.
    for (;;) {
        accept_symbol(",");
        if (peek().is_symbol(")")) break;
        const Token& t = peek();
        if (t.kind == TokenKind::identifier &&
            one_of(t.text, {"uint8", "sint8", "uint16be", "uint16le", "sint16be", "sint16le", "sint32be", "sint32le"}))
            fail(t.location, "binary `#write` (`" + t.text + "`) is not supported by photon: write text");
        if (starts_string(t)) {
            out += parse_string_expression("a string to #write");
            continue;
        }
        const Numeric n = parse_expression_for("a string, number or vector to #write");
        if (n.dim == 0) {
            out += pov_g(n.c[0]);
        } else {
            out += "<";
            for (int i = 0; i < n.dim; ++i) out += (i ? "," : "") + pov_g(n.c[std::size_t(i)]);
            out += "> ";
        }
    }
    expect_symbol(")", "to close `#write`");
    suppress_.pop_back();
    (void)d;
    std::string& file = written_files_[f.name];
    if (file.size() + out.size() > options_.max_file_bytes)
        fail(id.location, "#write: \"" + f.name + "\" would grow past " + std::to_string(options_.max_file_bytes) +
                              " bytes");
    charge_bytes(out.size(), id.location);
    file += out;
}

// READ: #read ( FILE_ID {, IDENTIFIER} ). At the end of the file the file
// identifier becomes undefined (POV-Ray's `#while (defined(F)) #read (F, V) ... #end`).
inline void Parser::directive_read(const Token& d) {
    suppress_.push_back(files_.size());
    expect_symbol("(", "after `#read`");
    const Token id = next();
    OpenFile& f = open_file(id, "read");
    if (f.writing) fail(id.location, "cannot #read from \"" + f.name + "\": it is open for writing");
    bool at_end = false;
    while (accept_symbol(",")) {
        const Token var = next();
        if (var.kind != TokenKind::identifier || is_reserved(var.text))
            fail_expected("an identifier to read into", var);
        if (at_end) continue;
        // Items are separated by commas and white space, as POV-Ray writes them.
        auto skip = [&] {
            while (f.pos < f.text.size() && (std::isspace(static_cast<unsigned char>(f.text[f.pos])) || f.text[f.pos] == ','))
                ++f.pos;
        };
        auto number = [&]() -> std::optional<double> {
            skip();
            const char* begin = f.text.c_str() + f.pos;
            char* end = nullptr;
            const double v = std::strtod(begin, &end);
            if (end == begin || !std::isfinite(v)) return std::nullopt;
            f.pos += std::size_t(end - begin);
            return v;
        };
        skip();
        if (f.pos >= f.text.size()) {
            at_end = true;
            continue;
        }
        const char c = f.text[f.pos];
        if (c == '"') {
            std::string s;
            ++f.pos;
            while (f.pos < f.text.size() && f.text[f.pos] != '"') {
                if (f.text[f.pos] == '\\' && f.pos + 1 < f.text.size()) ++f.pos;
                s += f.text[f.pos++];
            }
            if (f.pos >= f.text.size()) fail(var.location, "#read: unterminated string in \"" + f.name + "\"");
            ++f.pos;
            assign(var, s, false);
        } else if (c == '<') {
            ++f.pos;
            Numeric n;
            while (const auto v = number()) {
                if (n.dim == 5) fail(var.location, "#read: a vector in \"" + f.name + "\" has more than 5 components");
                n.c[std::size_t(n.dim++)] = *v;
            }
            skip();
            if (f.pos >= f.text.size() || f.text[f.pos] != '>' || n.dim < 2)
                fail(var.location, "#read: expected a vector `<a, b, ...>` in \"" + f.name + "\"");
            ++f.pos;
            assign(var, n, false);
        } else if (const auto v = number()) {
            assign(var, Numeric::scalar(*v), false);
        } else {
            fail(var.location, "#read: expected a number, a vector or a string in \"" + f.name + "\", found `" +
                                   std::string(1, c) + "`");
        }
    }
    expect_symbol(")", "to close `#read`");
    suppress_.pop_back();
    (void)d;
    // POV-Ray undefines the file as soon as its last item is read.
    while (f.pos < f.text.size() && (std::isspace(static_cast<unsigned char>(f.text[f.pos])) || f.text[f.pos] == ','))
        ++f.pos;
    if (at_end || f.pos >= f.text.size()) close_file(id.text);
}

}  // namespace photon::dsl::detail
