// SPDX-License-Identifier: MIT
#pragma once
// Directives other than `#include`: #declare/#local/#undef, #if/#ifdef/#ifndef/#else/#elseif,
// #while, #default and the messages. They are run in the token stream (peek), so they may appear
// anywhere, as in POV-Ray.

#include "parser_class.hpp"

namespace photon::dsl::detail {

inline void Parser::directive(const Token& d) {
    // A directive's arguments may start another directive (`#undef #undef ...`, a `#while`
    // whose `#end` re-reads the condition); bounded like any nesting, so that no chain of
    // them can overflow the stack.
    const Nest nest(*this, d.location);
    ++statements_;
    const std::string& name = d.text;
    if (name == "declare" || name == "local") {
        directive_declare(d, name == "local");
    } else if (name == "undef") {
        const Token id = next();
        if (id.kind != TokenKind::identifier) fail_expected("an identifier after `#undef`", id);
        for (auto& scope : scopes_) scope.erase(id.text);
    } else if (name == "version") {
        ++suppress_;
        const SourceLocation at = peek().location;
        const double v = to_float(parse_expression_for("the language version"), "the language version", at);
        --suppress_;
        version_ = v;
        scene_.version = v;
        if (v < 3.5) warn(at, "#version " + format_number(v) + ": photon reads scenes with POV-Ray 3.7's rules");
        accept_symbol(";");
    } else if (name == "include") {
        directive_include(d);
    } else if (name == "if" || name == "ifdef" || name == "ifndef") {
        bool guard = false;
        const bool cond =
            name == "if" ? parse_condition(d, guard) : parse_defined_condition(d, name == "ifndef", guard);
        start_if(d, cond, guard);
    } else if (name == "else" || name == "elseif") {
        if (conds_.empty() || conds_.back().file_depth != files_.size() || conds_.back().kind != CondKind::if_)
            fail(d.location, "`#" + name + "` without a matching `#if`");
        skip_branch(conds_.back().at, "#if", false);
        conds_.pop_back();
    } else if (name == "end") {
        if (conds_.empty() || conds_.back().file_depth != files_.size())
            fail(d.location, "`#end` without a matching `#if`, `#ifdef`, `#ifndef` or `#while`");
        CondFrame frame = conds_.back();
        conds_.pop_back();
        if (frame.kind == CondKind::while_) loop_again(frame);
    } else if (name == "while") {
        const Lexer::State start = files_.back().lexer.state();
        bool guard = false;
        if (parse_condition(d, guard)) {
            conds_.push_back({CondKind::while_, files_.size(), d.location, start, guard, 0});
        } else {
            skip_branch(d.location, "#while", false);
        }
    } else if (name == "warning" || name == "debug" || name == "error") {
        const Token s = next();
        if (s.kind != TokenKind::string) fail_expected("a string in double quotes after `#" + name + "`", s);
        if (name == "error") fail(d.location, "#error: " + s.text);
        if (name == "warning") warn(d.location, "#warning: " + s.text);
    } else if (name == "default") {
        directive_default(d);
    } else if (one_of(name, {"macro", "switch", "case", "range", "break", "for", "fopen", "fclose", "read", "write",
                             "statistics", "render"})) {
        fail(d.location, "`#" + name + "` is not supported by photon's scene language (see docs/scene-language.md)");
    } else {
        fail(d.location,
             "unknown directive `#" + name + "`" +
                 suggest(name, {"declare", "local", "undef", "include", "if", "ifdef", "ifndef", "else", "elseif",
                                "end", "while", "version", "warning", "error", "debug", "default"}));
    }
}

inline bool Parser::is_reserved(std::string_view w) const {
    return one_of(w, object_keywords) || one_of(w, unsupported_objects) || one_of(w, color_keywords) ||
           one_of(w, constants) || one_of(w, functions) || one_of(w, modifier_keywords) || one_of(w, finish_keywords) ||
           one_of(w, camera_keywords) || one_of(w, global_keywords) || one_of(w, light_keywords) ||
           one_of(w, other_keywords);
}

inline void Parser::declare_global(const std::string& name, ValueData v, const SourceLocation& at) {
    scopes_.front()[name] = Value{std::move(v), at};
}

inline const Value* Parser::lookup(const std::string& name) const {
    for (auto it = scopes_.rbegin(); it != scopes_.rend(); ++it) {
        auto f = it->find(name);
        if (f != it->end()) return &f->second;
    }
    return nullptr;
}

inline void Parser::directive_declare(const Token& d, bool local) {
    const Token id = next();
    if (id.kind != TokenKind::identifier) fail_expected("an identifier after `#" + d.text + "`", id);
    if (is_reserved(id.text)) fail(id.location, "cannot #" + d.text + " `" + id.text + "`: it is a keyword");
    expect_symbol("=", "after `#" + d.text + " " + id.text + "`");
    auto store = [&](ValueData v) {
        auto& scope = local ? scopes_.back() : scopes_.front();
        scope[id.text] = Value{std::move(v), id.location};
    };
    const Token t = peek();
    if (t.kind == TokenKind::identifier) {
        const std::string& w = t.text;
        std::optional<ValueData> block;
        if (w == "texture")
            block = parse_texture(next(), default_texture_);
        else if (w == "pigment")
            block = parse_pigment(next(), Pigment{});
        else if (w == "finish")
            block = parse_finish(next(), Finish{});
        else if (w == "interior")
            block = parse_interior(next(), Interior{});
        else if (w == "transform")
            block = parse_transform_block(next());
        else if (w == "camera")
            block = parse_camera(next());
        else if (is_object_keyword(w)) {
            block = parse_object(next());
        } else if (one_of(w, blend_map_keywords)) {
            block = parse_blend_map(next());
        } else if (one_of(w, {"fog", "rainbow", "sky_sphere", "media", "normal", "density"})) {
            // Read (so that its errors show), kept so that its use by name is known; the warning
            // comes where it is used.
            const Nest nest(*this, t.location);
            skip_block(next());
            block = IgnoredBlock{w};
        } else if (const Value* v = lookup(w); v && !std::holds_alternative<Numeric>(v->data)) {
            next();
            block = v->data;
        }
        if (block) {
            store(std::move(*block));
            accept_symbol(";");
            return;
        }
    }
    if (t.kind == TokenKind::string) {
        next();
        store(t.text);
        expect_symbol(";", "after the value of `" + id.text + "`");
        return;
    }
    ++suppress_;
    const Numeric n = parse_expression_for("the value of `" + id.text + "`");
    --suppress_;
    store(n);
    ++suppress_;
    const Token after = peek();
    --suppress_;
    if (!after.is_symbol(";"))
        fail(after.location, "expected `;` after the value of `" + id.text + "`, found " + describe(after));
    next();
}

/// `( expression )` after #if, #elseif or #while. Directives are not run inside it (as in
/// POV-Ray): `#if #end` is an error here, not an `#end` that re-enters a loop's condition.
inline bool Parser::parse_condition(const Token& d, bool& guard) {
    ++suppress_;
    expect_symbol("(", "after `#" + d.text + "`");
    const bool saved = mentions_photon_version_;
    mentions_photon_version_ = false;
    const SourceLocation at = peek().location;
    const double v = to_float(parse_expression_for("a condition"), "a condition", at);
    guard = mentions_photon_version_;
    mentions_photon_version_ = saved;
    expect_symbol(")", "to close the condition of `#" + d.text + "`");
    --suppress_;
    return v != 0.0;
}

inline bool Parser::parse_defined_condition(const Token& d, bool negate, bool& guard) {
    ++suppress_;
    expect_symbol("(", "after `#" + d.text + "`");
    const Token id = next();
    if (id.kind != TokenKind::identifier) fail_expected("an identifier in `#" + d.text + " ( )`", id);
    expect_symbol(")", "after the identifier of `#" + d.text + "`");
    --suppress_;
    guard = id.text == "photon_version";
    return (lookup(id.text) != nullptr) != negate;
}

inline void Parser::start_if(const Token& d, bool cond, bool guard) {
    for (;;) {
        if (cond) {
            conds_.push_back({CondKind::if_, files_.size(), d.location, {}, guard, 0});
            return;
        }
        const Token stop = skip_branch(d.location, "#" + d.text, true);
        if (stop.text == "end") return;
        if (stop.text == "else") {
            cond = true;
            continue;
        }
        bool g = false;
        cond = parse_condition(stop, g);
        guard = guard || g;
    }
}

/// Skips the current file's tokens up to the `#end` (or, with `stop_at_else`, an `#else` or
/// `#elseif`) that belongs to the directive opened at `opened`; returns that directive.
inline Token Parser::skip_branch(const SourceLocation& opened, const std::string& what, bool stop_at_else) {
    int depth = 0;
    for (;;) {
        if (++tokens_ > options_.max_tokens)
            fail(opened, "the scene is too long: more than " + std::to_string(options_.max_tokens) + " tokens read");
        Token t = files_.back().lexer.next();
        if (t.kind == TokenKind::end_of_file)
            fail(t.location,
                 "expected `#end` to close the `" + what + "` opened at " + position(opened) + ", found end of file");
        if (t.kind != TokenKind::directive) continue;
        if (one_of(t.text, {"if", "ifdef", "ifndef", "while", "switch", "macro", "for"})) {
            ++depth;
        } else if (t.text == "end") {
            if (depth == 0) return t;
            --depth;
        } else if (depth == 0 && stop_at_else && (t.text == "else" || t.text == "elseif")) {
            return t;
        }
    }
}

inline void Parser::loop_again(CondFrame frame) {
    if (++frame.iterations > options_.max_loop_iterations)
        fail(frame.at, "`#while` loop ran more than " + std::to_string(options_.max_loop_iterations) +
                           " times: is its condition ever false?");
    files_.back().lexer.restore(frame.loop_start);
    const Token w{TokenKind::directive, "while", 0, frame.at};
    bool guard = false;
    if (parse_condition(w, guard)) {
        conds_.push_back(frame);
    } else {
        skip_branch(frame.at, "#while", false);
    }
}

inline bool Parser::in_photon_guard() const {
    return std::any_of(conds_.begin(), conds_.end(), [](const CondFrame& c) { return c.photon_guard; });
}

inline void Parser::directive_default(const Token& d) {
    open_block(d);
    for (;;) {
        const Token t = peek();
        if (t.is_identifier("texture"))
            default_texture_ = parse_texture(next(), default_texture_);
        else if (t.is_identifier("pigment"))
            default_texture_.pigment = parse_pigment(next(), default_texture_.pigment);
        else if (t.is_identifier("finish"))
            default_texture_.finish = parse_finish(next(), default_texture_.finish);
        else
            break;
    }
    close_block(d, "`texture`, `pigment` or `finish`", {"texture", "pigment", "finish"});
}

}  // namespace photon::dsl::detail
