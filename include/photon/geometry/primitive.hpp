// SPDX-License-Identifier: MIT
#pragma once
// The Primitive concept: what any shape must offer to be placed in a Scene. A user's own shape
// becomes first-class by satisfying it and being listed in the Scene's shape types.

#include <concepts>
#include <optional>

#include "bbox.hpp"
#include "hit.hpp"
#include "ray.hpp"

namespace photon {

template <class T> using scalar_of = typename T::scalar_type;

/// A shape that bounds itself and reports the nearest hit with t in (0, ray.t_max).
/// `bounds()` may be infinite (an unbounded plane); such shapes are tested outside the BVH.
template <class T>
concept Primitive = Scalar<typename T::scalar_type> &&
    requires(const T& shape, const Ray<typename T::scalar_type>& ray) {
        { shape.bounds() } -> std::same_as<BBox<typename T::scalar_type>>;
        { shape.intersect(ray) } -> std::same_as<std::optional<Hit<typename T::scalar_type>>>;
    };

/// Optional capability: a cheaper any-hit test for shadow rays. Shapes without it fall back to
/// `intersect(ray).has_value()`.
template <class T>
concept HasOcclusionTest = requires(const T& shape, const Ray<typename T::scalar_type>& ray) {
    { shape.occluded(ray) } -> std::same_as<bool>;
};

template <Primitive P> [[nodiscard]] bool occluded(const P& shape, const Ray<scalar_of<P>>& ray) {
    if constexpr (HasOcclusionTest<P>) {
        return shape.occluded(ray);
    } else {
        return shape.intersect(ray).has_value();
    }
}

}  // namespace photon
