// SPDX-License-Identifier: MIT
#pragma once
// What the light-path plan (effects_plan.hpp) may assume about a shape: whether it is flat (it
// cannot light itself), a closed convex solid (lit from outside, it cannot light itself; a light
// inside it lights only its inside), and whether a ball lies inside it. Only the library's own
// shapes answer; a user's own primitive is "unknown", about which the plan assumes nothing, so
// every answer errs on the side of keeping work.

#include <array>
#include <cmath>
#include <string>
#include <type_traits>

#include "../geometry/bbox.hpp"
#include "../geometry/box.hpp"
#include "../geometry/cone.hpp"
#include "../geometry/csg.hpp"
#include "../geometry/cylinder.hpp"
#include "../geometry/disc.hpp"
#include "../geometry/blob.hpp"
#include "../geometry/lathe.hpp"
#include "../geometry/height_field.hpp"
#include "../geometry/plane.hpp"
#include "../geometry/polygon.hpp"
#include "../geometry/polynomial_surface.hpp"
#include "../geometry/prism.hpp"
#include "../geometry/quadric.hpp"
#include "../geometry/sor.hpp"
#include "../geometry/sphere.hpp"
#include "../geometry/superellipsoid.hpp"
#include "../geometry/torus.hpp"
#include "../geometry/transformed.hpp"
#include "../geometry/triangle.hpp"
#include "../geometry/triangle_mesh.hpp"

namespace photon::plan {

template <class T> struct is_transformed : std::false_type {};
template <class P> struct is_transformed<Transformed<P>> : std::true_type {};
template <class T> struct is_csg : std::false_type {};
template <Scalar S, class... L> struct is_csg<Csg<S, L...>> : std::true_type {};

/// POV-Ray's name of a CSG operation.
[[nodiscard]] inline const char* csg_op_name(CsgOp op) {
    switch (op) {
    case CsgOp::leaf: return "csg";
    case CsgOp::merge: return "merge";
    case CsgOp::intersection: return "intersection";
    case CsgOp::difference: return "difference";
    case CsgOp::clip: return "clipped object";
    }
    return "csg";
}

/// What the shape is called in the plan's reasons ("sphere", "transformed box"; "object" for a
/// user's own primitive).
template <class Shape> [[nodiscard]] std::string shape_name(const Shape& shape) {
    using S = scalar_of<Shape>;
    if constexpr (is_transformed<Shape>::value) return "transformed " + shape_name(shape.shape());
    else if constexpr (is_csg<Shape>::value) {
        const std::string op = shape.op() == CsgOp::leaf
                                   ? std::visit([](const auto& leaf) { return shape_name(leaf); }, shape.leaves()[0])
                                   : csg_op_name(shape.op());
        return shape.inverted() ? "inverse " + op : op;
    } else if constexpr (std::is_same_v<Shape, Sphere<S>>) return "sphere";
    else if constexpr (std::is_same_v<Shape, Plane<S>>) return "plane";
    else if constexpr (std::is_same_v<Shape, Box<S>>) return "box";
    else if constexpr (std::is_same_v<Shape, Triangle<S>>) return "triangle";
    else if constexpr (std::is_same_v<Shape, TriangleMesh<S>>) return "mesh";
    else if constexpr (std::is_same_v<Shape, Cylinder<S>>) return shape.open() ? "open cylinder" : "cylinder";
    else if constexpr (std::is_same_v<Shape, TruncatedCone<S>>) {
        // The scene language places a cylinder under a shear or non-uniform scale as a cone with equal radii.
        const char* name = shape.base_radius() == shape.cap_radius() ? "cylinder" : "cone";
        return shape.open() ? std::string("open ") + name : std::string(name);
    }
    else if constexpr (std::is_same_v<Shape, Disc<S>>) return "disc";
    else if constexpr (std::is_same_v<Shape, Torus<S>>) return "torus";
    else if constexpr (std::is_same_v<Shape, Quadric<S>>) return shape.bounds().is_finite() ? "ellipsoid quadric" : "quadric";
    else if constexpr (std::is_same_v<Shape, Polygon<S>>) return "polygon";
    else if constexpr (std::is_same_v<Shape, Prism<S>>) return "prism";
    else if constexpr (std::is_same_v<Shape, PolynomialSurface<S>>) return "poly";
    else if constexpr (std::is_same_v<Shape, Superellipsoid<S>>) return "superellipsoid";
    else if constexpr (std::is_same_v<Shape, Lathe<S>>) return "lathe";
    else if constexpr (std::is_same_v<Shape, Sor<S>>) return shape.open() ? "open sor" : "sor";
    else if constexpr (std::is_same_v<Shape, HeightField<S>>) return "height field";
    else if constexpr (std::is_same_v<Shape, Blob<S>>) return "blob";
    else return "object";
}

/// A plane, a triangle, a disc or a polygon (also transformed: an affine map keeps it flat): no point of it sees
/// another, so light it reflects never lands on it again.
template <class Shape> [[nodiscard]] constexpr bool is_flat(const Shape& shape) {
    using S = scalar_of<Shape>;
    if constexpr (is_transformed<Shape>::value) return is_flat(shape.shape());
    else
        return std::is_same_v<Shape, Plane<S>> || std::is_same_v<Shape, Triangle<S>> || std::is_same_v<Shape, Disc<S>> ||
               std::is_same_v<Shape, Polygon<S>>;
}

/// A sphere, a box, a closed cylinder or a closed cone (also transformed: an affine map keeps it
/// convex and closed), or a quadric whose solid is bounded (then an ellipsoid). A torus is neither convex nor flat; an open cylinder or cone is not closed.
/// A CSG intersection of convex solids and half-spaces (planes) is one when it is bounded; any
/// other CSG (a merge, a difference, an inverse) is not known to be.
template <class Shape> [[nodiscard]] bool is_convex_solid(const Shape& shape) {
    using S = scalar_of<Shape>;
    if constexpr (is_transformed<Shape>::value) return is_convex_solid(shape.shape());
    else if constexpr (is_csg<Shape>::value) {
        if (shape.inverted()) return false;
        if (shape.op() == CsgOp::leaf)
            return std::visit([](const auto& leaf) { return is_convex_solid(leaf); }, shape.leaves()[0]);
        if (shape.op() != CsgOp::intersection || !shape.bounds().is_finite()) return false;
        for (const Shape& child : shape.children()) {
            const bool half_space = child.op() == CsgOp::leaf && !child.inverted() &&
                                    std::holds_alternative<Plane<S>>(child.leaves()[0]);
            if (!half_space && !is_convex_solid(child)) return false;
        }
        return true;
    }
    else if constexpr (std::is_same_v<Shape, Cylinder<S>> || std::is_same_v<Shape, TruncatedCone<S>>) return !shape.open();
    else if constexpr (std::is_same_v<Shape, Quadric<S>>) return shape.bounds().is_finite();
    else return std::is_same_v<Shape, Sphere<S>> || std::is_same_v<Shape, Box<S>>;
}

namespace detail {
/// Whether `p` is inside a sphere or a box by more than `margin`.
template <class Shape, Scalar S> [[nodiscard]] bool inside_by(const Shape& shape, const Vec3<S>& p, S margin) {
    if constexpr (std::is_same_v<Shape, Sphere<S>>) {
        return glm::length(p - shape.center()) < shape.radius() - margin;
    } else if constexpr (std::is_same_v<Shape, Box<S>>) {
        const BBox<S> b = shape.bounds();
        for (int a = 0; a < 3; ++a)
            if (!(p[a] > b.min[a] + margin && p[a] < b.max[a] - margin)) return false;
        return true;
    } else {
        return false;
    }
}
}  // namespace detail

/// Whether the ball (centre, radius) lies inside the closed convex solid `shape`, with a margin
/// of 1e-4 of the shape's largest coordinate (the scale rounding errors follow). A transformed
/// solid holds the ball if it holds the eight corners of the ball's bounding cube (it is convex),
/// tested in its own space.
template <class Shape, Scalar S>
[[nodiscard]] bool contains_ball(const Shape& shape, const Vec3<S>& center, S radius) {
    if constexpr (is_csg<Shape>::value) {  // a leaf's answer; an intersection's if every child holds it
        if (shape.inverted()) return false;
        if (shape.op() == CsgOp::leaf)
            return std::visit([&](const auto& leaf) { return contains_ball(leaf, center, radius); }, shape.leaves()[0]);
        if (shape.op() != CsgOp::intersection) return false;
        for (const Shape& child : shape.children())
            if (!contains_ball(child, center, radius)) return false;
        return true;
    } else if constexpr (is_transformed<Shape>::value) {
        using Inner = std::remove_cvref_t<decltype(shape.shape())>;
        if constexpr (!std::is_same_v<Inner, Sphere<S>> && !std::is_same_v<Inner, Box<S>>) {
            return false;
        } else {
            const Affine<S> to_local = shape.to_world().inverse();
            const S margin = S(1e-4) * shape.shape().bounds().magnitude();
            for (int corner = 0; corner < 8; ++corner) {
                const Vec3<S> p = center + radius * Vec3<S>((corner & 1) ? 1 : -1, (corner & 2) ? 1 : -1, (corner & 4) ? 1 : -1);
                if (!detail::inside_by(shape.shape(), to_local.point(p), margin)) return false;
            }
            return true;
        }
    } else if constexpr (std::is_same_v<Shape, Sphere<S>>) {
        return detail::inside_by(shape, center, radius + S(1e-4) * shape.bounds().magnitude());
    } else if constexpr (std::is_same_v<Shape, Box<S>>) {
        return detail::inside_by(shape, center, radius + S(1e-4) * shape.bounds().magnitude());
    } else {
        return false;
    }
}

}  // namespace photon::plan
