// SPDX-License-Identifier: MIT
#pragma once
// POV-Ray's functions that ask an object's geometry while the scene is read: trace(),
// min_extent() and max_extent() (the parser holds no geometry; ParseOptions::geometry answers),
// and inside(), which the description answers for the solids photon has.

#include <photon/geometry/lathe.hpp>
#include <photon/geometry/outline.hpp>
#include <photon/geometry/polynomial_surface.hpp>
#include <photon/geometry/sor.hpp>
#include <photon/geometry/superellipsoid.hpp>

#include "../build/library_shape.hpp"
#include "parser_class.hpp"

namespace photon::dsl::detail {

// OBJECT_QUERY: trace ( OBJECT_ID , FROM , DIRECTION [, NORMAL_ID] ) | min_extent ( OBJECT_ID )
//             | max_extent ( OBJECT_ID )
inline Numeric Parser::parse_object_query(const Token& f) {
    const std::string& w = f.text;
    expect_symbol("(", "after `" + w + "`");
    const bool saved = in_vector_;
    in_vector_ = false;
    const Token id = next();
    const Value* v = id.kind == TokenKind::identifier ? lookup(id.text) : nullptr;
    if (!v || !std::holds_alternative<Object>(v->data) || std::holds_alternative<LightSource>(std::get<Object>(v->data).shape))
        fail_expected("an object identifier as the first argument of `" + w + "`", id);
    const Object obj = std::get<Object>(v->data);
    if (!options_.geometry)
        fail(f.location, "`" + w + "` needs the object's geometry while the scene is read: set ParseOptions::geometry "
                         "(photon::dsl::library_object_geometry())");
    Numeric result;
    if (w == "trace") {
        expect_symbol(",", "after the object of `trace`");
        const SourceLocation from_at = peek().location;
        const Vector3 from = to_vector(parse_expression_for("the ray's origin in `trace`"), "the ray's origin", from_at);
        expect_symbol(",", "after the ray's origin in `trace`");
        const SourceLocation dir_at = peek().location;
        const Vector3 dir = to_vector(parse_expression_for("the ray's direction in `trace`"), "the ray's direction", dir_at);
        if (glm::length(dir) == 0.0) fail(dir_at, "the direction of `trace` must not be zero");
        std::optional<Token> normal_id;
        if (accept_symbol(",")) {
            normal_id = next();
            if (normal_id->kind != TokenKind::identifier || is_reserved(normal_id->text))
                fail_expected("an identifier to receive the normal in `trace`", *normal_id);
        }
        expect_symbol(")", "to close the arguments of `trace`");
        const auto hit = options_.geometry->trace(obj, from, dir);
        // POV-Ray's answer for a miss: the point and the normal are <0, 0, 0>.
        result = Numeric::vector(hit ? hit->point : Vector3(0.0));
        if (normal_id) {
            const Numeric n = Numeric::vector(hit ? hit->normal : Vector3(0.0));
            assign(*normal_id, n, false);  // as `#declare`
        }
    } else {
        expect_symbol(")", "to close the arguments of `" + w + "`");
        const ObjectGeometry::Bounds b = options_.geometry->bounds(obj);
        result = Numeric::vector(w == "min_extent" ? b.min : b.max);
    }
    in_vector_ = saved;
    return result;
}

/// Whether `p` is inside the solid of revolution from `base` (radius r0) to `cap` (radius r1).
[[nodiscard]] inline bool inside_frustum(const Vector3& p, const Vector3& base, double r0, const Vector3& cap, double r1) {
    const Vector3 axis = cap - base;
    const double length = glm::length(axis);
    const double h = glm::dot(p - base, axis) / length;
    if (h < 0 || h > length) return false;
    const double r = r0 + (r1 - r0) * h / length;
    const Vector3 radial = p - base - axis * (h / length);
    return glm::dot(radial, radial) <= r * r;
}

/// POV-Ray's Inside test: solids contain their inside (boundary included, within POV-Ray's
/// tolerance); triangles and meshes without inside_vector contain nothing.
[[nodiscard]] inline bool object_contains(const Object& o, const Vector3& world) {
    constexpr double tolerance = 1e-10;
    const Vector3 p = o.transform.inverse().point(world);
    const bool in = std::visit(
        [&](const auto& s) -> bool {
            using S = std::decay_t<decltype(s)>;
            if constexpr (std::is_same_v<S, SphereShape>) {
                const Vector3 d = p - s.center;
                return glm::dot(d, d) < s.radius * s.radius;
            } else if constexpr (std::is_same_v<S, BoxShape>) {
                const Vector3 lo = glm::min(s.corner1, s.corner2), hi = glm::max(s.corner1, s.corner2);
                for (int k = 0; k < 3; ++k)
                    if (p[k] < lo[k] - tolerance || p[k] > hi[k] + tolerance) return false;
                return true;
            } else if constexpr (std::is_same_v<S, PlaneShape>) {
                return glm::dot(p, glm::normalize(s.normal)) - s.distance < tolerance;
            } else if constexpr (std::is_same_v<S, CylinderShape>) {
                return inside_frustum(p, s.base, s.radius, s.cap, s.radius);
            } else if constexpr (std::is_same_v<S, ConeShape>) {  // open or closed: the solid (POV-Ray)
                return inside_frustum(p, s.base, s.base_radius, s.cap, s.cap_radius);
            } else if constexpr (std::is_same_v<S, DiscShape>) {  // POV-Ray: the half-space behind the normal
                return glm::dot(p - s.center, glm::normalize(s.normal)) < 0;
            } else if constexpr (std::is_same_v<S, TorusShape>) {
                const double ring = std::sqrt(p.x * p.x + p.z * p.z) - s.major;
                return p.y * p.y + ring * ring <= s.minor * s.minor;
            } else if constexpr (std::is_same_v<S, QuadricShape>) {  // POV-Ray's Inside_Quadric: <= 0, no tolerance
                const Vector3 m = s.mixed;
                return s.squares.x * p.x * p.x + s.squares.y * p.y * p.y + s.squares.z * p.z * p.z + m.x * p.x * p.y +
                           m.y * p.x * p.z + m.z * p.y * p.z + glm::dot(s.linear, p) + s.constant <=
                       0;
            } else if constexpr (std::is_same_v<S, PrismShape>) {  // POV-Ray's Inside: the closed solid, also when open
                if (!(p.y >= s.height1 && p.y <= s.height2)) return false;
                glm::dvec2 q(p.x, p.z);
                if (s.sweep == PrismShape::Sweep::conic) {
                    if (std::abs(p.y) <= tolerance) return false;
                    q /= p.y;
                }
                std::vector<std::vector<OutlineSegment>> contours;
                for (const auto& contour : *s.contours) {
                    contours.emplace_back();
                    for (const OutlineCurve& c : contour) contours.back().push_back({c.control, c.degree});
                }
                return Outline(contours).contains(q);
            } else if constexpr (std::is_same_v<S, PolynomialShape>) {  // POV-Ray's Inside_Poly (the gate plays no part)
                return PolynomialSurface<double>(s.order, *s.coefficients).value(p) < 1e-4;  // INSIDE_TOLERANCE
            } else if constexpr (std::is_same_v<S, SuperellipsoidShape>) {
                return Superellipsoid<double>(s.e, s.n).contains(p);
            } else if constexpr (std::is_same_v<S, LatheShape>) {  // POV-Ray's crossing parity
                std::vector<OutlineSegment> profile;
                for (const OutlineCurve& c : *s.profile) profile.push_back({c.control, c.degree});
                return Lathe<double>(profile).contains(p);
            } else if constexpr (std::is_same_v<S, SorShape>) {  // the closed solid, also when open (POV-Ray)
                return Sor<double>(*s.points).contains(p);
            } else if constexpr (std::is_same_v<S, BlobShape>) {  // POV-Ray's Inside_Blob: the field above the threshold
                return blob_of<double>(s).contains(p);
            } else if constexpr (std::is_same_v<S, UnionShape>) {
                for (const auto& child : s.children)
                    if (object_contains(*child, p)) return true;
                return false;
            } else if constexpr (std::is_same_v<S, CsgShape>) {
                using Op = CsgShape::Operation;
                if (s.operation == Op::merge) {
                    for (const auto& child : s.children)
                        if (object_contains(*child, p)) return true;
                    return false;
                }
                if (s.operation == Op::intersection) {
                    for (const auto& child : s.children)
                        if (!object_contains(*child, p)) return false;
                    return true;
                }
                if (!object_contains(*s.children.front(), p)) return false;
                for (std::size_t k = 1; k < s.children.size(); ++k)
                    if (object_contains(*s.children[k], p)) return false;
                return true;
            } else {
                return false;
            }
        },
        o.shape);
    return in != o.inverse;
}

/// Whether one of `bounds` is shown to hold the whole of `obj`: every corner of obj's bounding box
/// inside one convex bound (a sphere, box, cylinder or cone, not inverse; convex, so its corners
/// inside mean the box is), or obj has nothing photon renders (a skipped shape says so itself).
/// False when that cannot be shown (a loose box, a bound of another shape, no library geometry).
inline bool Parser::bound_contains(const Object& obj, const std::vector<Object>& bounds) const {
    if (!options_.geometry) return false;
    const ObjectGeometry::Bounds b = options_.geometry->bounds(obj);
    if (!(b.min.x < b.max.x || b.min.y < b.max.y || b.min.z < b.max.z)) return true;  // nothing to bound
    for (const Object& bound : bounds) {
        const bool convex = !bound.inverse && (std::holds_alternative<SphereShape>(bound.shape) ||
                                               std::holds_alternative<BoxShape>(bound.shape) ||
                                               std::holds_alternative<CylinderShape>(bound.shape) ||
                                               std::holds_alternative<ConeShape>(bound.shape));
        if (!convex) continue;
        bool all = true;
        for (int c = 0; c < 8 && all; ++c)
            all = object_contains(bound, Vector3(c & 1 ? b.max.x : b.min.x, c & 2 ? b.max.y : b.min.y,
                                                 c & 4 ? b.max.z : b.min.z));
        if (all) return true;
    }
    return false;
}

// INSIDE: inside ( OBJECT_ID , VECTOR )
inline Numeric Parser::parse_inside(const Token& f) {
    expect_symbol("(", "after `inside`");
    const bool saved = in_vector_;
    in_vector_ = false;
    const Token id = next();
    const Value* v = id.kind == TokenKind::identifier ? lookup(id.text) : nullptr;
    if (!v || !std::holds_alternative<Object>(v->data) || std::holds_alternative<LightSource>(std::get<Object>(v->data).shape))
        fail_expected("an object identifier as the first argument of `inside`", id);
    const Object obj = std::get<Object>(v->data);
    expect_symbol(",", "after the object of `inside`");
    const Vector3 p = parse_vector("a point as argument 2 of `inside`");
    expect_symbol(")", "to close the arguments of `inside`");
    in_vector_ = saved;
    (void)f;
    return Numeric::scalar(object_contains(obj, p) ? 1.0 : 0.0);
}

}  // namespace photon::dsl::detail
