// SPDX-License-Identifier: MIT
#pragma once
// The prism and text (a prism per glyph, built from the font by the build step), with POV-Ray
// 3.7's reading of its points (source/parser/parser.cpp Parse_Prism and
// source/core/shape/prism.cpp Compute_Prism): which points make each curve for each spline type,
// where a sub-outline closes, and what happens when the last one does not (a linear prism is
// closed, as POV-Ray closes it; a curved one is skipped with a warning, as POV-Ray ignores it).

#include <algorithm>
#include <cmath>
#include <filesystem>

#include "degradation.hpp"
#include "parser_class.hpp"

namespace photon::dsl::detail {

namespace prism {

enum class Spline : std::uint8_t { linear, quadratic, cubic, bezier };

/// POV-Ray's EPSILON: points closer than this in x and in z are one point.
inline constexpr double epsilon = 1e-10;

/// Whether two outline points are one point, as POV-Ray judges it (within epsilon).
[[nodiscard]] inline bool same_point(glm::dvec2 a, glm::dvec2 b) noexcept {
    return std::abs(a.x - b.x) < epsilon && std::abs(a.y - b.y) < epsilon;
}

/// The closed contours of POV-Ray's points, Compute_Prism's way: a quadratic spline's curve i
/// runs from P[i+1] to P[i+2] shaped by P[i] (POV-Ray's quadratic interpolation, as a quadratic
/// Bezier), a cubic spline's from P[i+1] to P[i+2] shaped by P[i] and P[i+3] (Catmull-Rom, as a
/// cubic Bezier), a Bezier spline takes four points per curve; a sub-outline ends where its curve
/// reaches the first point of it again (for Bezier: where the next curve does not start at the
/// end of this one). Nothing when a curved outline's last sub-outline is not closed.
[[nodiscard]] inline std::optional<std::vector<std::vector<OutlineCurve>>> contours(Spline spline,
                                                                                  const std::vector<glm::dvec2>& p) {
    std::vector<std::vector<OutlineCurve>> out(1);
    const std::size_t n = p.size();
    const auto close = [&](glm::dvec2 first) {
        out.back().back().control[std::size_t(out.back().back().degree)] = first;  // within epsilon: exactly
        out.emplace_back();
    };
    if (spline == Spline::bezier) {
        for (std::size_t i = 0; i + 3 < n; i += 4) {
            if (!out.back().empty() && !same_point(p[i], out.back().back().control[3])) {
                if (!same_point(out.back().back().control[3], out.back().front().control[0])) return std::nullopt;
                close(out.back().front().control[0]);
            }
            glm::dvec2 start = out.back().empty() ? p[i] : out.back().back().control[3];
            out.back().push_back({{start, p[i + 1], p[i + 2], p[i + 3]}, 3});
        }
        if (out.back().empty() || !same_point(out.back().back().control[3], out.back().front().control[0]))
            return std::nullopt;
        close(out.back().front().control[0]);
        out.pop_back();
        return out;
    }
    glm::dvec2 first = spline == Spline::linear ? p[0] : p[1];
    for (std::size_t i = 0; i + 1 < n; ++i) {
        const std::size_t i1 = i + 1, i2 = i + 2, i3 = i + 3;
        if (spline == Spline::linear) {
            out.back().push_back({{p[i], p[i1], {}, {}}, 1});
            if (same_point(p[i1], first)) {
                close(first);
                ++i;
                if (i + 1 < n) first = p[i + 1];
            }
        } else if (spline == Spline::quadratic) {
            if (i2 >= n) break;
            out.back().push_back({{p[i1], p[i1] + 0.25 * (p[i2] - p[i]), p[i2], {}}, 2});
            if (same_point(p[i2], first)) {
                close(first);
                i += 2;
                if (i + 2 < n) first = p[i + 2];
            }
        } else {
            if (i3 >= n) break;
            out.back().push_back({{p[i1], p[i1] + (p[i2] - p[i]) / 6.0, p[i2] - (p[i3] - p[i1]) / 6.0, p[i2]}, 3});
            if (same_point(p[i2], first)) {
                close(first);
                i += 3;
                if (i + 2 < n) first = p[i + 2];
            }
        }
    }
    if (!out.back().empty()) {
        if (spline != Spline::linear) return std::nullopt;
        // POV-Ray: "Linear prism not closed. Closing it."
        out.back().push_back({{out.back().back().control[1], first, {}, {}}, 1});
        out.emplace_back();
    }
    out.pop_back();
    return out;
}

}  // namespace prism

// PRISM: prism { {SPLINE_TYPE | SWEEP_TYPE} FLOAT [,] FLOAT [,] INT [,] {UV_VECTOR [,]} [open] [sturm] MODIFIERS }
//   SPLINE_TYPE: linear_spline | quadratic_spline | cubic_spline | bezier_spline
//   SWEEP_TYPE: linear_sweep | conic_sweep
// The points are <x, z> of the xz plane; the prism spans y from the lower height to the higher.
inline void Parser::parse_prism(Object& obj) {
    using prism::Spline;
    PrismShape shape;
    Spline spline = Spline::linear;
    for (bool more = true; more;) {
        const Token& t = peek();
        if (t.is_identifier("linear_spline")) spline = Spline::linear;
        else if (t.is_identifier("quadratic_spline")) spline = Spline::quadratic;
        else if (t.is_identifier("cubic_spline")) spline = Spline::cubic;
        else if (t.is_identifier("bezier_spline")) spline = Spline::bezier;
        else if (t.is_identifier("linear_sweep")) shape.sweep = PrismShape::Sweep::linear;
        else if (t.is_identifier("conic_sweep")) shape.sweep = PrismShape::Sweep::conic;
        else more = false;
        if (more) next();
    }
    SourceLocation h1_at, h2_at, count_at;
    const double h1 = finite_value(parse_float("the first height of the prism", &h1_at), "the first height of the prism", h1_at);
    optional_comma();
    const double h2 = finite_value(parse_float("the second height of the prism", &h2_at), "the second height of the prism", h2_at);
    optional_comma();
    shape.height1 = std::min(h1, h2), shape.height2 = std::max(h1, h2);
    const double count = parse_float("the number of points of the prism", &count_at);
    if (!(count <= double(options_.max_primitives)))
        fail(count_at, "the prism has too many points: " + format_number(count) + " (at most " +
                           std::to_string(options_.max_primitives) + ")");
    const auto n = count >= 0 ? std::size_t(count) : 0;
    if (spline == Spline::linear && n < 3) fail(count_at, "a prism with linear splines needs at least 3 points");
    if (spline == Spline::quadratic && n < 5) fail(count_at, "a prism with quadratic splines needs at least 5 points");
    if (spline == Spline::cubic && n < 6) fail(count_at, "a prism with cubic splines needs at least 6 points");
    if (spline == Spline::bezier && (n == 0 || n % 4 != 0))
        fail(count_at, "a prism with Bezier splines needs 4 points per segment, found " + format_number(count));
    optional_comma();
    std::vector<glm::dvec2> points;
    for (std::size_t i = 0; i < n; ++i) {
        SourceLocation at;
        const Vector3 v = parse_vector("point " + std::to_string(i + 1) + " of the prism", &at);
        if (!is_finite(v)) fail(at, "point " + std::to_string(i + 1) + " of the prism must be finite");
        points.emplace_back(v.x, v.y);
        optional_comma();
    }
    shape.open = accept_open();
    auto closed = prism::contours(spline, points);
    obj.shape = shape;
    if (!closed) return skip_empty_shape(obj, "prism", "its outline is not closed", count_at);
    shape.contours = std::make_shared<const std::vector<std::vector<OutlineCurve>>>(std::move(*closed));
    obj.shape = shape;
    if (!(shape.height1 < shape.height2)) skip_empty_shape(obj, "prism", "its two heights are equal", h1_at);
}

// TEXT: text { ttf STRING [,] STRING [,] FLOAT [,] VECTOR MODIFIERS }
//     | text { internal FLOAT [,] STRING [,] FLOAT [,] VECTOR MODIFIERS }   (skipped, warning)
// The font file is looked for beside the scene, then on the include path (with `.ttf` added when
// the name has no extension, as POV-Ray adds it); POV-Ray reads the
// offset as a vector (a float is that float in x, y and z, as for every vector).
inline void Parser::parse_text(Object& obj) {
    TextShape t;
    const Token kind = next();
    if (kind.is_identifier("internal")) {  // POV-Ray's fonts compiled into it: photon has none
        parse_float("the number of POV-Ray's built-in font");
        optional_comma();
        (void)parse_string_token("the string of the text");
        optional_comma();
        parse_float("the thickness of the text");
        optional_comma();
        parse_vector("the offset between the glyphs of the text");
        const std::string why = "photon has no copies of POV-Ray's built-in (`internal`) fonts; name the font file with `ttf`";
        degrade(kind.location, degraded::skipped_object, "text", "`text` is skipped: " + why);
        obj.shape = SkippedShape{"text", why};
        return;
    }
    if (!kind.is_identifier("ttf")) fail_expected("`ttf` or `internal` and a font", kind);
    const Token font = parse_string_token("a font file name after `ttf`");
    t.font.written = font.text;
    t.font.at = font.location;
    const std::filesystem::path name(font.text);
    if (options_.read_include) {
        t.font.path = name;  // scenes read from memory name no files photon could open
    } else {
        // POV-Ray adds the extension `.ttf` to a name without one (`ttf "cyrvetic"`).
        std::vector<std::filesystem::path> names{name};
        if (!name.has_extension()) names.push_back(std::filesystem::path(font.text + ".ttf"));
        std::vector<std::filesystem::path> candidates;
        for (const auto& n : names)
            for (auto& place : search_places(n, true)) candidates.push_back(std::move(place));
        t.font.path = find_readable(candidates, font);
        if (t.font.path.empty())
            fail(font.location, "cannot find the font file \"" + font.text + "\" (looked beside the scene and on the include path)");
    }
    optional_comma();
    t.text = parse_string_token("the string of the text").text;
    optional_comma();
    SourceLocation thickness_at;
    t.thickness = finite_value(parse_float("the thickness of the text", &thickness_at), "the thickness of the text", thickness_at);
    optional_comma();
    SourceLocation offset_at;
    t.offset = parse_vector("the offset between the glyphs of the text", &offset_at);
    if (!is_finite(t.offset)) fail(offset_at, "the offset between the glyphs of the text must be finite");
    obj.shape = t;
    if (t.thickness == 0) skip_empty_shape(obj, "text", "thickness 0", thickness_at);
}

}  // namespace photon::dsl::detail
