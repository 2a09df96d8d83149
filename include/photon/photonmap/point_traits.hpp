// SPDX-License-Identifier: MIT
#pragma once
// How the kd-tree reads a user's point type: a traits class, specialised for layouts it cannot
// guess (nanoflann's dataset adaptor, as a C++20 concept).

#include <concepts>
#include <type_traits>

#include "../math/vec.hpp"

namespace photon {

/// Default traits: `P` has a public member `position` (a glm 3-vector of float or double), and
/// the tree keeps the whole record beside its own copy of the positions. Specialise for other
/// layouts, or to keep only part of the record (`payload`) when memory matters; photon::Photon
/// does so and keeps 8 bytes beside the position.
template <class P> struct point_traits {
    using payload_type = P;
    [[nodiscard]] static auto position(const P& p) noexcept { return p.position; }
    [[nodiscard]] static const P& payload(const P& p) noexcept { return p; }
};

/// Anything the kd-tree can index: a position in 3D and a trivially copyable payload.
template <class P>
concept SpatialPoint = requires(const P& p) {
    typename point_traits<P>::payload_type;
    { point_traits<P>::position(p).x } -> std::convertible_to<double>;
    { point_traits<P>::payload(p) } -> std::convertible_to<typename point_traits<P>::payload_type>;
} && std::is_trivially_copyable_v<typename point_traits<P>::payload_type> &&
    Scalar<typename std::remove_cvref_t<decltype(point_traits<P>::position(std::declval<const P&>()))>::value_type>;

/// The scalar type of a point's coordinates (float or double).
template <SpatialPoint P>
using position_scalar_t =
    typename std::remove_cvref_t<decltype(point_traits<P>::position(std::declval<const P&>()))>::value_type;

template <SpatialPoint P> using payload_t = typename point_traits<P>::payload_type;

}  // namespace photon
