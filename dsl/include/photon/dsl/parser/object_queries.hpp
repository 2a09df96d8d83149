// SPDX-License-Identifier: MIT
#pragma once
// Built-ins that ask a declared object: inside(OBJ, P), min_extent(OBJ), max_extent(OBJ), as
// POV-Ray answers them for the shapes photon has (bounds are the object's box through its
// transform, as POV-Ray's bounding boxes; an infinite plane reaches POV-Ray's 1e10). trace()
// needs ray intersection at parse time, which photon's parser does not have: a clear error.

#include "parser_class.hpp"

namespace photon::dsl::detail {

struct Bounds {
    Vector3 lo{std::numeric_limits<double>::infinity()}, hi{-std::numeric_limits<double>::infinity()};
    void add(const Vector3& p) { lo = glm::min(lo, p), hi = glm::max(hi, p); }
    void add(const Bounds& b) { lo = glm::min(lo, b.lo), hi = glm::max(hi, b.hi); }
    [[nodiscard]] bool empty() const { return lo.x > hi.x; }
};

/// POV-Ray's BOUND_HUGE / 2: the extent it gives infinite objects.
inline constexpr double infinite_extent = 1e10;

/// The box of the 8 corners of `b` through `t` (POV-Ray's Recompute_BBox).
[[nodiscard]] inline Bounds transformed(const Bounds& b, const Transform& t) {
    if (b.empty()) return b;
    Bounds r;
    for (int i = 0; i < 8; ++i)
        r.add(t.point({i & 1 ? b.hi.x : b.lo.x, i & 2 ? b.hi.y : b.lo.y, i & 4 ? b.hi.z : b.lo.z}));
    // An infinite side stays infinite rather than becoming NaN through a rotation.
    for (int k = 0; k < 3; ++k) {
        if (b.lo[k] <= -infinite_extent || b.hi[k] >= infinite_extent || !std::isfinite(r.lo[k]) ||
            !std::isfinite(r.hi[k]))
            return Bounds{Vector3(-infinite_extent), Vector3(infinite_extent)};
    }
    return r;
}

[[nodiscard]] inline Bounds object_bounds(const Object& o) {
    Bounds b;
    bool placed = false;  // the shape's box is already in world space
    std::visit(
        [&](const auto& s) {
            using S = std::decay_t<decltype(s)>;
            if constexpr (std::is_same_v<S, SphereShape>) {
                // POV-Ray keeps a sphere a sphere under rotation, uniform scale and translation
                // (its box is then the moved centre +- the scaled radius), else an ellipsoid.
                const glm::dmat3 m = glm::transpose(o.transform.linear) * o.transform.linear;
                const double s2 = m[0][0];
                bool similar = s2 > 0;
                for (int i = 0; i < 3; ++i)
                    for (int j = 0; j < 3; ++j) similar = similar && std::abs(m[i][j] - (i == j ? s2 : 0.0)) <= 1e-12 * s2;
                if (similar) {
                    const Vector3 c = o.transform.point(s.center);
                    const double r = s.radius * std::sqrt(s2);
                    b.add(c - Vector3(r)), b.add(c + Vector3(r));
                    placed = true;
                    return;
                }
                b.add(s.center - Vector3(s.radius)), b.add(s.center + Vector3(s.radius));
            } else if constexpr (std::is_same_v<S, BoxShape>) {
                b.add(s.corner1), b.add(s.corner2);
            } else if constexpr (std::is_same_v<S, PlaneShape>) {
                b = Bounds{Vector3(-infinite_extent), Vector3(infinite_extent)};
            } else if constexpr (std::is_same_v<S, TriangleShape>) {
                for (const auto& v : s.vertices) b.add(v);
            } else if constexpr (std::is_same_v<S, MeshShape>) {
                if (s.triangles)
                    for (const auto& tri : *s.triangles)
                        for (const auto& v : tri) b.add(v);
            } else if constexpr (std::is_same_v<S, UnionShape>) {
                for (const auto& child : s.children) b.add(object_bounds(*child));
            } else {  // a light source: its position
                b.add(s.position);
            }
        },
        o.shape);
    return placed ? b : transformed(b, o.transform);
}

/// POV-Ray's Inside test: solids contain their inside (boundary included, within POV-Ray's
/// tolerance); triangles and meshes without inside_vector contain nothing.
[[nodiscard]] inline bool object_contains(const Object& o, const Vector3& world) {
    constexpr double tolerance = 1e-10;
    const Vector3 p = o.transform.inverse().point(world);
    return std::visit(
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
            } else if constexpr (std::is_same_v<S, UnionShape>) {
                for (const auto& child : s.children)
                    if (object_contains(*child, p)) return true;
                return false;
            } else {
                return false;
            }
        },
        o.shape);
}

inline const Object& Parser::parse_object_argument(const std::string& function) {
    const Token id = next();
    const std::string what = "a declared object as the first argument of `" + function + "`";
    if (id.kind != TokenKind::identifier) fail_expected(what, id);
    const Value* v = lookup(id.text);
    if (!v) fail(id.location, "undefined identifier `" + id.text + "` (" + what + ")");
    const auto* o = std::get_if<Object>(&v->data);
    if (!o)
        fail(id.location, "expected " + what + ", found `" + id.text + "` (" + type_name(v->data) + ", declared at " +
                              position_in(v->at, id.location) + ")");
    return *o;
}

// OBJECT_QUERY: inside ( OBJECT_IDENTIFIER , VECTOR ) | min_extent ( OBJECT_IDENTIFIER )
//             | max_extent ( OBJECT_IDENTIFIER ) | trace ( OBJECT_IDENTIFIER , VECTOR , VECTOR [, VECTOR_IDENTIFIER] )
inline Numeric Parser::parse_object_query(const Token& f) {
    const std::string& w = f.text;
    if (w == "trace")
        fail(f.location, "`trace` is not supported by photon's scene language (it needs ray intersection while "
                         "the scene is read)");
    expect_symbol("(", "after `" + w + "`");
    const bool saved = in_vector_;
    in_vector_ = false;
    const Object& o = parse_object_argument(w);
    Numeric r;
    if (w == "inside") {
        expect_symbol(",", "after the object of `inside`");
        const Vector3 p = parse_vector("a point as argument 2 of `inside`");
        r = Numeric::scalar(object_contains(o, p) ? 1.0 : 0.0);
    } else {
        const Bounds b = object_bounds(o);
        if (b.empty()) fail(f.location, "`" + w + "` of an empty object");
        r = Numeric::vector(w == "min_extent" ? b.lo : b.hi);
    }
    expect_symbol(")", "to close the arguments of `" + w + "`");
    in_vector_ = saved;
    return r;
}

}  // namespace photon::dsl::detail
