// SPDX-License-Identifier: MIT
#pragma once
// The Solid concept: a Primitive that also encloses a volume and can say whether a point is in
// it. CSG (csg.hpp) combines solids; its crossings are those of the surfaces, its inside is the
// children's, so a solid's outward normal must point out of the volume contains() describes.
//
// The library's solids: Sphere, Box, Plane (the half-space below it, as POV-Ray's plane),
// Cylinder and TruncatedCone (the closed solid, also when `open`: POV-Ray's inside test ignores
// `open`, so an open one in CSG shows no end caps where they would bound the result), Torus,
// Quadric, Prism, PolynomialSurface, Superellipsoid, Lathe, Sor, HeightField, Blob, Csg itself, and
// Transformed<P> of a solid. Not solids: Triangle and Disc (no inside) and TriangleMesh (its
// winding need not be closed or consistent; POV-Ray needs an `inside_vector` to decide).

#include <concepts>

#include "primitive.hpp"

namespace photon {

/// A Primitive with an inside: `contains(p)` is true for points in the volume (points on the
/// surface may answer either way), and the normals of its hits point out of that volume.
template <class T>
concept Solid = Primitive<T> && requires(const T& shape, const Vec3<typename T::scalar_type>& p) {
    { shape.contains(p) } -> std::same_as<bool>;
};

}  // namespace photon
