// SPDX-License-Identifier: MIT
#pragma once
// The superellipsoid and the shapes turned around the y axis, lathe and sor, with POV-Ray 3.7's
// reading of their numbers (source/parser/parser.cpp Parse_Superellipsoid, Parse_Lathe,
// Parse_Sor; source/core/shape/lathe.cpp Compute_Lathe, sor.cpp Compute_Sor): which points make
// each lathe curve for each spline type, which points may have a negative radius, what a sor
// needs of its heights.

#include <cmath>
#include <string>

#include "degradation.hpp"
#include "parser_class.hpp"

namespace photon::dsl::detail {

namespace lathe {

enum class Spline : std::uint8_t { linear, quadratic, cubic, bezier };

/// Compute_Lathe's curves as Bezier curves: a linear spline's curve i runs from P[i] to P[i+1];
/// a quadratic spline's from P[i+1] to P[i+2], leaving P[i+1] along (P[i+2] - P[i]) / 2; a cubic
/// spline's is Catmull-Rom from P[i+1] to P[i+2] with P[i] and P[i+3] as neighbours; a Bezier
/// spline takes four points per curve. (The same conventions as the prism's, parser/prism.hpp,
/// but a lathe's curves need not join or close.)
[[nodiscard]] inline std::vector<OutlineCurve> profile(Spline spline, const std::vector<glm::dvec2>& p) {
    std::vector<OutlineCurve> out;
    const std::size_t n = p.size();
    switch (spline) {
        case Spline::linear:
            for (std::size_t i = 0; i + 1 < n; ++i) out.push_back({{p[i], p[i + 1], {}, {}}, 1});
            break;
        case Spline::quadratic:
            for (std::size_t i = 0; i + 2 < n; ++i)
                out.push_back({{p[i + 1], p[i + 1] + 0.25 * (p[i + 2] - p[i]), p[i + 2], {}}, 2});
            break;
        case Spline::cubic:
            for (std::size_t i = 0; i + 3 < n; ++i)
                out.push_back({{p[i + 1], p[i + 1] + (p[i + 2] - p[i]) / 6.0, p[i + 2] - (p[i + 3] - p[i + 1]) / 6.0, p[i + 2]}, 3});
            break;
        case Spline::bezier:
            for (std::size_t i = 0; i + 3 < n; i += 4) out.push_back({{p[i], p[i + 1], p[i + 2], p[i + 3]}, 3});
            break;
    }
    return out;
}

}  // namespace lathe

// SUPERELLIPSOID: superellipsoid { <EAST_WEST_EXPONENT, NORTH_SOUTH_EXPONENT> MODIFIERS }
inline void Parser::parse_superellipsoid(Object& obj) {
    SourceLocation at;
    const Vector3 v = parse_vector("the exponents <e, n> of the superellipsoid", &at);
    // POV-Ray divides by both; 0 or less has no shape (and POV-Ray no sensible one).
    if (!(v.x > 0) || !(v.y > 0) || !std::isfinite(v.x) || !std::isfinite(v.y))
        fail(at, "the exponents of the superellipsoid must be positive and finite, found <" + format_number(v.x) + ", " +
                     format_number(v.y) + ">");
    obj.shape = SuperellipsoidShape{v.x, v.y};
}

// LATHE: lathe { [SPLINE_TYPE] INT [,] {UV_VECTOR [,]} [sturm] MODIFIERS }
//   SPLINE_TYPE: linear_spline | quadratic_spline | cubic_spline | bezier_spline
// The points are <radius, height>; the profile turns around the y axis.
inline void Parser::parse_lathe(Object& obj) {
    using lathe::Spline;
    Spline spline = Spline::linear;
    const Token& kind = peek();
    if (kind.is_identifier("linear_spline")) spline = Spline::linear, next();
    else if (kind.is_identifier("quadratic_spline")) spline = Spline::quadratic, next();
    else if (kind.is_identifier("cubic_spline")) spline = Spline::cubic, next();
    else if (kind.is_identifier("bezier_spline")) spline = Spline::bezier, next();
    SourceLocation count_at;
    const double count = parse_float("the number of points of the lathe", &count_at);
    if (!(count <= double(options_.max_primitives)))
        fail(count_at, "the lathe has too many points: " + format_number(count) + " (at most " +
                           std::to_string(options_.max_primitives) + ")");
    const auto n = count >= 0 ? std::size_t(count) : 0;
    if (spline == Spline::linear && n < 2) fail(count_at, "a lathe with linear splines needs at least 2 points");
    if (spline == Spline::quadratic && n < 3) fail(count_at, "a lathe with quadratic splines needs at least 3 points");
    if (spline == Spline::cubic && n < 4) fail(count_at, "a lathe with cubic splines needs at least 4 points");
    if (spline == Spline::bezier && (n == 0 || n % 4 != 0))
        fail(count_at, "a lathe with Bezier splines needs 4 points per segment, found " + format_number(count));
    optional_comma();
    std::vector<glm::dvec2> points;
    bool warned_control = false;
    for (std::size_t i = 0; i < n; ++i) {
        SourceLocation at;
        const std::string what = "point " + std::to_string(i + 1) + " of the lathe";
        const Vector3 v = parse_vector(what, &at);
        if (!is_finite(v)) fail(at, what + " must be finite");
        points.emplace_back(v.x, v.y);
        optional_comma();
        if (!(v.x < 0)) continue;
        // Parse_Lathe (3.7): a negative radius is an error, except at the ends of the curve,
        // where it is accepted with a warning (the surface there is the mirrored radius's).
        const bool end = i == 0 || i + 1 == n;
        const bool control = spline == Spline::bezier && i % 4 != 0 && i % 4 != 3;
        if (!end && !control) fail(at, what + " has a negative radius (x = " + format_number(v.x) + "): POV-Ray stops there too");
        const bool guide = (spline == Spline::quadratic && i == 0) || (spline == Spline::cubic && end);
        if (guide || (control && warned_control)) continue;
        if (control) warned_control = true;
        warn(at, what + " has a negative radius (x = " + format_number(v.x) +
                     "): the surface there is that of its mirror image, as POV-Ray 3.7 draws it");
    }
    obj.shape = LatheShape{std::make_shared<const std::vector<OutlineCurve>>(lathe::profile(spline, points))};
}

// SOR: sor { INT [,] {UV_VECTOR [,]} [open] [sturm] MODIFIERS }
// The points are <radius, height>; segment i runs between the heights of points i + 2 and i + 3
// (counting from 1), the first and last point only give the slope at the ends.
inline void Parser::parse_sor(Object& obj) {
    SourceLocation count_at;
    const double count = parse_float("the number of points of the sor", &count_at);
    if (!(count <= double(options_.max_primitives)))
        fail(count_at, "the sor has too many points: " + format_number(count) + " (at most " +
                           std::to_string(options_.max_primitives) + ")");
    const auto n = count >= 0 ? std::size_t(count) : 0;
    if (n < 4) fail(count_at, "a sor needs at least 4 points, found " + format_number(count));
    optional_comma();
    auto points = std::make_shared<std::vector<glm::dvec2>>();
    for (std::size_t i = 0; i < n; ++i) {
        SourceLocation at;
        const std::string what = "point " + std::to_string(i + 1) + " of the sor";
        const Vector3 v = parse_vector(what, &at);
        if (!is_finite(v)) fail(at, what + " must be finite");
        if (v.x < 0) fail(at, what + " has a negative radius (x = " + format_number(v.x) + ")");
        if (i > 1 && i + 1 < n && !(v.y > points->back().y))
            fail(at, what + " must be higher than the point before it (y " + format_number(v.y) + " after " +
                         format_number(points->back().y) + ")");
        // Compute_Sor divides by the height between a point's neighbours.
        if ((i == 2 && v.y == (*points)[0].y) || (i + 1 == n && v.y == (*points)[n - 3].y))
            fail(at, what + " must differ in height from point " + std::to_string(i - 1) + " (POV-Ray: \"Incorrect point\")");
        points->emplace_back(v.x, v.y);
        optional_comma();
    }
    SorShape shape;
    shape.open = accept_open();
    shape.points = std::move(points);
    obj.shape = shape;
}

}  // namespace photon::dsl::detail
