// SPDX-License-Identifier: MIT
#pragma once
// The quadric and the polygon, with POV-Ray 3.7's reading of their values. Where POV-Ray renders
// nothing (a quadric with no terms in x, y or z; a polygon whose points are all on one line or
// not in one plane) photon skips the object with a warning.

#include <photon/geometry/polygon.hpp>

#include "degradation.hpp"
#include "parser_class.hpp"

namespace photon::dsl::detail {

// QUADRIC: quadric { VECTOR [,] VECTOR [,] VECTOR [,] FLOAT MODIFIERS }
inline void Parser::parse_quadric(Object& obj) {
    QuadricShape q;
    SourceLocation at[4];
    q.squares = parse_vector("the x^2, y^2, z^2 coefficients of the quadric", &at[0]);
    optional_comma();
    q.mixed = parse_vector("the xy, xz, yz coefficients of the quadric", &at[1]);
    optional_comma();
    q.linear = parse_vector("the x, y, z coefficients of the quadric", &at[2]);
    optional_comma();
    q.constant = parse_float("the constant of the quadric", &at[3]);
    const std::pair<Vector3, const char*> terms[] = {
        {q.squares, "x^2, y^2, z^2"}, {q.mixed, "xy, xz, yz"}, {q.linear, "x, y, z"}};
    for (std::size_t k = 0; k < 3; ++k)
        if (!is_finite(terms[k].first))
            fail(at[k], std::string("the ") + terms[k].second + " coefficients of the quadric must be finite");
    finite_value(q.constant, "the constant of the quadric", at[3]);
    obj.shape = q;
    if (q.squares == Vector3(0.0) && q.mixed == Vector3(0.0) && q.linear == Vector3(0.0))
        skip_empty_shape(obj, "quadric", "its coefficients of x, y and z are all 0", at[0]);
}

// POLYGON: polygon { INT {[,] VECTOR} MODIFIERS }   (INT points, at least 3)
// 2D points are in the xy plane (z = 0), as POV-Ray reads them. A loop ends where its first point
// repeats; POV-Ray closes an open last loop, and so does photon.
inline void Parser::parse_polygon(Object& obj) {
    SourceLocation count_at;
    const double count = parse_float("the number of points of the polygon", &count_at);
    if (!(count >= 3))
        fail(count_at, "a polygon needs at least 3 points, found " + format_number(count));
    if (!(count <= double(options_.max_primitives)))
        fail(count_at, "the polygon has too many points: " + format_number(count) + " (at most " +
                           std::to_string(options_.max_primitives) + ")");
    auto points = std::make_shared<std::vector<Vector3>>();
    const auto n = std::size_t(count);
    for (std::size_t i = 0; i < n; ++i) {
        optional_comma();
        SourceLocation at;
        points->push_back(parse_vector("point " + std::to_string(i + 1) + " of the polygon", &at));
        if (!is_finite(points->back())) fail(at, "point " + std::to_string(i + 1) + " of the polygon must be finite");
    }
    obj.shape = PolygonShape{points};
    if (!polygon_frame(*points))
        skip_empty_shape(obj, "polygon", "its points are all on one line or not in one plane", count_at);
}

}  // namespace photon::dsl::detail
