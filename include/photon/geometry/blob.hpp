// SPDX-License-Identifier: MIT
#pragma once
// POV-Ray's blob: the points where a sum of component fields exceeds a threshold. A component
// adds strength * (1 - (d / radius)^2)^2 where d < radius, d the distance to its centre (a
// sphere component) or to its segment (a cylinder component, whose ends are hemispheres), both
// measured in the component's own space (a sphere component scaled unevenly is an ellipsoid).
// A negative strength carves.
//
// Along a ray each piece of a component (a ball; a cylinder's body and its two end caps, as
// POV-Ray splits it) is active on one span of t, and inside it d^2 is a quadratic in t, so its
// field is a quartic. Between consecutive span ends the sum minus the threshold is one quartic,
// solved on that stretch by bracketing (polynomial_roots.hpp) after moving the origin to the
// stretch's start and its length to 1 (the coefficients then do not depend on how far the ray
// started or on the scene's scale). POV-Ray does the same, with its own quartic solver (or Sturm
// sequences when asked: `sturm` changes nothing here). The field and its first derivative are
// continuous where a piece starts or ends, so a crossing is never lost at a stretch's end.

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <stdexcept>
#include <vector>

#include "../math/transform.hpp"
#include "polynomial_roots.hpp"
#include "primitive.hpp"

namespace photon {

template <Scalar S> class Blob {
public:
    using scalar_type = S;

    /// One of POV-Ray's components, as written: `sphere { centre, radius, strength }` or
    /// `cylinder { a, b, radius, strength }`, then its own transforms (`placement`, from the
    /// component's space to the blob's).
    struct Component {
        enum class Kind { sphere, cylinder };
        Kind kind = Kind::sphere;
        Vec3<S> a{S(0)};  ///< the sphere's centre, or the cylinder's first end
        Vec3<S> b{S(0)};  ///< the cylinder's second end (unused by a sphere)
        S radius = S(1);
        S strength = S(1);
        Affine<S> placement{};

        [[nodiscard]] static Component sphere(const Vec3<S>& centre, S radius, S strength) {
            return {Kind::sphere, centre, centre, radius, strength, {}};
        }
        [[nodiscard]] static Component cylinder(const Vec3<S>& a, const Vec3<S>& b, S radius, S strength) {
            return {Kind::cylinder, a, b, radius, strength, {}};
        }
    };

    /// Throws std::invalid_argument when a radius is not positive and finite, a cylinder's ends
    /// coincide (POV-Ray: "degenerate cylindrical component"), a placement is singular, or the
    /// threshold is not positive (the blob would fill space outside its components). Components of
    /// strength 0 add nothing and are dropped.
    Blob(std::vector<Component> components, S threshold) : components_(std::move(components)), threshold_(threshold) {
        if (!(threshold > S(0)) || !std::isfinite(threshold))
            throw std::invalid_argument("blob: the threshold must be positive and finite");
        for (const Component& c : components_) add_pieces(c);
        for (const Piece& p : pieces_)
            if (p.k2 > 0.0) extend(box_, p);
    }

    [[nodiscard]] S threshold() const noexcept { return threshold_; }
    [[nodiscard]] const std::vector<Component>& components() const noexcept { return components_; }

    /// The components of positive strength: no point outside them can reach a positive threshold.
    [[nodiscard]] BBox<S> bounds() const noexcept {
        if (box_.is_empty()) return {};
        const Vec3<S> pad = Vec3<S>(S(16) * std::numeric_limits<S>::epsilon()) *
                            (glm::abs(Vec3<S>(box_.min)) + glm::abs(Vec3<S>(box_.max)));
        return {Vec3<S>(box_.min) - pad, Vec3<S>(box_.max) + pad};
    }

    /// The summed field at p.
    [[nodiscard]] double field(const Vec3<S>& p) const noexcept {
        double sum = 0.0;
        for (const Piece& piece : pieces_) sum += piece.field(glm::dvec3(p));
        return sum;
    }

    /// Solid: the field exceeds the threshold (POV-Ray's Inside).
    [[nodiscard]] bool contains(const Vec3<S>& p) const noexcept { return field(p) > double(threshold_); }

    [[nodiscard]] std::optional<Hit<S>> intersect(const Ray<S>& ray) const {
        const glm::dvec3 o(ray.origin), d(ray.direction);
        const double t_max = std::isfinite(double(ray.t_max)) ? double(ray.t_max) : std::numeric_limits<double>::max();
        thread_local std::vector<Span> spans;
        thread_local std::vector<double> ends;
        spans.clear();
        ends.clear();
        for (const Piece& piece : pieces_) {
            const auto span = piece.span(o, d);
            if (!span) continue;
            const double t0 = std::max(span->first, 0.0), t1 = std::min(span->second, t_max);
            if (!(t0 < t1)) continue;
            spans.push_back({&piece, t0, t1});
            ends.push_back(t0);
            ends.push_back(t1);
        }
        if (spans.empty()) return std::nullopt;
        std::sort(ends.begin(), ends.end());
        for (std::size_t i = 0; i + 1 < ends.size(); ++i) {
            const double ta = ends[i], tb = ends[i + 1];
            if (!(tb > ta)) continue;
            const double mid = 0.5 * (ta + tb), width = tb - ta;
            std::array<double, 5> c{-double(threshold_), 0.0, 0.0, 0.0, 0.0};
            bool active = false;
            for (const Span& s : spans) {
                if (!(s.t0 <= mid && mid <= s.t1)) continue;
                s.piece->add_quartic(o + ta * d, width * d, c);
                active = true;
            }
            if (!active) continue;
            const auto roots = detail::roots_in<4>(c, 0.0, 1.0);
            for (std::size_t k = 0; k < roots.count; ++k) {
                const double t = ta + roots.value[k] * width;
                const S ts = S(t);
                if (!(ts > S(0)) || !(ts < ray.t_max)) continue;
                return Hit<S>{ts, ray.at(ts), Vec3<S>(normal_at(o + t * d, d))};
            }
        }
        return std::nullopt;
    }

private:
    /// A ball, or a cylinder's body or end cap, in its own frame: `local = linear * p + offset`
    /// takes a blob-space point there, where the ball is centred at the origin and the cylinder
    /// runs from the origin along z for `length`.
    struct Piece {
        enum class Kind { ball, body, base_cap, apex_cap };
        Kind kind;
        glm::dmat3 linear;
        glm::dvec3 offset;
        double length, radius2;
        double k0, k1, k2;  // field = k0 r^4 + k1 r^2 + k2 for r^2 < radius2

        /// The point relative to what d is measured from, with the component along the axis
        /// dropped for the body.
        [[nodiscard]] glm::dvec3 radial(const glm::dvec3& local) const noexcept {
            switch (kind) {
            case Kind::body: return {local.x, local.y, 0.0};
            case Kind::apex_cap: return {local.x, local.y, local.z - length};
            default: return local;
            }
        }
        [[nodiscard]] bool covers(const glm::dvec3& local) const noexcept {
            switch (kind) {
            case Kind::body: return local.z >= 0.0 && local.z <= length;
            case Kind::base_cap: return local.z < 0.0;
            case Kind::apex_cap: return local.z > length;
            default: return true;
            }
        }
        [[nodiscard]] double field(const glm::dvec3& p) const noexcept {
            const glm::dvec3 local = linear * p + offset;
            if (!covers(local)) return 0.0;
            const glm::dvec3 q = radial(local);
            const double r2 = glm::dot(q, q);
            return r2 < radius2 ? (k0 * r2 + k1) * r2 + k2 : 0.0;
        }
        /// d(field)/dp in blob space (0 outside the piece).
        [[nodiscard]] glm::dvec3 gradient(const glm::dvec3& p) const noexcept {
            const glm::dvec3 local = linear * p + offset;
            if (!covers(local)) return glm::dvec3(0.0);
            const glm::dvec3 q = radial(local);
            const double r2 = glm::dot(q, q);
            if (!(r2 < radius2)) return glm::dvec3(0.0);
            return glm::transpose(linear) * ((2.0 * (2.0 * k0 * r2 + k1)) * q);
        }

        /// The t where the ray o + t d is inside the piece's reach (r < radius, within the body's
        /// or a cap's part of the axis), or nothing.
        [[nodiscard]] std::optional<std::pair<double, double>> span(const glm::dvec3& o, const glm::dvec3& d) const noexcept {
            glm::dvec3 p = linear * o + offset, v = linear * d;
            if (kind == Kind::apex_cap) p.z -= length;
            double t0 = -std::numeric_limits<double>::infinity(), t1 = std::numeric_limits<double>::infinity();
            if (kind != Kind::ball) {  // the part of the axis: z in [0, length], z <= 0 or z >= 0
                const double lo = kind == Kind::apex_cap ? 0.0 : kind == Kind::base_cap ? -std::numeric_limits<double>::infinity() : 0.0;
                const double hi = kind == Kind::body ? length : kind == Kind::base_cap ? 0.0 : std::numeric_limits<double>::infinity();
                if (v.z == 0.0) {
                    if (!(p.z >= lo && p.z <= hi)) return std::nullopt;
                } else {
                    double a = (lo - p.z) / v.z, b = (hi - p.z) / v.z;
                    if (a > b) std::swap(a, b);
                    t0 = std::max(t0, a), t1 = std::min(t1, b);
                }
                if (kind == Kind::body) p.z = v.z = 0.0;
            }
            // r^2 < radius2: from the closest approach (Hearn and Baker), exact for a far origin.
            const double a = glm::dot(v, v);
            if (!(a > 0.0)) {
                if (!(glm::dot(p, p) < radius2)) return std::nullopt;
            } else {
                const double b = glm::dot(p, v);
                const glm::dvec3 closest = p - (b / a) * v;
                const double reach2 = radius2 - glm::dot(closest, closest);
                if (!(reach2 > 0.0)) return std::nullopt;
                const double half = std::sqrt(reach2 / a), centre = -b / a;
                t0 = std::max(t0, centre - half), t1 = std::min(t1, centre + half);
            }
            if (!(t0 < t1)) return std::nullopt;
            return std::pair{t0, t1};
        }

        /// Adds this piece's field along p + u v (u in [0, 1]) to the quartic c (c[k] multiplies
        /// u^k): r^2 = A u^2 + 2 B u + C, field = k0 (r^2)^2 + k1 r^2 + k2.
        void add_quartic(const glm::dvec3& p_world, const glm::dvec3& v_world, std::array<double, 5>& c) const noexcept {
            glm::dvec3 p = linear * p_world + offset, v = linear * v_world;
            p = radial(p);
            if (kind == Kind::body) v.z = 0.0;
            const double a = glm::dot(v, v), b = glm::dot(p, v), r = glm::dot(p, p);
            c[4] += k0 * a * a;
            c[3] += 4.0 * k0 * a * b;
            c[2] += k0 * (4.0 * b * b + 2.0 * a * r) + k1 * a;
            c[1] += 4.0 * k0 * b * r + 2.0 * k1 * b;
            c[0] += (k0 * r + k1) * r + k2;
        }
    };

    struct Span {
        const Piece* piece;
        double t0, t1;
    };

    void add_pieces(const Component& c) {
        const double radius = double(c.radius), strength = double(c.strength);
        if (!(radius > 0.0) || !std::isfinite(radius) || !std::isfinite(strength))
            throw std::invalid_argument("blob: a component's radius must be positive and finite");
        const Affine<double> placement{glm::dmat3(c.placement.linear), glm::dvec3(c.placement.translation)};
        const double det = placement.determinant();
        if (!(std::abs(det) > 0.0) || !std::isfinite(det) || !is_finite(placement.translation))
            throw std::invalid_argument("blob: a component's transform must be invertible and finite");
        if (strength == 0.0) return;
        const Affine<double> to_component = placement.inverse();
        const double r2 = radius * radius;
        Piece piece{Piece::Kind::ball, to_component.linear, to_component.translation - glm::dvec3(c.a), 0.0, r2,
                    strength / (r2 * r2), -2.0 * strength / r2, strength};
        if (c.kind == Component::Kind::sphere) {
            pieces_.push_back(piece);
            return;
        }
        const glm::dvec3 a(c.a), axis = glm::dvec3(c.b) - a;
        const double length = glm::length(axis);
        if (!(length > 0.0) || !std::isfinite(length))
            throw std::invalid_argument("blob: a cylinder component's ends must differ");
        // A frame with z along the axis: rows are its unit vectors, so frame * (q - a) is local.
        const glm::dvec3 z = axis / length;
        const glm::dvec3 helper = std::abs(z.x) < 0.9 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 1, 0);
        const glm::dvec3 x = glm::normalize(glm::cross(helper, z)), y = glm::cross(z, x);
        const glm::dmat3 frame = glm::transpose(glm::dmat3(x, y, z));
        piece.linear = frame * to_component.linear;
        piece.offset = frame * (to_component.translation - a);
        piece.length = length;
        for (const auto kind : {Piece::Kind::body, Piece::Kind::base_cap, Piece::Kind::apex_cap}) {
            piece.kind = kind;
            pieces_.push_back(piece);
        }
    }

    /// Grows `box` by the blob-space box around the piece's reach.
    static void extend(BBox<double>& box, const Piece& p) {
        const double r = std::sqrt(p.radius2);
        glm::dvec3 lo(-r), hi(r);
        if (p.kind == Piece::Kind::body) hi.z = p.length;
        if (p.kind == Piece::Kind::base_cap) hi.z = 0.0;
        if (p.kind == Piece::Kind::apex_cap) lo.z = p.length, hi.z = p.length + r;
        const glm::dmat3 back = glm::inverse(p.linear);
        for (int corner = 0; corner < 8; ++corner) {
            const glm::dvec3 q{(corner & 1) ? hi.x : lo.x, (corner & 2) ? hi.y : lo.y, (corner & 4) ? hi.z : lo.z};
            box.extend(back * (q - p.offset));
        }
    }

    /// The outward normal: the field falls outward, so against its gradient.
    [[nodiscard]] glm::dvec3 normal_at(const glm::dvec3& p, const glm::dvec3& ray_direction) const noexcept {
        glm::dvec3 g(0.0);
        for (const Piece& piece : pieces_) g += piece.gradient(p);
        const double length = glm::length(g);
        if (!(length > 0.0) || !std::isfinite(length)) return -glm::normalize(ray_direction);  // a flat point
        return -g / length;
    }

    std::vector<Component> components_;
    S threshold_;
    std::vector<Piece> pieces_;
    BBox<double> box_{};
};

}  // namespace photon
