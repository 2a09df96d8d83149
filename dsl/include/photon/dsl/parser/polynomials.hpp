// SPDX-License-Identifier: MIT
#pragma once
// POV-Ray's polynomial surfaces: quartic, cubic, poly and 3.7's polynomial, read as POV-Ray 3.7
// reads them (source/parser/parser.cpp Parse_Poly, Parse_Polynom and Parse_Coeffs): an order from
// 2 to 35 (MAX_ORDER), the coefficients in POV-Ray's term order, `sturm` accepted (photon's root
// finder brackets every root anyway). A bounded_by sphere or box becomes the surface's gate, so
// that it renders as POV-Ray's does (parse_polynomial_gate).

#include <cmath>

#include <photon/geometry/polynomial_surface.hpp>

#include "degradation.hpp"
#include "parser_class.hpp"

namespace photon::dsl::detail {

namespace polynomial {
/// POV-Ray's MAX_ORDER.
inline constexpr int max_order = 35;
}  // namespace polynomial

// QUARTIC: quartic { < FLOAT {[,] FLOAT} > MODIFIERS }          (35 coefficients)
// CUBIC: cubic { < FLOAT {[,] FLOAT} > MODIFIERS }              (20 coefficients)
// POLY: poly { ORDER , < FLOAT {[,] FLOAT} > MODIFIERS }        ((n + 1)(n + 2)(n + 3) / 6 coefficients)
// POLYNOMIAL: polynomial { ORDER [,] {xyz ( INT , INT , INT ) : FLOAT [,]} MODIFIERS }
inline void Parser::parse_polynomial(const Token& kw, Object& obj) {
    PolynomialShape p;
    p.keyword = kw.text;
    SourceLocation first_at = peek().location;
    if (kw.text == "quartic" || kw.text == "cubic") {
        p.order = kw.text == "quartic" ? 4 : 3;
    } else {
        SourceLocation order_at;
        const double order = parse_float("the order of the " + kw.text, &order_at);
        optional_comma();
        if (!(order >= 2 && order < polynomial::max_order + 1))
            fail(order_at, "the order of `" + kw.text + "` must be 2 to 35 (POV-Ray's limit), found " + format_number(order));
        p.order = int(order);  // POV-Ray truncates
        first_at = peek().location;
    }
    auto coefficients = std::make_shared<std::vector<double>>(polynomial_term_count(p.order), 0.0);
    const std::string what = "a coefficient of the " + kw.text;
    if (kw.text != "polynomial") {
        const Token open = peek();
        expect_symbol("<", "to open the " + std::to_string(coefficients->size()) + " coefficients of the " + kw.text);
        const bool saved = in_vector_;
        in_vector_ = true;  // `>` closes the list, it is no comparison
        for (std::size_t n = 0; n < coefficients->size(); ++n) {
            if (n > 0) optional_comma();
            if (peek().is_symbol(">"))
                fail(peek().location, "the " + kw.text + " of order " + std::to_string(p.order) + " needs " +
                                          std::to_string(coefficients->size()) + " coefficients, found " +
                                          std::to_string(n));
            SourceLocation at;
            (*coefficients)[n] = finite_value(parse_float(what, &at), what, at);
        }
        in_vector_ = saved;
        optional_comma();
        expect_symbol(">", "after the " + std::to_string(coefficients->size()) + " coefficients of the " + kw.text +
                               " opened at " + position(open.location));
    } else {
        while (peek().is_identifier("xyz")) {
            next();
            expect_symbol("(", "after `xyz`");
            int powers[3];
            SourceLocation power_at[3];
            for (int a = 0; a < 3; ++a) {
                if (a > 0) expect_symbol(",", "between the powers of `xyz`");
                const double v = parse_float("a power in `xyz`", &power_at[a]);
                if (!(v >= 0 && v <= polynomial::max_order))
                    fail(power_at[a], "a power in `xyz` must be 0 to " + std::to_string(p.order) + ", found " + format_number(v));
                powers[a] = int(v);
            }
            expect_symbol(")", "to close `xyz`");
            if (powers[0] + powers[1] + powers[2] > p.order)
                fail(power_at[0], "the term x^" + std::to_string(powers[0]) + " y^" + std::to_string(powers[1]) + " z^" +
                                      std::to_string(powers[2]) + " is above the polynomial's order " +
                                      std::to_string(p.order) + " (POV-Ray: \"Coefficient of polynom is out of range\")");
            expect_symbol(":", "after `xyz(...)`");
            SourceLocation at;
            (*coefficients)[polynomial_term_index(p.order, powers[0], powers[1], powers[2])] =
                finite_value(parse_float(what, &at), what, at);
            optional_comma();
        }
    }
    bool any = false;
    for (std::size_t n = 0; n + 1 < coefficients->size(); ++n) any = any || (*coefficients)[n] != 0.0;
    p.coefficients = std::move(coefficients);
    obj.shape = std::move(p);
    if (!any) skip_empty_shape(obj, kw.text, "its coefficients of x, y and z are all 0", first_at);
}

/// A `bounded_by` of one sphere or box on a polynomial becomes its gate, in the polynomial's own
/// coordinates (`obj`'s transformation so far maps them to where the bound is written): exact
/// where the bound's own placement keeps it a sphere (a similarity) or an axis-aligned box.
/// False (the bound stays ignored, with its warning) otherwise.
inline bool Parser::parse_polynomial_gate(Object& obj, const std::vector<Object>& bounds) {
    auto* poly = std::get_if<PolynomialShape>(&obj.shape);
    if (!poly || bounds.size() != 1 || bounds[0].inverse) return false;
    const Object& b = bounds[0];
    const Transform to_local = b.transform.then(obj.transform.inverse());
    const glm::dmat3& m = to_local.linear;
    PolynomialShape::Gate gate;
    if (const auto* s = std::get_if<SphereShape>(&b.shape)) {
        const glm::dmat3 g = glm::transpose(m) * m;  // a similarity: g = s^2 I
        const double s2 = g[0][0];
        for (int i = 0; i < 3; ++i)
            for (int j = 0; j < 3; ++j)
                if (std::abs(g[i][j] - (i == j ? s2 : 0.0)) > 1e-12 * s2) return false;
        gate.sphere = true;
        gate.center = to_local.point(s->center);
        gate.radius = s->radius * std::sqrt(s2);
    } else if (const auto* x = std::get_if<BoxShape>(&b.shape)) {
        for (int c = 0; c < 3; ++c) {  // each axis to an axis
            int big = 0;
            for (int k = 0; k < 3; ++k) big += std::abs(m[c][k]) > 1e-12 * glm::length(m[c]);
            if (big != 1) return false;
        }
        const Vector3 a = to_local.point(x->corner1), c = to_local.point(x->corner2);
        gate.sphere = false;
        gate.min = glm::min(a, c), gate.max = glm::max(a, c);
        if (!(gate.min.x < gate.max.x && gate.min.y < gate.max.y && gate.min.z < gate.max.z)) return false;
    } else {
        return false;
    }
    poly->gate = gate;
    return true;
}

}  // namespace photon::dsl::detail
