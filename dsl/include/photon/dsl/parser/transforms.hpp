// SPDX-License-Identifier: MIT
#pragma once
// Transformations: translate, rotate, scale, matrix, transform { } and transform identifiers.

#include "parser_class.hpp"

namespace photon::dsl::detail {

// TRANSFORMATION: translate V | rotate V | scale V | matrix < F , F , F , F , F , F , F , F , F , F , F , F >
//   | transform { TRANSFORM_BODY } | transform TRANSFORM_IDENT   (a scale by 0 or a singular matrix is an error)
inline bool Parser::try_transform(Transform& tr) {
    const Token t = peek();
    if (t.kind != TokenKind::identifier) return false;
    if (t.text == "translate") {
        next();
        tr = tr.then(Transform::translate(parse_vector("the translation after `translate`")));
    } else if (t.text == "rotate") {
        next();
        tr = tr.then(Transform::rotate(parse_vector("the angles in degrees after `rotate`")));
    } else if (t.text == "scale") {
        next();
        SourceLocation at;
        const Vector3 s = parse_vector("the scale factors after `scale`", &at);
        if (s.x == 0 || s.y == 0 || s.z == 0)
            fail(at, "scale by zero would flatten the object: expected non-zero scale factors, found <" +
                         format_number(s.x) + ", " + format_number(s.y) + ", " + format_number(s.z) + ">");
        tr = tr.then(Transform::scale(s));
    } else if (t.text == "matrix") {
        next();
        const Token open = expect_symbol("<", "after `matrix`");
        std::array<double, 12> m{};
        const bool saved = in_vector_;
        for (std::size_t i = 0; i < 12; ++i) {
            in_vector_ = true;
            m[i] = parse_float("entry " + std::to_string(i + 1) + " of the 12 numbers of `matrix`");
            in_vector_ = saved;
            if (i < 11) expect_symbol(",", "between the 12 numbers of `matrix`");
        }
        expect_symbol(">", "after the 12 numbers of `matrix`");
        const Transform mt = Transform::matrix(m);
        if (std::abs(glm::determinant(mt.linear)) < 1e-300)
            fail(open.location, "the matrix is singular (its 3x3 part has determinant 0)");
        tr = tr.then(mt);
    } else if (t.text == "transform") {
        next();
        if (peek().is_symbol("{")) {
            tr = tr.then(parse_transform_body(t));
        } else {
            const Token id = next();
            const Value* v = id.kind == TokenKind::identifier ? lookup(id.text) : nullptr;
            if (!v || !std::holds_alternative<Transform>(v->data))
                fail_expected("a transform identifier or `{` after `transform`", id);
            tr = tr.then(std::get<Transform>(v->data));
        }
    } else {
        return false;
    }
    return true;
}

// TRANSFORM_BLOCK: transform { TRANSFORM_BODY }, a declared value (the `{` is required).
inline Transform Parser::parse_transform_block(const Token& kw) {
    if (!peek().is_symbol("{")) fail_expected("`{` after `transform`", peek());
    return parse_transform_body(kw);
}

// TRANSFORM_BODY: [TRANSFORM_IDENT] {TRANSFORMATION | inverse}, with its braces.
inline Transform Parser::parse_transform_body(const Token& kw) {
    const Nest nest(*this, kw.location);
    open_block(kw);
    Transform tr;
    if (peek().kind == TokenKind::identifier) {
        const Value* v = lookup(peek().text);
        if (v && std::holds_alternative<Transform>(v->data)) {
            next();
            tr = std::get<Transform>(v->data);
        }
    }
    for (;;) {
        if (try_transform(tr)) continue;
        if (peek().is_identifier("inverse")) {
            next();
            tr = tr.inverse();
            continue;
        }
        break;
    }
    close_block(kw, "`translate`, `rotate`, `scale`, `matrix`, `transform` or `inverse`",
                {"translate", "rotate", "scale", "matrix", "transform", "inverse"});
    return tr;
}

}  // namespace photon::dsl::detail
