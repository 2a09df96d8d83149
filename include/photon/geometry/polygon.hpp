// SPDX-License-Identifier: MIT
#pragma once
// POV-Ray's polygon: flat outlines (loops) in one plane, filled by the even-odd rule over all
// their edges, so a loop inside another cuts a hole and overlapping loops cancel where they
// overlap. Like a triangle it has no inside.

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <stdexcept>
#include <vector>

#include "primitive.hpp"

namespace photon {

/// The plane of a polygon's points, as POV-Ray finds it: origin at the first point, u along the
/// first point apart from it, w = u x v for the first point v off that line, v = w x u.
struct PolygonFrame {
    glm::dvec3 origin{0.0}, u{1, 0, 0}, v{0, 1, 0}, w{0, 0, 1};
};

/// The frame of `points`, or nothing when they are all on one line or not in one plane: farther
/// from it than 1e-9 of their extent, or than S's rounding of their coordinates (a polygon moved
/// in double and stored in float stays flat).
template <Scalar S> [[nodiscard]] std::optional<PolygonFrame> polygon_frame(const std::vector<Vec3<S>>& points) {
    if (points.size() < 3) return std::nullopt;
    PolygonFrame f;
    f.origin = glm::dvec3(points[0]);
    double extent = 0.0, magnitude = 0.0;
    for (const auto& p : points) {
        extent = std::max(extent, glm::length(glm::dvec3(p) - f.origin));
        magnitude = std::max(magnitude, double(max_component(glm::abs(p))));
    }
    if (!(extent > 0.0) || !std::isfinite(extent)) return std::nullopt;
    const double tiny = std::max(1e-9 * extent, 64.0 * double(std::numeric_limits<S>::epsilon()) * magnitude);
    std::size_t i = 1;
    while (i < points.size() && !(glm::length(glm::dvec3(points[i]) - f.origin) > tiny)) ++i;
    if (i == points.size()) return std::nullopt;
    const glm::dvec3 u = glm::dvec3(points[i]) - f.origin;
    glm::dvec3 w(0.0);
    for (++i; i < points.size(); ++i) {
        w = glm::cross(u, glm::dvec3(points[i]) - f.origin);
        if (glm::length(w) > tiny * glm::length(u)) break;
    }
    if (i == points.size()) return std::nullopt;  // all on one line
    f.w = glm::normalize(w);
    f.u = glm::normalize(u);
    f.v = glm::cross(f.w, f.u);
    for (const auto& p : points)
        if (std::abs(glm::dot(glm::dvec3(p) - f.origin, f.w)) > tiny) return std::nullopt;
    return f;
}

template <Scalar S> class Polygon {
public:
    using scalar_type = S;

    /// `loops`: each a closed outline (its last point joins its first), all in one plane. The
    /// normal is that of POV-Ray's frame (polygon_frame) of all the points. Throws
    /// std::invalid_argument when the points are not finite, all on one line or not in one plane.
    explicit Polygon(const std::vector<std::vector<Vec3<S>>>& loops) {
        std::vector<Vec3<S>> all;
        for (const auto& loop : loops) all.insert(all.end(), loop.begin(), loop.end());
        for (const auto& p : all)
            if (!is_finite(p)) throw std::invalid_argument("polygon: points must be finite");
        const auto frame = polygon_frame(all);
        if (!frame) throw std::invalid_argument("polygon: its points are all on one line or not in one plane");
        frame_ = *frame;
        normal_ = Vec3<S>(frame_.w);
        for (const auto& loop : loops)
            for (std::size_t k = 0; k < loop.size(); ++k) {
                const glm::dvec2 a = flat(loop[k]), b = flat(loop[(k + 1) % loop.size()]);
                if (a.y != b.y) edges_.push_back({a, b});  // a horizontal edge never crosses the test line
            }
        for (const auto& p : all) bounds_.extend(p);
    }

    [[nodiscard]] const Vec3<S>& normal() const noexcept { return normal_; }
    [[nodiscard]] BBox<S> bounds() const noexcept { return bounds_; }

    /// The plane's crossing measured from the polygon's first point (a far ray origin cancels
    /// no digits of the polygon's offset), kept when the even-odd rule puts it inside.
    [[nodiscard]] std::optional<Hit<S>> intersect(const Ray<S>& ray) const noexcept {
        const glm::dvec3 d(ray.direction), o = glm::dvec3(ray.origin) - frame_.origin;
        const double denom = glm::dot(d, frame_.w);
        if (denom == 0.0) return std::nullopt;  // parallel, also when in the plane: no area seen
        const double t_local = -glm::dot(o, frame_.w) / denom;
        const S t = S(t_local);
        if (!(t > S(0)) || !(t < ray.t_max)) return std::nullopt;
        const glm::dvec3 q = o + t_local * d;
        if (!inside(glm::dvec2(glm::dot(q, frame_.u), glm::dot(q, frame_.v)))) return std::nullopt;
        return Hit<S>{t, ray.at(t), normal_};
    }

private:
    struct Edge {
        glm::dvec2 a, b;
    };
    [[nodiscard]] glm::dvec2 flat(const Vec3<S>& p) const noexcept {
        const glm::dvec3 r = glm::dvec3(p) - frame_.origin;
        return {glm::dot(r, frame_.u), glm::dot(r, frame_.v)};
    }
    /// Even-odd: the edges a line from p towards +u crosses (each edge taken as half-open in v,
    /// so a line through a vertex counts the two edges meeting there once between them).
    [[nodiscard]] bool inside(const glm::dvec2& p) const noexcept {
        bool in = false;
        for (const Edge& e : edges_) {
            if ((e.a.y > p.y) == (e.b.y > p.y)) continue;
            const double x = e.a.x + (p.y - e.a.y) * (e.b.x - e.a.x) / (e.b.y - e.a.y);
            if (x > p.x) in = !in;
        }
        return in;
    }

    PolygonFrame frame_;
    Vec3<S> normal_;
    std::vector<Edge> edges_;
    BBox<S> bounds_;
};

}  // namespace photon
