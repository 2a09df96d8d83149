// SPDX-License-Identifier: MIT
#pragma once
// A planar outline: closed contours of line, quadratic and cubic Bezier segments, filled by the
// even-odd rule over all of them (POV-Ray's prism and TrueType glyphs): a contour inside another
// cuts a hole. The 2D math a prism needs: whether a point is inside (crossing count), where a
// line meets the curves (a polynomial in the curve parameter) and which way is out (the tangent
// turned towards the outside). Kept in double whatever the scalar of the shape using it.

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <optional>
#include <stdexcept>
#include <vector>

#include "../math/vec.hpp"
#include "polynomial_roots.hpp"

namespace photon {

/// One piece of a contour: a Bezier curve of degree 1 (a line), 2 or 3, by its control points
/// (the first `degree + 1` of `control`). It runs from control[0] to control[degree].
struct OutlineSegment {
    std::array<glm::dvec2, 4> control{};
    int degree = 1;

    [[nodiscard]] static OutlineSegment line(glm::dvec2 a, glm::dvec2 b) { return {{a, b, {}, {}}, 1}; }
    [[nodiscard]] static OutlineSegment quadratic(glm::dvec2 a, glm::dvec2 b, glm::dvec2 c) { return {{a, b, c, {}}, 2}; }
    [[nodiscard]] static OutlineSegment cubic(glm::dvec2 a, glm::dvec2 b, glm::dvec2 c, glm::dvec2 d) {
        return {{a, b, c, d}, 3};
    }
    [[nodiscard]] glm::dvec2 start() const noexcept { return control[0]; }
    [[nodiscard]] glm::dvec2 end() const noexcept { return control[std::size_t(degree)]; }
};

/// A line in the plane as the points where dot(normal, p) + offset == 0.
struct OutlineLine {
    glm::dvec2 normal{0.0};
    double offset = 0.0;
};

/// Where a line meets an outline's curve: the curve parameter's point, and the outward normal
/// there (not unit length).
struct OutlineCrossing {
    glm::dvec2 point{0.0};
    glm::dvec2 outward{0.0};
};

class Outline {
public:
    /// `contours`: each a chain of segments, every segment starting where the one before it
    /// ends and the last ending where the first starts (gaps up to 1e-9 of the outline's extent
    /// are closed by moving the start to the end). Throws std::invalid_argument when a point is
    /// not finite, a segment's degree is not 1 to 3, or a contour is not a closed chain.
    explicit Outline(const std::vector<std::vector<OutlineSegment>>& contours);

    /// The box of the curves (not of their control points).
    [[nodiscard]] glm::dvec2 min() const noexcept { return min_; }
    [[nodiscard]] glm::dvec2 max() const noexcept { return max_; }
    [[nodiscard]] std::size_t contour_count() const noexcept { return contours_.size(); }
    [[nodiscard]] std::size_t segment_count() const noexcept { return segments_.size(); }

    /// Even-odd: the curves a half-line from p towards +x crosses, each y-monotone piece of a
    /// curve taken as half-open in y (as Polygon's edges), so a line through a joint of two
    /// pieces counts them once between them, or not at all where they turn back.
    [[nodiscard]] bool contains(glm::dvec2 p) const noexcept;

    /// Every point where `line` meets a curve (curve parameter in [0, 1]), handed to `visit`;
    /// contours and segments whose bounding boxes the line misses are not solved.
    template <class Visit> void for_each_crossing(const OutlineLine& line, Visit&& visit) const;

private:
    struct Segment {
        std::array<glm::dvec2, 4> power{};  ///< p(s) = power[0] + power[1] s + power[2] s^2 + power[3] s^3
        glm::dvec2 start{0.0}, end{0.0};     ///< exactly the control points, for the crossing count
        glm::dvec2 lo{0.0}, hi{0.0};         ///< bounding box of the control points (holds the curve)
        int degree = 1;
        [[nodiscard]] glm::dvec2 at(double s) const noexcept {
            if (s == 0.0) return start;
            if (s == 1.0) return end;
            return power[0] + s * (power[1] + s * (power[2] + s * power[3]));
        }
        [[nodiscard]] glm::dvec2 tangent(double s) const noexcept {
            return power[1] + s * (2.0 * power[2] + s * 3.0 * power[3]);
        }
    };
    /// A y-monotone piece of a segment, s in [s0, s1], for the crossing count.
    struct Piece {
        std::uint32_t segment;
        double s0, s1, y0, y1;
    };
    struct Contour {
        std::size_t first_segment, segment_end, first_piece, piece_end;
        glm::dvec2 lo, hi;
        bool left_is_solid;  ///< which side of its curves (seen along them) is inside the outline
    };

    [[nodiscard]] static std::array<double, 4> component(const Segment& g, int axis) noexcept {
        return {g.power[0][axis], g.power[1][axis], g.power[2][axis], g.power[3][axis]};
    }
    [[nodiscard]] bool contour_contains(const Contour& c, glm::dvec2 p) const noexcept;
    [[nodiscard]] static double signed_area(const std::vector<Segment>& segments, std::size_t begin, std::size_t end);

    std::vector<Segment> segments_;
    std::vector<Piece> pieces_;
    std::vector<Contour> contours_;
    glm::dvec2 min_{0.0}, max_{0.0};
};

namespace detail {

/// The real roots in [lo, hi] of c[0] + c[1] s + ... + c[degree] s^degree, ascending.
[[nodiscard]] inline Roots<3> outline_roots(const std::array<double, 4>& c, int degree, double lo, double hi) noexcept {
    Roots<3> out;
    // A curve of degree 3 whose cubic term cancels along this line is solved as the quadratic it is.
    while (degree > 1 && c[std::size_t(degree)] == 0.0) --degree;
    if (degree == 3) return roots_in<3>(c, lo, hi);
    const auto copy = [&](const auto& r) {
        for (std::size_t i = 0; i < r.count; ++i) out.push(r.value[i]);
        return out;
    };
    if (degree == 2) return copy(roots_in<2>({c[0], c[1], c[2]}, lo, hi));
    return copy(roots_in<1>({c[0], c[1]}, lo, hi));
}

/// Whether `line` misses the box [lo, hi]: all four corners strictly on one side.
[[nodiscard]] inline bool line_misses_box(const OutlineLine& line, glm::dvec2 lo, glm::dvec2 hi) noexcept {
    const double a = glm::dot(line.normal, lo) + line.offset, b = glm::dot(line.normal, glm::dvec2(hi.x, lo.y)) + line.offset;
    const double c = glm::dot(line.normal, hi) + line.offset, d = glm::dot(line.normal, glm::dvec2(lo.x, hi.y)) + line.offset;
    return (a > 0 && b > 0 && c > 0 && d > 0) || (a < 0 && b < 0 && c < 0 && d < 0);
}

}  // namespace detail

inline Outline::Outline(const std::vector<std::vector<OutlineSegment>>& contours) {
    min_ = glm::dvec2(std::numeric_limits<double>::infinity());
    max_ = -min_;
    for (const auto& contour : contours)
        for (const auto& g : contour) {
            if (g.degree < 1 || g.degree > 3) throw std::invalid_argument("outline: a segment's degree must be 1, 2 or 3");
            for (int k = 0; k <= g.degree; ++k) {
                const glm::dvec2 p = g.control[std::size_t(k)];
                if (!std::isfinite(p.x) || !std::isfinite(p.y)) throw std::invalid_argument("outline: points must be finite");
                min_ = glm::min(min_, p), max_ = glm::max(max_, p);
            }
        }
    if (!(min_.x <= max_.x)) throw std::invalid_argument("outline: it has no segments");
    const auto largest = [](glm::dvec2 v) { return std::max(std::abs(v.x), std::abs(v.y)); };
    const double gap = 1e-9 * std::max({largest(max_ - min_), largest(min_), largest(max_)});
    glm::dvec2 tight_lo = max_, tight_hi = min_;
    for (const auto& contour : contours) {
        if (contour.empty()) continue;
        Contour c{segments_.size(), 0, pieces_.size(), 0, glm::dvec2(std::numeric_limits<double>::infinity()),
                  glm::dvec2(-std::numeric_limits<double>::infinity()), true};
        for (std::size_t k = 0; k < contour.size(); ++k) {
            OutlineSegment g = contour[k];
            // Joints shared exactly: the crossing count then sees one point where two curves meet.
            const glm::dvec2 previous_end = contour[(k + contour.size() - 1) % contour.size()].end();
            if (largest(g.start() - previous_end) > gap)
                throw std::invalid_argument("outline: a contour is not closed (a segment does not start where the one "
                                            "before it ends)");
            g.control[0] = previous_end;
            Segment s;
            const auto& p = g.control;
            if (g.degree == 1) s.power = {p[0], p[1] - p[0], glm::dvec2(0.0), glm::dvec2(0.0)};
            else if (g.degree == 2) s.power = {p[0], 2.0 * (p[1] - p[0]), p[0] - 2.0 * p[1] + p[2], glm::dvec2(0.0)};
            else s.power = {p[0], 3.0 * (p[1] - p[0]), 3.0 * (p[0] - 2.0 * p[1] + p[2]), p[3] - p[0] + 3.0 * (p[1] - p[2])};
            s.degree = g.degree, s.start = g.start(), s.end = g.end();
            s.lo = s.hi = p[0];
            for (int i = 1; i <= g.degree; ++i) s.lo = glm::min(s.lo, p[std::size_t(i)]), s.hi = glm::max(s.hi, p[std::size_t(i)]);
            c.lo = glm::min(c.lo, s.lo), c.hi = glm::max(c.hi, s.hi);
            // The outline's box is the curves' own (their ends and turns), not their control points'.
            for (const glm::dvec2 q : {s.start, s.end}) tight_lo = glm::min(tight_lo, q), tight_hi = glm::max(tight_hi, q);
            for (int axis = 0; axis < 2; ++axis) {
                const auto a = component(s, axis);
                const auto turn = detail::outline_roots({a[1], 2.0 * a[2], 3.0 * a[3], 0.0}, std::max(1, g.degree - 1), 0.0, 1.0);
                for (std::size_t i = 0; i < turn.count; ++i) {
                    const double v = s.at(turn.value[i])[axis];
                    tight_lo[axis] = std::min(tight_lo[axis], v), tight_hi[axis] = std::max(tight_hi[axis], v);
                }
            }
            // Cut at the turns of y(s), so that each piece crosses a horizontal line at most once.
            const auto y = component(s, 1);
            const auto turns = detail::outline_roots({y[1], 2.0 * y[2], 3.0 * y[3], 0.0}, std::max(1, g.degree - 1), 0.0, 1.0);
            double s0 = 0.0;
            const auto index = std::uint32_t(segments_.size());
            for (std::size_t i = 0; i <= turns.count; ++i) {
                const double s1 = i < turns.count ? turns.value[i] : 1.0;
                if (s1 > s0) pieces_.push_back({index, s0, s1, s.at(s0).y, s.at(s1).y});
                s0 = std::max(s0, s1);
            }
            segments_.push_back(s);
        }
        c.segment_end = segments_.size(), c.piece_end = pieces_.size();
        contours_.push_back(c);
    }
    min_ = tight_lo, max_ = tight_hi;
    // Sides: a contour's inside is solid where the other contours leave a point of it outside
    // (an even count of them around it); its inside is on its left when it runs counter-clockwise.
    for (std::size_t i = 0; i < contours_.size(); ++i) {
        Contour& c = contours_[i];
        const glm::dvec2 probe = segments_[c.first_segment].at(0.5);
        bool covered = false;
        for (std::size_t j = 0; j < contours_.size(); ++j)
            if (j != i && contour_contains(contours_[j], probe)) covered = !covered;
        c.left_is_solid = (signed_area(segments_, c.first_segment, c.segment_end) > 0.0) != covered;
    }
}

inline double Outline::signed_area(const std::vector<Segment>& segments, std::size_t begin, std::size_t end) {
    // Green: area = 1/2 of the integral of x y' - y x'; a polynomial of degree <= 5 in s, so
    // 3-point Gauss-Legendre is exact.
    static constexpr double node[3] = {0.1127016653792583, 0.5, 0.8872983346207417};
    static constexpr double weight[3] = {5.0 / 18.0, 8.0 / 18.0, 5.0 / 18.0};
    double twice = 0.0;
    for (std::size_t k = begin; k < end; ++k)
        for (int i = 0; i < 3; ++i) {
            const glm::dvec2 p = segments[k].at(node[i]), t = segments[k].tangent(node[i]);
            twice += weight[i] * (p.x * t.y - p.y * t.x);
        }
    return 0.5 * twice;
}

inline bool Outline::contour_contains(const Contour& c, glm::dvec2 p) const noexcept {
    if (!(p.y >= c.lo.y && p.y <= c.hi.y && p.x <= c.hi.x)) return false;
    bool in = false;
    for (std::size_t k = c.first_piece; k < c.piece_end; ++k) {
        const Piece& piece = pieces_[k];
        if ((piece.y0 > p.y) == (piece.y1 > p.y)) continue;
        const Segment& g = segments_[piece.segment];
        if (g.hi.x <= p.x) continue;
        if (g.lo.x > p.x) {
            in = !in;
            continue;
        }
        auto y = component(g, 1);
        y[0] -= p.y;
        const auto root = detail::outline_roots(y, g.degree, piece.s0, piece.s1);
        // The piece is monotone and changes sides of the line: one root (rounding may report none
        // only at an end, where the end's own x decides).
        const double s = root.count > 0                                       ? root.value[0]
                         : std::abs(piece.y0 - p.y) <= std::abs(piece.y1 - p.y) ? piece.s0
                                                                                : piece.s1;
        if (g.at(s).x > p.x) in = !in;
    }
    return in;
}

inline bool Outline::contains(glm::dvec2 p) const noexcept {
    if (!(p.x >= min_.x && p.x <= max_.x && p.y >= min_.y && p.y <= max_.y)) return false;
    bool in = false;
    for (const Contour& c : contours_)
        if (contour_contains(c, p)) in = !in;
    return in;
}

template <class Visit> void Outline::for_each_crossing(const OutlineLine& line, Visit&& visit) const {
    if (detail::line_misses_box(line, min_, max_)) return;
    for (const Contour& c : contours_) {
        if (detail::line_misses_box(line, c.lo, c.hi)) continue;
        for (std::size_t k = c.first_segment; k < c.segment_end; ++k) {
            const Segment& g = segments_[k];
            if (detail::line_misses_box(line, g.lo, g.hi)) continue;
            std::array<double, 4> f{};
            for (std::size_t i = 0; i < 4; ++i) f[i] = glm::dot(line.normal, g.power[i]);
            f[0] += line.offset;
            const auto roots = detail::outline_roots(f, g.degree, 0.0, 1.0);
            for (std::size_t i = 0; i < roots.count; ++i) {
                const double s = roots.value[i];
                glm::dvec2 t = g.tangent(s);
                if (t == glm::dvec2(0.0))  // a cusp or a repeated control point: the chord around s
                    t = g.at(std::min(1.0, s + 1e-4)) - g.at(std::max(0.0, s - 1e-4));
                visit(OutlineCrossing{g.at(s), c.left_is_solid ? glm::dvec2(t.y, -t.x) : glm::dvec2(-t.y, t.x)});
            }
        }
    }
}

}  // namespace photon
