// SPDX-License-Identifier: MIT
#pragma once

#include <cmath>
#include <optional>
#include <stdexcept>

#include "../math/transform.hpp"
#include "primitive.hpp"
#include "solid.hpp"

namespace photon {

/// Any primitive under an affine transform (translate, rotate, scale, also non-uniform): rays
/// are taken into the shape's local space, normals back by the inverse transpose.
template <Primitive P> class Transformed {
public:
    using scalar_type = scalar_of<P>;
    using S = scalar_type;

    /// Throws std::invalid_argument if `to_world` is singular or not finite.
    Transformed(P shape, const Affine<S>& to_world) : shape_(std::move(shape)), to_world_(to_world) {
        const S det = to_world.determinant();
        if (!(std::abs(det) > S(0)) || !std::isfinite(det) || !is_finite(to_world.translation))
            throw std::invalid_argument("transform: matrix must be invertible and finite");
        to_local_ = to_world.inverse();
    }

    [[nodiscard]] const P& shape() const noexcept { return shape_; }
    [[nodiscard]] const Affine<S>& to_world() const noexcept { return to_world_; }

    [[nodiscard]] BBox<S> bounds() const noexcept {
        const BBox<S> local = shape_.bounds();
        if (!local.is_finite()) return BBox<S>::infinite();
        BBox<S> world;
        for (int corner = 0; corner < 8; ++corner) {
            const Vec3<S> p{(corner & 1) ? local.max.x : local.min.x, (corner & 2) ? local.max.y : local.min.y,
                            (corner & 4) ? local.max.z : local.min.z};
            world.extend(to_world_.point(p));
        }
        return world;
    }

    /// Solid when the shape is: the point taken into the shape's space.
    [[nodiscard]] bool contains(const Vec3<S>& p) const noexcept
        requires Solid<P>
    {
        return shape_.contains(to_local_.point(p));
    }

    [[nodiscard]] std::optional<Hit<S>> intersect(const Ray<S>& ray) const noexcept {
        const Ray<S> local{to_local_.point(ray.origin), to_local_.vector(ray.direction), ray.t_max};
        auto hit = shape_.intersect(local);
        if (!hit) return std::nullopt;
        hit->point = ray.at(hit->t);  // same t: the direction was transformed with the point
        hit->normal = glm::normalize(to_local_.normal_from_inverse(hit->normal));
        return hit;
    }

    [[nodiscard]] bool occluded(const Ray<S>& ray) const noexcept {
        const Ray<S> local{to_local_.point(ray.origin), to_local_.vector(ray.direction), ray.t_max};
        return photon::occluded(shape_, local);
    }

private:
    P shape_;
    Affine<S> to_world_, to_local_;
};

}  // namespace photon
