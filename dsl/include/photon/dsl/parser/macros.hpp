// SPDX-License-Identifier: MIT
#pragma once
// Macros, as POV-Ray runs them: `#macro` records where the body is; a call `NAME(args)`, met
// anywhere in the token stream, binds the arguments in a new scope and reads the body as a frame
// of its own, up to the macro's `#end`, so a macro gives whatever tokens its body holds (a float,
// a vector, an object, a whole block's worth).

#include "parser_class.hpp"

namespace photon::dsl::detail {

// MACRO: #macro IDENTIFIER ( [[optional] PARAM {, [optional] PARAM}] ) TOKENS #end
inline void Parser::directive_macro(const Token& d) {
    auto m = std::make_shared<Macro>();
    Token name;
    {
        const ReadingName reading(*this);
        name = next();
        if (name.kind != TokenKind::identifier) fail_expected("a macro name after `#macro`", name);
        if (is_reserved(name.text)) fail(name.location, "cannot name a macro `" + name.text + "`: it is a keyword");
        if (const auto f = scopes_.front().find(name.text); f != scopes_.front().end())
            fail(name.location, "cannot define the macro `" + name.text + "`: it is declared at " +
                                    position_in(f->second.at, name.location) + "; `#undef` it first");
        expect_symbol("(", "after the macro name `" + name.text + "`");
        while (!peek().is_symbol(")")) {
            bool optional = false;
            Token p = next();
            if (p.is_identifier("optional")) optional = true, p = next();
            if (p.kind != TokenKind::identifier || p.text.find('[') != std::string::npos || is_reserved(p.text))
                fail_expected("a parameter name in the macro `" + name.text + "`", p);
            if (std::find(m->params.begin(), m->params.end(), p.text) != m->params.end())
                fail(p.location, "the macro `" + name.text + "` has two parameters named `" + p.text + "`");
            m->params.push_back(p.text);
            m->optional.push_back(optional);
            if (!accept_symbol(",") && !peek().is_symbol(")"))
                fail_expected("`,` or `)` in the parameters of the macro `" + name.text + "`", peek());
        }
    }
    next();  // `)`: the body starts right after it
    m->name = name.text;
    m->at = name.location;
    m->file = files_.back().lexer.file();
    m->path = files_.back().path;
    Lexer& lexer = files_.back().lexer;
    m->body = lexer.state();
    int depth = 0;
    for (;;) {
        if (++tokens_ > options_.max_tokens)
            fail(d.location, "the scene is too long: more than " + std::to_string(options_.max_tokens) + " tokens read");
        const Lexer::State before = lexer.state();
        if (files_.back().macro && before.pos >= files_.back().macro->body_end)
            fail(d.location, "expected `#end` to close the `#macro` opened at " + position(d.location) +
                                 ", found the end of the macro `" + files_.back().macro->name + "` it is in");
        const Token t = lexer.next();
        if (t.kind == TokenKind::end_of_file)
            fail(t.location, "expected `#end` to close the `#macro` opened at " + position(d.location) +
                                 ", found end of file");
        if (t.kind != TokenKind::directive) continue;
        if (one_of(t.text, {"if", "ifdef", "ifndef", "while", "switch", "macro", "for"})) {
            ++depth;
        } else if (t.text == "end" && depth-- == 0) {
            m->body_end = before.pos;
            break;
        }
    }
    macros_[m->name] = std::move(m);
}

/// MACRO_CALL: IDENTIFIER ( [ARG {, ARG}] ) when IDENTIFIER names a macro (and no identifier of
/// an inner scope hides it). Returns false for other identifiers.
inline bool Parser::try_invoke_macro(const Token& t) {
    const auto found = macros_.find(t.text);
    if (found == macros_.end() || lookup(t.text)) return false;
    const std::shared_ptr<const Macro> m = found->second;  // the call keeps it if the body redefines it
    const Nest nest(*this, t.location);
    if (macro_depth_ >= options_.max_macro_depth)
        fail(t.location, "macro calls nested too deep: more than " + std::to_string(options_.max_macro_depth) +
                             " running inside each other (does `" + m->name + "` call itself without end?)");
    if (!peek().is_symbol("("))
        fail_expected("`(` after the macro name `" + m->name + "` (defined at " + position_in(m->at, t.location) + ")",
                      peek());
    next();
    // All arguments are read before the new scope opens, so that a recursive call sees the
    // caller's identifiers (POV-Ray's rule).
    std::unordered_map<std::string, Value> scope;
    for (std::size_t i = 0; i < m->params.size(); ++i) {
        // POV-Ray reads an optional comma after each argument (Parse_Comma), so `M(A -y)` is two.
        if (i > 0 && !accept_symbol(",") &&
            !(starts_expression(peek()) || peek().kind == TokenKind::identifier || peek().kind == TokenKind::string)) {
            if (peek().is_symbol(")") && std::all_of(m->optional.begin() + std::ptrdiff_t(i), m->optional.end(),
                                                     [](bool o) { return o; }))
                break;
            fail_expected("`,` and argument " + std::to_string(i + 1) + " (`" + m->params[i] + "`) of the macro `" +
                              m->name + "`, which takes " + std::to_string(m->params.size()),
                          peek());
        }
        bind_argument(*m, i, scope);
    }
    if (!peek().is_symbol(")"))
        fail_expected("`)` to close the call of the macro `" + m->name + "`, which takes " +
                          std::to_string(m->params.size()) + " argument" + (m->params.size() == 1 ? "" : "s"),
                      peek());
    next();
    Lexer body(m->file);
    body.restore(m->body);
    files_.push_back({std::move(body), m->path, m, t.location});
    scopes_.push_back(std::move(scope));
    ++macro_depth_;
    return true;
}

/// ARG: IDENTIFIER (by reference, when it is the whole argument) | RVALUE (by value) | nothing
/// (for an optional parameter).
inline void Parser::bind_argument(const Macro& m, std::size_t i, std::unordered_map<std::string, Value>& scope) {
    const Token& t = peek();
    if ((t.is_symbol(",") || t.is_symbol(")")) && m.optional[i]) return;
    if (t.kind == TokenKind::identifier && lookup(t.text)) {
        // A bare identifier: look one raw token ahead without reading it.
        Lexer probe = files_.back().lexer;
        const bool at_body_end = files_.back().macro && probe.state().pos >= files_.back().macro->body_end;
        const Token after = at_body_end ? Token{} : probe.next();
        if (after.is_symbol(",") || after.is_symbol(")")) {
            std::size_t s = scopes_.size();
            while (s-- > 0 && !lookup_in(s, t.text)) {
            }
            // Point at the identifier itself, or at what it refers to in turn.
            std::string name = t.text;
            for (auto f = scopes_[s].find(name); f != scopes_[s].end() && f->second.is_reference();
                 f = scopes_[s].find(name)) {
                const std::size_t to = f->second.ref_scope;
                name = f->second.ref_name;
                s = to;
            }
            Value ref{Numeric{}, t.location};
            ref.ref_scope = s;
            ref.ref_name = name;
            scope[m.params[i]] = std::move(ref);
            next();
            return;
        }
    }
    const SourceLocation at = t.location;
    bool needs_semicolon = false;
    scope[m.params[i]] = Value{parse_rvalue("argument " + std::to_string(i + 1) + " (`" + m.params[i] +
                                                "`) of the macro `" + m.name + "`",
                                            needs_semicolon),
                               at};
}

/// The body's tokens are all read: back to the caller, closing the call's scope.
inline void Parser::return_from_macro() {
    const FileFrame& f = files_.back();
    if (!conds_.empty() && conds_.back().file_depth == files_.size()) {
        const CondFrame& c = conds_.back();
        const char* kinds[] = {"#if", "#while", "#for", "#switch"};
        fail(c.at, "expected `#end` to close the `" + std::string(kinds[int(c.kind)]) +
                       "` before the end of the macro `" + f.macro->name + "`");
    }
    files_.pop_back();
    scopes_.pop_back();
    --macro_depth_;
}

/// " (in macro `M` called at file:line:column, ...)" for an error inside macro bodies.
inline std::string Parser::macro_trace() const {
    std::string trace;
    int shown = 0, more = 0;
    for (auto it = files_.rbegin(); it != files_.rend(); ++it) {
        if (!it->macro) continue;
        if (shown == 4) {
            ++more;
            continue;
        }
        trace += std::string(shown++ ? ", " : " (") + "in macro `" + it->macro->name + "` called at " +
                 it->called_at.str();
    }
    if (more) trace += ", and " + std::to_string(more) + " more calls";
    return trace.empty() ? trace : trace + ")";
}

}  // namespace photon::dsl::detail
