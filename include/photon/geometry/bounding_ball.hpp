// SPDX-License-Identifier: MIT
#pragma once
// A ball that holds a shape: what caustic photons are aimed at. The box's circumscribed ball is
// always one, but for a sphere it has sqrt(3) times the radius and three times the solid angle,
// so two thirds of the photons aimed at a sphere that way missed it. The library's round shapes
// give their own, tighter ball; anything else (a user's primitive too) falls back to the box's.

#include <algorithm>
#include <cmath>
#include <limits>
#include <type_traits>

#include "../math/symmetric_eigen.hpp"
#include "bbox.hpp"
#include "cone.hpp"
#include "cylinder.hpp"
#include "disc.hpp"
#include "sphere.hpp"
#include "transformed.hpp"

namespace photon {

template <Scalar S> struct Ball {
    Vec3<S> center{S(0)};
    S radius = S(0);
};

/// The ball around a finite box's corners; radius infinity for an infinite or empty box.
template <Scalar S> [[nodiscard]] Ball<S> ball_around(const BBox<S>& box) noexcept {
    if (!box.is_finite()) return {Vec3<S>(S(0)), std::numeric_limits<S>::infinity()};
    return {box.center(), S(0.5) * glm::length(box.extent())};
}

template <Primitive Shape> [[nodiscard]] Ball<scalar_of<Shape>> bounding_ball(const Shape& shape);

namespace detail {
/// The largest factor by which `linear` stretches a vector: the square root of the largest
/// eigenvalue of its Gram matrix (a transformed ball's radius grows by at most this).
template <Scalar S> [[nodiscard]] S largest_stretch(const glm::mat<3, 3, S>& linear) noexcept {
    const glm::dmat3 m(linear);
    const SymmetricEigen3 e = symmetric_eigen(glm::transpose(m) * m);
    return S(std::sqrt(std::max({e.values.x, e.values.y, e.values.z, 0.0})));
}
}  // namespace detail

/// A ball holding `shape`: exact for a sphere, a cylinder, a cone and a disc, mapped for a
/// transformed one (whichever is smaller of the mapped ball and the box's ball), the box's ball
/// otherwise. Radius infinity for an unbounded shape.
template <Primitive Shape> [[nodiscard]] Ball<scalar_of<Shape>> bounding_ball(const Shape& shape) {
    using S = scalar_of<Shape>;
    const Ball<S> boxed = ball_around(shape.bounds());
    Ball<S> own = boxed;
    if constexpr (std::is_same_v<Shape, Sphere<S>>) own = {shape.center(), shape.radius()};
    else if constexpr (std::is_same_v<Shape, Cylinder<S>> || std::is_same_v<Shape, TruncatedCone<S>>) {
        S r;
        if constexpr (std::is_same_v<Shape, Cylinder<S>>) r = shape.radius();
        else r = std::max(shape.base_radius(), shape.cap_radius());
        own = {(shape.base() + shape.cap()) * S(0.5), std::sqrt(squared(shape.length() * S(0.5)) + r * r)};
    } else if constexpr (std::is_same_v<Shape, Disc<S>>) own = {shape.center(), shape.radius()};
    else if constexpr (requires { shape.shape(); shape.to_world(); }) {
        const Ball<S> inner = bounding_ball(shape.shape());
        if (std::isfinite(inner.radius))
            own = {shape.to_world().point(inner.center), inner.radius * detail::largest_stretch(shape.to_world().linear)};
    }
    return own.radius < boxed.radius ? own : boxed;
}

}  // namespace photon
