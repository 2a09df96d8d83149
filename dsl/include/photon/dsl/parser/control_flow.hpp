// SPDX-License-Identifier: MIT
#pragma once
// `#switch` / `#case` / `#range` / `#else` / `#break` and `#for`, with POV-Ray's semantics: a
// matching #case runs on through later #case and #range lines (they are read and ignored) until
// `#break` or the switch's `#end`; `#break` also leaves a #while, a #for or the running macro.

#include "parser_class.hpp"

namespace photon::dsl::detail {

// SWITCH: #switch ( FLOAT ) { (#case ( FLOAT ) | #range ( FLOAT , FLOAT ) | #else) TOKENS [#break] } #end
inline void Parser::directive_switch(const Token& d) {
    suppress_.push_back(files_.size());
    expect_symbol("(", "after `#switch`");
    const double v = parse_float("the value of `#switch`");
    expect_symbol(")", "to close the value of `#switch`");
    suppress_.pop_back();
    CondFrame frame{CondKind::switch_, files_.size(), d.location};
    frame.switch_value = v;
    conds_.push_back(frame);
    skip_to_case(d);
}

/// CASE: ( FLOAT ) after #case, ( FLOAT , FLOAT ) after #range: does the switch's value match?
inline bool Parser::case_matches(const Token& d) {
    suppress_.push_back(files_.size());
    expect_symbol("(", "after `#" + d.text + "`");
    const double a = parse_float("the value of `#" + d.text + "`");
    double b = a;
    if (d.text == "range") {
        expect_symbol(",", "between the two ends of `#range`");
        b = parse_float("the upper end of `#range`");
    }
    expect_symbol(")", "to close `#" + d.text + "`");
    suppress_.pop_back();
    const double v = conds_.back().switch_value;
    return d.text == "case" ? std::abs(v - a) < 1e-10 : v >= a && v <= b;
}

/// SKIPPED_CASES: {TOKEN | #if|#ifdef|#ifndef|#while|#for|#switch|#macro .. #end} (#case CASE |
/// #range CASE | #else | #end): skips to the first #case or #range that matches, an #else, or the
/// switch's #end.
inline void Parser::skip_to_case(const Token& d) {
    int depth = 0;
    for (;;) {
        if (++tokens_ > options_.max_tokens)
            fail(d.location, "the scene is too long: more than " + std::to_string(options_.max_tokens) + " tokens read");
        if (files_.back().macro && files_.back().lexer.state().pos >= files_.back().macro->body_end)
            return_from_macro();  // reports the open #switch
        const Token t = files_.back().lexer.next();
        if (t.kind == TokenKind::end_of_file)
            fail(t.location, "expected `#end` to close the `#switch` opened at " + position(d.location) +
                                 ", found end of file");
        if (t.kind != TokenKind::directive) continue;
        if (one_of(t.text, {"if", "ifdef", "ifndef", "while", "switch", "macro", "for"})) {
            ++depth;
        } else if (t.text == "end") {
            if (depth-- > 0) continue;
            conds_.pop_back();
            return;
        } else if (depth == 0 && t.text == "else") {
            conds_.back().case_running = true;
            return;
        } else if (depth == 0 && (t.text == "case" || t.text == "range") && case_matches(t)) {
            conds_.back().case_running = true;
            return;
        }
    }
}

/// FALL_THROUGH: (#case | #range) CASE met while a matching case runs: read and ignored.
inline void Parser::directive_case(const Token& d) {
    if (conds_.empty() || conds_.back().file_depth != files_.size() || conds_.back().kind != CondKind::switch_)
        fail(d.location, "`#" + d.text + "` without a matching `#switch`");
    case_matches(d);
}

/// BREAK: #break — leaves the innermost #switch, #while or #for (skipping to the #end of each
/// #if it is in), or else returns from the running macro.
inline void Parser::directive_break(const Token& d) {
    for (std::size_t i = conds_.size(); i-- > 0 && conds_[i].file_depth == files_.size();)
        if (conds_[i].kind != CondKind::if_) {
            skip_to_end_of(i);
            return;
        }
    if (!files_.back().macro)
        fail(d.location, "`#break` outside `#switch`, `#while`, `#for` or a macro");
    while (!conds_.empty() && conds_.back().file_depth == files_.size()) conds_.pop_back();
    return_from_macro();
}

/// Skips to the #end of conds_[frame], and of every directive opened inside it, and closes them.
inline void Parser::skip_to_end_of(std::size_t frame) {
    while (conds_.size() > frame) {
        const CondFrame& c = conds_.back();
        const char* kinds[] = {"#if", "#while", "#for", "#switch"};
        skip_branch(c.at, kinds[int(c.kind)], false);
        conds_.pop_back();
    }
}

// FOR: #for ( IDENTIFIER [,] FLOAT [,] FLOAT [, FLOAT] ) TOKENS #end
inline void Parser::directive_for(const Token& d) {
    suppress_.push_back(files_.size());
    expect_symbol("(", "after `#for`");
    Token id;
    {
        const ReadingName reading(*this);
        id = next();
    }
    if (id.kind != TokenKind::identifier || is_reserved(id.text) || macros_.count(id.text))
        fail_expected("the name of the loop variable after `#for (`", id);
    if (id.text.find('[') != std::string::npos)
        fail(id.location, "the loop variable of `#for` cannot be an array element");
    optional_comma();
    const double start = parse_float("the start of `#for`");
    optional_comma();
    const double end = parse_float("the end of `#for`");
    double step = 1;
    SourceLocation step_at = d.location;
    if (accept_symbol(",")) step = parse_float("the step of `#for`", &step_at);
    expect_symbol(")", "to close `#for (`");
    suppress_.pop_back();
    if (std::abs(step) < 1e-10) fail(step_at, "the step of `#for` must not be 0");
    scopes_.back()[id.text] = Value{Numeric::scalar(start), id.location};
    if ((step > 0 && start > end + 1e-10) || (step < 0 && start < end - 1e-10)) {
        skip_branch(d.location, "#for", false);
        return;
    }
    CondFrame frame{CondKind::for_, files_.size(), d.location, files_.back().lexer.state()};
    frame.loop_variable = id.text;
    frame.loop_end = end;
    frame.loop_step = step;
    conds_.push_back(frame);
}

/// At a #for's #end: step the variable, and run the body again while it is within the end.
inline void Parser::for_again(CondFrame frame) {
    if (++frame.iterations > options_.max_loop_iterations)
        fail(frame.at, "`#for` loop ran more than " + std::to_string(options_.max_loop_iterations) + " times");
    const auto f = scopes_.back().find(frame.loop_variable);
    Numeric* n = f == scopes_.back().end() ? nullptr : std::get_if<Numeric>(&f->second.data);
    if (!n || !n->is_float() || f->second.is_reference())
        fail(frame.at, "the loop variable `" + frame.loop_variable + "` of `#for` must stay a number in its loop");
    n->c[0] += frame.loop_step;
    const double v = n->c[0];
    if ((frame.loop_step > 0 && v > frame.loop_end + 1e-10) || (frame.loop_step < 0 && v < frame.loop_end - 1e-10))
        return;
    files_.back().lexer.restore(frame.loop_start);
    conds_.push_back(frame);
}

}  // namespace photon::dsl::detail
