// SPDX-License-Identifier: MIT
#pragma once
// POV-Ray's prism: a planar outline (outline.hpp) in the xz plane swept along y between two
// heights, exactly (no tessellation). With a linear sweep every height has the outline itself;
// with a conic sweep the outline is scaled by the height (the point (u, v) of the outline is at
// (u y, y, v y)), a cone from the origin. TrueType text is the same solid (a glyph's outline
// swept over its thickness), placed with Transformed.

#include <algorithm>
#include <cmath>
#include <optional>
#include <stdexcept>
#include <utility>

#include "outline.hpp"
#include "primitive.hpp"

namespace photon {

enum class PrismSweep : std::uint8_t { linear, conic };

template <Scalar S> class Prism {
public:
    using scalar_type = S;

    /// The outline swept from y = height1 to y = height2. `open`: without the two caps (POV-Ray's
    /// `open`; the inside stays the closed solid's, as POV-Ray's). Throws std::invalid_argument
    /// unless height1 < height2, both finite.
    Prism(Outline outline, S height1, S height2, PrismSweep sweep = PrismSweep::linear, bool open = false)
        : outline_(std::move(outline)), h1_(double(height1)), h2_(double(height2)), sweep_(sweep), open_(open) {
        if (!(h1_ < h2_) || !std::isfinite(h1_) || !std::isfinite(h2_))
            throw std::invalid_argument("prism: height1 must be below height2, both finite");
        const glm::dvec2 lo = outline_.min(), hi = outline_.max();
        if (sweep_ == PrismSweep::linear) {
            bounds_ = {Vec3<S>(S(lo.x), S(h1_), S(lo.y)), Vec3<S>(S(hi.x), S(h2_), S(hi.y))};
        } else {
            for (const double h : {h1_, h2_})
                for (const glm::dvec2 c : {lo, hi, glm::dvec2(lo.x, hi.y), glm::dvec2(hi.x, lo.y)})
                    bounds_.extend(Vec3<S>(S(c.x * h), S(h), S(c.y * h)));
        }
        // Rounding to S must not shrink the box below the surface.
        const S pad = S(4) * std::numeric_limits<S>::epsilon() * bounds_.magnitude();
        bounds_.min -= pad, bounds_.max += pad;
    }

    [[nodiscard]] const Outline& outline() const noexcept { return outline_; }
    [[nodiscard]] S height1() const noexcept { return S(h1_); }
    [[nodiscard]] S height2() const noexcept { return S(h2_); }
    [[nodiscard]] PrismSweep sweep() const noexcept { return sweep_; }
    [[nodiscard]] bool open() const noexcept { return open_; }
    [[nodiscard]] BBox<S> bounds() const noexcept { return bounds_; }

    /// Solid: between the heights and inside the outline (scaled by the height for a conic sweep).
    [[nodiscard]] bool contains(const Vec3<S>& p) const noexcept { return contains_local(glm::dvec3(p)); }

    /// Nearest of the caps (ray-plane, then the outline's crossing count) and the sides (per
    /// curve, the ray's line against the curve: a polynomial of the curve's degree in its
    /// parameter), all in double.
    [[nodiscard]] std::optional<Hit<S>> intersect(const Ray<S>& ray) const noexcept {
        const glm::dvec3 o(ray.origin), d(ray.direction);
        double best = std::isfinite(double(ray.t_max)) ? double(ray.t_max) : std::numeric_limits<double>::infinity();
        glm::dvec3 normal(0.0);
        bool found = false;
        const auto take = [&](double t, const glm::dvec3& n) {
            if (t > 0.0 && t < best && S(t) > S(0) && S(t) < ray.t_max) best = t, normal = n, found = true;
        };
        if (!open_ && d.y != 0.0)
            for (const double h : {h1_, h2_}) {
                const double t = (h - o.y) / d.y;
                if (!(t > 0.0 && t < best)) continue;
                glm::dvec2 q(o.x + t * d.x, o.z + t * d.z);
                if (sweep_ == PrismSweep::conic) {
                    if (h == 0.0) continue;  // the apex: a point, no area
                    q /= h;
                }
                if (outline_.contains(q)) take(t, glm::dvec3(0.0, h == h1_ ? -1.0 : 1.0, 0.0));
            }
        if (sweep_ == PrismSweep::linear) sides_linear(o, d, take);
        else sides_conic(o, d, take);
        if (!found) return std::nullopt;
        const S t = S(best);
        return Hit<S>{t, ray.at(t), Vec3<S>(glm::normalize(normal))};
    }

private:
    [[nodiscard]] bool contains_local(const glm::dvec3& p) const noexcept {
        if (!(p.y >= h1_ && p.y <= h2_)) return false;
        if (sweep_ == PrismSweep::linear) return outline_.contains({p.x, p.z});
        return p.y != 0.0 && outline_.contains(glm::dvec2(p.x, p.z) / p.y);
    }

    /// Linear sweep: the ray's projection on the xz plane against each curve; the hit's height
    /// decides whether it is on the side.
    template <class Take> void sides_linear(const glm::dvec3& o, const glm::dvec3& d, Take& take) const {
        const glm::dvec2 o2(o.x, o.z), d2(d.x, d.z);
        const double speed2 = glm::dot(d2, d2);
        if (!(speed2 > 0.0)) return;  // along the axis: the sides are seen edge-on
        const glm::dvec2 n(-d2.y, d2.x);
        outline_.for_each_crossing({n, -glm::dot(n, o2)}, [&](const OutlineCrossing& c) {
            const double t = glm::dot(c.point - o2, d2) / speed2;
            const double y = o.y + t * d.y;
            if (y >= h1_ && y <= h2_) take(t, glm::dvec3(c.outward.x, 0.0, c.outward.y));
        });
    }

    /// Conic sweep: the side is the cone of lines from the origin through (u, 1, v) on the
    /// outline, so the plane through the origin and the ray meets it where the outline meets the
    /// line n.x u + n.z v + n.y = 0 (n = o x d); the ray meets that generator at one t.
    template <class Take> void sides_conic(const glm::dvec3& o, const glm::dvec3& d, Take& take) const {
        const glm::dvec3 n = glm::cross(o, d);
        if (n == glm::dvec3(0.0)) return;  // a ray through the apex: it meets the side edge-on
        outline_.for_each_crossing({{n.x, n.z}, n.y}, [&](const OutlineCrossing& c) {
            const glm::dvec3 w(c.point.x, 1.0, c.point.y);
            const glm::dvec3 dw = glm::cross(d, w);
            const double dw2 = glm::dot(dw, dw);
            if (!(dw2 > 0.0)) return;  // the ray runs along the generator
            const double t = -glm::dot(glm::cross(o, w), dw) / dw2;
            const double y = o.y + t * d.y;
            if (!(y >= h1_ && y <= h2_) || y == 0.0) return;
            // Outward in the cross-section at height y (the outline scaled by y, turned half
            // round when y < 0), tilted to be normal to the generator w.
            const glm::dvec2 out = y > 0.0 ? c.outward : -c.outward;
            take(t, glm::dvec3(out.x, -(out.x * w.x + out.y * w.z), out.y));
        });
    }

    Outline outline_;
    double h1_, h2_;
    PrismSweep sweep_;
    bool open_;
    BBox<S> bounds_;
};

}  // namespace photon
