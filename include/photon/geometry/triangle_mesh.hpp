// SPDX-License-Identifier: MIT
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

#include "../memory/huge_page_allocator.hpp"
#include "bvh.hpp"
#include "triangle.hpp"

namespace photon {

/// Indexed triangle mesh with its own BVH, so that a mesh of a million triangles is one object
/// in the scene and costs O(log n) per ray. Normals follow the winding of each triangle.
template <Scalar S> class TriangleMesh {
public:
    using scalar_type = S;
    using Index = std::array<std::uint32_t, 3>;

    /// Throws std::invalid_argument on an index out of range or a non-finite vertex.
    TriangleMesh(std::vector<Vec3<S>> positions, std::vector<Index> triangles, BvhConfig config = {});

    [[nodiscard]] std::size_t triangle_count() const noexcept { return tris_.size(); }
    [[nodiscard]] std::span<const Vec3<S>> positions() const noexcept { return positions_; }
    [[nodiscard]] std::span<const Index> triangles() const noexcept { return indices_; }
    [[nodiscard]] const Bvh<S>& bvh() const noexcept { return bvh_; }
    [[nodiscard]] BBox<S> bounds() const noexcept { return bvh_.bounds(); }
    [[nodiscard]] std::size_t memory_bytes() const noexcept {
        return positions_.capacity() * sizeof(Vec3<S>) + indices_.capacity() * sizeof(Index) +
               tris_.capacity() * sizeof(LeafTriangle) + bvh_.memory_bytes();
    }

    /// Nearest hit with the watertight test: no ray passes between two triangles sharing an edge.
    [[nodiscard]] std::optional<Hit<S>> intersect(const Ray<S>& ray) const noexcept {
        const detail::WatertightRay<S> prepared(ray);
        Ray<S> r = ray;
        std::uint32_t hit_index = 0;
        const bool found = detail::with_shear_axis(prepared, [&](auto kz) {
            return bvh_.intersect(r, [&](std::uint32_t i, Ray<S>& current) {
                const LeafTriangle& tri = tris_[i];
                const auto t = detail::intersect_watertight<kz()>(prepared, current.t_max, tri.v[0], tri.v[1], tri.v[2]);
                if (!t) return false;
                current.t_max = *t;
                hit_index = i;
                return true;
            });
        });
        if (!found) return std::nullopt;
        const LeafTriangle& tri = tris_[hit_index];
        return Hit<S>{r.t_max, ray.at(r.t_max), detail::triangle_normal(tri.v[1] - tri.v[0], tri.v[2] - tri.v[0])};
    }

    [[nodiscard]] bool occluded(const Ray<S>& ray) const noexcept {
        const detail::WatertightRay<S> prepared(ray);
        return detail::with_shear_axis(prepared, [&](auto kz) {
            return bvh_.any_hit(ray, [&](std::uint32_t i, const Ray<S>& current) {
                const LeafTriangle& tri = tris_[i];
                return detail::intersect_watertight<kz()>(prepared, current.t_max, tri.v[0], tri.v[1], tri.v[2])
                    .has_value();
            });
        });
    }

private:
    /// Vertices copied in BVH leaf order, so a leaf's triangles are contiguous in memory.
    struct LeafTriangle {
        std::array<Vec3<S>, 3> v;
    };

    std::vector<Vec3<S>> positions_;
    std::vector<Index> indices_;
    std::vector<LeafTriangle, HugePageAllocator<LeafTriangle>> tris_;
    Bvh<S> bvh_;
};

template <Scalar S>
TriangleMesh<S>::TriangleMesh(std::vector<Vec3<S>> positions, std::vector<Index> triangles, BvhConfig config)
    : positions_(std::move(positions)), indices_(std::move(triangles)) {
    for (const Vec3<S>& p : positions_)
        if (!is_finite(p)) throw std::invalid_argument("mesh: vertex positions must be finite");
    std::vector<BBox<S>> boxes;
    std::vector<Vec3<S>> centers;
    boxes.reserve(indices_.size());
    centers.reserve(indices_.size());
    for (std::size_t t = 0; t < indices_.size(); ++t) {
        const Index& idx = indices_[t];
        for (std::uint32_t v : idx)
            if (v >= positions_.size())
                throw std::invalid_argument("mesh: triangle " + std::to_string(t) + " refers to vertex " +
                                            std::to_string(v) + " of " + std::to_string(positions_.size()));
        BBox<S> b = BBox<S>::of_point(positions_[idx[0]]);
        b.extend(positions_[idx[1]]).extend(positions_[idx[2]]);
        boxes.push_back(b);
        centers.push_back(b.center());
    }
    bvh_ = Bvh<S>(boxes, centers, config);
    tris_.reserve(indices_.size());
    for (std::uint32_t id : bvh_.primitive_indices()) {
        const Index& idx = indices_[id];
        const Vec3<S>& v0 = positions_[idx[0]];
        // A triangle without a normal (collinear or coincident vertices, or an area that
        // underflows) collapses to one point: its edge functions are then exactly 0 and it is
        // never hit. Its own vertices would not do, as rounding can make the determinant
        // non-zero for exactly collinear vertices, and the hit would carry a NaN normal.
        if (detail::triangle_normal(positions_[idx[1]] - v0, positions_[idx[2]] - v0) == Vec3<S>(S(0)))
            tris_.push_back({{v0, v0, v0}});
        else
            tris_.push_back({{v0, positions_[idx[1]], positions_[idx[2]]}});
    }
}

}  // namespace photon
