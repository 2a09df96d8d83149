// SPDX-License-Identifier: MIT
#pragma once
// Directives other than `#include`: #declare/#local/#undef, #if/#ifdef/#ifndef/#else/#elseif,
// #while, #default and the messages. They are run in the token stream (peek), so they may appear
// anywhere, as in POV-Ray. The identifiers they declare are kept in symbol_table.hpp.

#include "degradation.hpp"
#include "parser_class.hpp"
#include "symbol_table.hpp"

namespace photon::dsl::detail {

// DIRECTIVE: #declare .. | #local .. | #undef IDENTIFIER | #version FLOAT [;] | #include STRING
//   | #if ( FLOAT ) | #ifdef ( IDENTIFIER ) | #ifndef ( IDENTIFIER ) | #elseif ( FLOAT ) | #else | #end
//   | #while ( FLOAT ) | #for (..) | #switch (..) | #case (..) | #range (..) | #break | #macro ..
//   | #warning STRING | #debug STRING | #error STRING | #default { .. } | #fopen .. | #fclose .. | #read (..)
//   | #write (..) | #   (a `#` with no name after it is ignored)
inline void Parser::directive(const Token& d) {
    if (d.text.empty()) {  // a `#` before no directive name: POV-Ray reads on as if it were not there
        warn(d.location, "`#` without a directive name after it is ignored, as POV-Ray does");
        return;
    }
    // A directive's arguments may start another directive (`#undef #undef ...`, a `#while`
    // whose `#end` re-reads the condition); bounded like any nesting, so that no chain of
    // them can overflow the stack.
    const Nest nest(*this, d.location);
    ++statements_;
    // A directive met inside a vector or a block's parameter (`sphere { 0, 1 #if (A = 1) ...`,
    // a macro body called there) reads its own expressions, where comparisons need no parentheses.
    const bool saved_in_vector = in_vector_;
    in_vector_ = false;
    struct Restore {
        bool& flag;
        bool value;
        ~Restore() { flag = value; }
    } restore{in_vector_, saved_in_vector};
    const std::string& name = d.text;
    if (name == "declare" || name == "local") {
        directive_declare(d, name == "local");
    } else if (name == "undef") {
        directive_undef();
    } else if (name == "version") {
        suppress_.push_back(files_.size());
        const SourceLocation at = peek().location;
        const double v = to_float(parse_expression_for("the language version"), "the language version", at);
        suppress_.pop_back();
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
        if (conds_.empty() || conds_.back().file_depth != files_.size() ||
            (conds_.back().kind != CondKind::if_ && conds_.back().kind != CondKind::switch_))
            fail(d.location, "`#" + name + "` without a matching `#if`");
        if (conds_.back().kind == CondKind::switch_) {
            // Reached while running a #case: POV-Ray falls through into the #else.
            if (name == "elseif") fail(d.location, "`#elseif` in a `#switch`: expected `#case`, `#range` or `#else`");
            return;
        }
        skip_branch(conds_.back().at, "#if", false);
        conds_.pop_back();
    } else if (name == "end") {
        if (conds_.empty() || conds_.back().file_depth != files_.size())
            fail(d.location, "`#end` without a matching `#if`, `#ifdef`, `#ifndef`, `#while`, `#for`, `#switch` or "
                             "`#macro`");
        CondFrame frame = conds_.back();
        conds_.pop_back();
        if (frame.kind == CondKind::while_) loop_again(frame);
        if (frame.kind == CondKind::for_) for_again(frame);
    } else if (name == "while") {
        const Lexer::State start = files_.back().lexer.state();
        bool guard = false;
        if (parse_condition(d, guard)) {
            conds_.push_back({CondKind::while_, files_.size(), d.location, start, guard, 0});
        } else {
            skip_branch(d.location, "#while", false);
        }
    } else if (name == "macro") {
        directive_macro(d);
    } else if (name == "switch") {
        directive_switch(d);
    } else if (name == "case" || name == "range") {
        directive_case(d);
    } else if (name == "break") {
        directive_break(d);
    } else if (name == "for") {
        directive_for(d);
    } else if (name == "warning" || name == "debug" || name == "error") {
        const Token s = parse_string_token("a string after `#" + name + "`");
        if (name == "error") fail(d.location, "#error: " + s.text);
        if (name == "warning") warn(d.location, "#warning: " + s.text, Severity::note);  // the scene's own message
    } else if (name == "default") {
        directive_default(d);
    } else if (name == "fopen") {
        directive_fopen(d);
    } else if (name == "fclose") {
        directive_fclose(d);
    } else if (name == "read") {
        directive_read(d);
    } else if (name == "write") {
        directive_write(d);
    } else if (one_of(name, {"statistics", "render"})) {
        fail(d.location, "`#" + name + "` is not supported by photon's scene language (see docs/scene-language.md)");
    } else {
        fail(d.location, "unknown directive `#" + name + "`" +
                             suggest(name, {"declare", "local", "undef", "include", "if", "ifdef", "ifndef", "else",
                                            "elseif", "end", "while", "for", "switch", "case", "range", "break",
                                            "macro", "version", "warning", "error", "debug", "default", "fopen",
                                            "fclose", "read", "write"}));
    }
}

// Whether `w` is a keyword of the language: no identifier, macro or file identifier may be named so.
inline bool Parser::is_reserved(std::string_view w) const { return reserved_words().contains(w); }

// DECLARE: (#declare | #local) [deprecated [once] STRING] IDENTIFIER = RVALUE [;]
//   (the `;` may be left out after a BLOCK or a STRING; IDENTIFIER may be an array element A[i])
inline void Parser::directive_declare(const Token& d, bool local) {
    const std::size_t home = files_.size(), depth = scopes_.size();
    Token id;
    {
        const ReadingName reading(*this);
        id = next();
        // POV-Ray 3.7's `#declare deprecated [once] "message" NAME = ...`: read, the mark ignored.
        if (id.is_identifier("deprecated")) {
            Token message = next();
            if (message.is_identifier("once")) message = next();
            if (message.kind != TokenKind::string) fail_expected("a message in double quotes after `deprecated`", message);
            id = next();
        }
    }
    if (id.kind != TokenKind::identifier) fail_expected("an identifier after `#" + d.text + "`", id);
    if (is_reserved(id.text)) fail(id.location, "cannot #" + d.text + " `" + id.text + "`: it is a keyword");
    if (const auto m = macros_.find(id.text); m != macros_.end())
        fail(id.location, "cannot #" + d.text + " `" + id.text + "`: it is a macro (defined at " +
                              position_in(m->second->at, id.location) + "); `#undef` it first");
    expect_symbol("=", "after `#" + d.text + " " + id.text + "`");
    bool needs_semicolon = false;
    declaring_ = id.text;  // a `function { }` knows its name, for messages and recursion
    ValueData v = parse_rvalue("the value of `" + id.text + "`", needs_semicolon);
    const bool semicolon_optional = !needs_semicolon || std::holds_alternative<std::string>(v);
    // A macro called for the value may still be open (`#local M = Matrix_Trans(...)` has read
    // the body's last token, `Q;` its `;` still to come): the value goes to the declaration's
    // scopes, not to the macro's, so those are set aside while it is assigned.
    std::vector<std::unordered_map<std::string, Value>> callee;
    for (std::size_t i = depth; i < scopes_.size(); ++i) callee.push_back(std::move(scopes_[i]));
    scopes_.resize(std::min(depth, scopes_.size()));
    assign(id, std::move(v), local);
    for (auto& scope : callee) scopes_.push_back(std::move(scope));  // before the next token, which may use it (a macro call's argument)
    // The next directive is not run from here (it runs after this one returns), so that a file
    // of declarations does not nest one directive inside the other.
    suppress_.push_back(home);
    const Token after = peek();
    suppress_.pop_back();
    if (after.is_symbol(";")) {
        next();
        return;
    }
    // POV-Ray reads a block or a string without the `;`.
    if (!semicolon_optional)
        fail(after.location, "expected `;` after the value of `" + id.text + "`, found " + describe(after));
}

/// BLOCK: texture {..} {texture {..}} | pigment {..} | finish {..} | normal {..} | interior {..}
///   | transform {..} | camera {..} | ARRAY | spline {..} | FUNCTION | material {..} | OBJECT | BLEND_MAP
///   | sky_sphere {..} | fog {..} | media {..} | density {..} | rainbow {..} | BLOCK_IDENTIFIER
/// A declarable block starting at `t` (texture { }, sphere { }, array[3], ...), or a declared
/// identifier of a block's type; nullopt when `t` starts something else.
inline std::optional<ValueData> Parser::parse_block_value(const Token& t) {
    if (t.kind != TokenKind::identifier) return std::nullopt;
    const std::string& w = t.text;
    if (w == "texture") {
        Texture tex = parse_texture(next(), default_texture_);
        // `#declare T = texture { } texture { }`: POV-Ray's layered texture, the first the bottom.
        // Looking for a layer must not run the next directive or call the next macro (either may
        // use this declaration: screen.pov's `Screen_Plane(MyScreenTexture, ...)`); a token that is
        // no layer is read again afterwards, when it runs.
        auto another_layer = [&] {
            const bool fresh = !lookahead_;
            const std::size_t frames = files_.size();
            const Lexer::State before = files_.back().lexer.state();
            suppress_.push_back(files_.size());
            bool more = false;
            {
                const ReadingName reading(*this);
                more = peek().is_identifier("texture");
            }
            suppress_.pop_back();
            if (!more && fresh && files_.size() == frames) {
                lookahead_.reset();
                files_.back().lexer.restore(before);
            }
            return more;
        };
        while (another_layer()) add_layer(tex, parse_texture(next(), default_texture_));
        return tex;
    }
    if (w == "pigment") return parse_pigment(next(), Pigment{});
    if (w == "finish") return parse_finish(next(), Finish{});
    if (w == "normal") return parse_normal(next(), Normal{});
    if (w == "interior") return parse_interior(next(), Interior{});
    if (w == "transform") return parse_transform_block(next());
    if (w == "camera") return parse_camera(next());
    if (w == "array") return parse_array(next());
    if (w == "spline") return parse_spline(next());
    if (w == "function") return parse_user_function(next(), declaring_);
    if (w == "material") {
        Object holder;
        const Token kw = next();
        parse_material(kw, holder);
        return MaterialBlock{std::move(holder.texture), std::move(holder.interior), kw.location};
    }
    if (is_object_keyword(w)) return parse_object(next());
    // Maps photon averages (parser/patterns.hpp); the blocks it reads and ignores, kept so that
    // their use by name is known (the warning comes where they are used).
    if (one_of(w, blend_map_keywords)) return parse_blend_map(next());
    if (w == "sky_sphere") return parse_sky_sphere_block(next());
    if (w == "fog") return parse_fog_block(next());
    if (w == "media") return parse_media_block(next());
    if (w == "density") return parse_density(next());
    if (one_of(w, ignored_declarable_blocks)) {
        const Nest nest(*this, t.location);
        skip_block(next());
        return IgnoredBlock{w};
    }
    const Value* v = lookup(w);
    if (!v || std::holds_alternative<Numeric>(v->data)) return std::nullopt;
    const ValueData value = v->data;  // next() may run a directive that changes it
    const Token name = next();
    if (std::holds_alternative<std::shared_ptr<const UserFunction>>(value) && peek().is_symbol("(")) {
        pending_call_ = name;  // `F(...)` calls the function; `#declare G = F` copies it
        return std::nullopt;
    }
    return value;
}

/// RVALUE: BLOCK | STRING | EXPRESSION — what `#declare NAME =` and a macro argument take.
/// `needs_semicolon`: a string or an expression, which `#declare` ends with `;`. `sums_only`:
/// the expression stops before a comparison, as POV-Ray's array elements do (Parse_Rel_Factor),
/// so that `<1, 2>\n<3, 4>` is two elements.
inline ValueData Parser::parse_rvalue(const std::string& what, bool& needs_semicolon, bool sums_only) {
    const std::size_t home = files_.size();  // before the first token, which may call a macro
    const Token t = peek();
    if (auto block = parse_block_value(t)) {
        needs_semicolon = false;
        return std::move(*block);
    }
    needs_semicolon = true;
    if (!pending_call_ && starts_string(t)) return parse_string_expression(what);
    suppress_.push_back(home);
    const bool saved = in_vector_;
    in_vector_ = sums_only;
    Numeric n = parse_expression_for(what);
    in_vector_ = saved;
    suppress_.pop_back();
    return n;
}

// UNDEF: #undef IDENTIFIER   (an identifier or a macro; not an array element)
inline void Parser::directive_undef() {
    Token id;
    {
        const ReadingName reading(*this);
        id = next();
    }
    if (id.kind != TokenKind::identifier) fail_expected("an identifier after `#undef`", id);
    if (id.text.find('[') != std::string::npos) fail(id.location, "cannot `#undef` an array element");
    macros_.erase(id.text);
    for (auto& scope : scopes_) scope.erase(id.text);
}

/// CONDITION: ( FLOAT ) after #if, #elseif or #while; true when not 0. Directives are not run
/// inside it (as in POV-Ray): `#if #end` is an error here, not an `#end` that re-enters a loop's
/// condition.
inline bool Parser::parse_condition(const Token& d, bool& guard) {
    suppress_.push_back(files_.size());
    expect_symbol("(", "after `#" + d.text + "`");
    const bool saved = mentions_photon_version_;
    mentions_photon_version_ = false;
    const SourceLocation at = peek().location;
    const double v = to_float(parse_expression_for("a condition"), "a condition", at);
    guard = mentions_photon_version_;
    mentions_photon_version_ = saved;
    expect_symbol(")", "to close the condition of `#" + d.text + "`");
    suppress_.pop_back();
    return v != 0.0;
}

// DEFINED_CONDITION: ( IDENTIFIER ) after #ifdef or #ifndef: whether it names a declared
// identifier or a macro (the opposite for #ifndef).
inline bool Parser::parse_defined_condition(const Token& d, bool negate, bool& guard) {
    suppress_.push_back(files_.size());
    expect_symbol("(", "after `#" + d.text + "`");
    Token id;
    {
        const ReadingName reading(*this);
        id = next();
    }
    if (id.kind != TokenKind::identifier) fail_expected("an identifier in `#" + d.text + " ( )`", id);
    expect_symbol(")", "after the identifier of `#" + d.text + "`");
    suppress_.pop_back();
    guard = id.text == "photon_version";
    return (lookup(id.text) != nullptr || macros_.count(id.text) > 0) != negate;
}

// IF: #if ( FLOAT ) TOKENS {#elseif ( FLOAT ) TOKENS} [#else TOKENS] #end, #ifdef and #ifndef
// alike: the branches before the first true one are skipped here; the rest, after it, by the
// #else or #elseif that ends it (directive).
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

/// SKIPPED_BRANCH: {TOKEN | #if|#ifdef|#ifndef|#while|#for|#switch|#macro SKIPPED_BRANCH #end}
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

// WHILE: #while ( FLOAT ) TOKENS #end. At the #end: back to the condition, which is read
// again; the body runs again while it holds, else it is skipped to the #end.
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

// Whether an open #if, #ifdef, #ifndef or #while tests photon_version: inside one the scene is written for
// photon, so photon's own settings there need no warning that POV-Ray stops at them.
inline bool Parser::in_photon_guard() const {
    return std::any_of(conds_.begin(), conds_.end(), [](const CondFrame& c) { return c.photon_guard; });
}

// DEFAULT: #default { {texture {..} | pigment {..} | finish {..} | normal {..}} }
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
        else if (t.is_identifier("normal"))
            default_texture_.normal = parse_normal(next(), default_texture_.normal.value_or(Normal{}));
        else
            break;
    }
    close_block(d, "`texture`, `pigment`, `finish` or `normal`", {"texture", "pigment", "finish", "normal"});
}

}  // namespace photon::dsl::detail
