// SPDX-License-Identifier: MIT
#pragma once
// A proof that no shadow ray from a point to a light can arrive, cheaper than the rays: an opaque
// wall lies across every segment from the point to the light's ball. In a building of rooms (the
// plan's hundred-lamps scene: 100 lamps, 4 in the camera's room) the shadow rays to the lamps in
// the other rooms were most of the render's time, each one blocked by a wall. A wall here is an
// opaque infinite plane with the point and the ball strictly on opposite sides, or an opaque
// axis-aligned box with the point and the ball on opposite sides of it along one axis, where
// every segment between them crosses that axis's span inside the box's extent along the other
// two (box_between), so it passes through the box. Opaque: casting shadows and transmitting nothing.

#include <cstdint>
#include <span>
#include <type_traits>
#include <variant>

#include "../geometry/box.hpp"
#include "../geometry/plane.hpp"
#include "../material/material.hpp"

namespace photon {

namespace detail {
/// Whether every segment from `p` to the ball (c, r) passes through the axis-aligned box: p and
/// the ball lie on opposite sides of it along one axis, and where any such segment crosses the
/// box's span along that axis, it is inside the box's extent along the other two. The segment
/// from p to q is at p + t (q - p); it is within the span for t in [t0, t1], and the bounds on
/// t0 and t1 over the ball's q, with the ball's extent along the other axes, bound the segment's
/// coordinates there (each is linear in t, so its extremes are at the ends).
template <Scalar S> [[nodiscard]] bool box_between(const Box<S>& box, const Vec3<S>& p, const Vec3<S>& c, S r) noexcept {
    const Vec3<S>& lo = box.min();
    const Vec3<S>& hi = box.max();
    const S margin = S(1e-5) * (max_component(glm::abs(lo)) + max_component(glm::abs(hi)) + max_component(glm::abs(p)) +
                                max_component(glm::abs(c)) + r);
    for (int axis = 0; axis < 3; ++axis) {
        // Along `axis`: p before the box and the ball after it (or the other way round).
        S t_min, t_max;
        if (p[axis] < lo[axis] - margin && c[axis] - r > hi[axis] + margin) {
            t_min = (lo[axis] - p[axis]) / (c[axis] + r - p[axis]);
            t_max = (hi[axis] - p[axis]) / (c[axis] - r - p[axis]);
        } else if (p[axis] > hi[axis] + margin && c[axis] + r < lo[axis] - margin) {
            t_min = (p[axis] - hi[axis]) / (p[axis] - (c[axis] - r));
            t_max = (p[axis] - lo[axis]) / (p[axis] - (c[axis] + r));
        } else {
            continue;
        }
        bool inside = true;
        for (int b : {(axis + 1) % 3, (axis + 2) % 3}) {
            const S low = c[b] - r - p[b], high = c[b] + r - p[b];  // q_b - p_b ranges over [low, high]
            const S least = p[b] + std::min(t_min * low, t_max * low);
            const S most = p[b] + std::max(t_min * high, t_max * high);
            inside = inside && least > lo[b] + margin && most < hi[b] - margin;
        }
        if (inside) return true;
    }
    return false;
}

template <Scalar S> [[nodiscard]] bool plane_between(const Plane<S>& plane, const Vec3<S>& p, const Vec3<S>& c, S r) noexcept {
    const S sp = glm::dot(plane.normal(), p) - plane.offset();
    const S sc = glm::dot(plane.normal(), c) - plane.offset();
    const S margin = S(1e-5) * (std::abs(plane.offset()) + max_component(glm::abs(p)) + max_component(glm::abs(c)) + r);
    return (sp > margin && sc < -r - margin) || (sp < -margin && sc > r + margin);
}
}  // namespace detail

/// Whether one of the objects `ids` (shadow casters, as Scene::occluders_in lists them) is an
/// opaque wall across every segment from `p` to the ball (`center`, `radius`).
template <class SceneT>
[[nodiscard]] bool wall_between(const SceneT& scene, std::span<const std::uint32_t> ids,
                                const Vec3<typename SceneT::scalar_type>& p,
                                const Vec3<typename SceneT::scalar_type>& center, typename SceneT::scalar_type radius) {
    using S = typename SceneT::scalar_type;
    const auto objects = scene.objects();
    for (std::uint32_t id : ids) {
        const bool across = std::visit(
            [&](const auto& shape) {
                using Shape = std::decay_t<decltype(shape)>;
                if constexpr (std::is_same_v<Shape, Box<S>>) return detail::box_between(shape, p, center, radius);
                else if constexpr (std::is_same_v<Shape, Plane<S>>) return detail::plane_between(shape, p, center, radius);
                else return false;
            },
            objects[id].shape);
        if (across && objects[id].options.casts_shadow && !scene.any_material_of(id, is_transmissive_material)) return true;
    }
    return false;
}

}  // namespace photon
