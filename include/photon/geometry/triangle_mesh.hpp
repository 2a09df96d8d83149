// SPDX-License-Identifier: MIT
#pragma once

#include <algorithm>
#include <array>
#include <bit>
#include <cstdint>
#include <optional>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

#include "../memory/huge_page_allocator.hpp"
#include "../parallel/parallel_for.hpp"
#include "bvh.hpp"
#include "triangle.hpp"
#include "triangle4.hpp"

namespace photon {

/// Indexed triangle mesh with its own BVH, so that a mesh of a million triangles is one object
/// in the scene and costs O(log n) per ray. Normals follow the winding of each triangle. A leaf's
/// triangles are stored four to a block and tested four at once (detail::Triangle4).
template <Scalar S> class TriangleMesh {
public:
    using scalar_type = S;
    using Index = std::array<std::uint32_t, 3>;

    /// Throws std::invalid_argument on an index out of range or a non-finite vertex.
    TriangleMesh(std::vector<Vec3<S>> positions, std::vector<Index> triangles, BvhConfig config = {});

    [[nodiscard]] std::size_t triangle_count() const noexcept { return indices_.size(); }
    [[nodiscard]] std::span<const Vec3<S>> positions() const noexcept { return positions_; }
    [[nodiscard]] std::span<const Index> triangles() const noexcept { return indices_; }
    [[nodiscard]] const Bvh<S>& bvh() const noexcept { return bvh_; }
    [[nodiscard]] BBox<S> bounds() const noexcept { return bvh_.bounds(); }
    [[nodiscard]] std::size_t memory_bytes() const noexcept {
        return positions_.capacity() * sizeof(Vec3<S>) + indices_.capacity() * sizeof(Index) +
               blocks_.capacity() * sizeof(detail::Triangle4<S>) + bvh_.memory_bytes();
    }

    /// Nearest hit with the watertight test: no ray passes between two triangles sharing an edge.
    [[nodiscard]] std::optional<Hit<S>> intersect(const Ray<S>& ray) const noexcept {
        const detail::WatertightRay<S> prepared(ray);
        Ray<S> r = ray;
        std::uint32_t hit_block = 0;
        int hit_lane = 0;
        const bool found = detail::with_shear_axis(prepared, [&](auto kz) {
            return bvh_.intersect_leaves(r, [&](std::uint32_t first, std::uint32_t count, Ray<S>& current) {
                bool any = false;
                for (std::uint32_t b = first / 4; count > 0; ++b) {
                    const unsigned n = std::min(count, 4u);
                    count -= n;
                    std::array<S, 4> t;
                    unsigned mask = detail::intersect_watertight4<kz()>(prepared, current.t_max, blocks_[b], n, t);
                    // The nearest lane; among equal distances the first, as one-by-one tests would pick.
                    for (; mask != 0; mask &= mask - 1) {
                        const int lane = std::countr_zero(mask);
                        if (!(t[lane] < current.t_max)) continue;
                        current.t_max = t[lane];
                        hit_block = b, hit_lane = lane, any = true;
                    }
                }
                return any;
            });
        });
        if (!found) return std::nullopt;
        const detail::Triangle4<S>& tri = blocks_[hit_block];
        const Vec3<S> v0 = tri.vertex(hit_lane, 0);
        return Hit<S>{r.t_max, ray.at(r.t_max),
                      detail::triangle_normal(tri.vertex(hit_lane, 1) - v0, tri.vertex(hit_lane, 2) - v0)};
    }

    [[nodiscard]] bool occluded(const Ray<S>& ray) const noexcept {
        const detail::WatertightRay<S> prepared(ray);
        return detail::with_shear_axis(prepared, [&](auto kz) {
            return bvh_.any_hit_leaves(ray, [&](std::uint32_t first, std::uint32_t count, const Ray<S>& current) {
                for (std::uint32_t b = first / 4; count > 0; ++b) {
                    const unsigned n = std::min(count, 4u);
                    count -= n;
                    std::array<S, 4> t;
                    if (detail::intersect_watertight4<kz()>(prepared, current.t_max, blocks_[b], n, t) != 0) return true;
                }
                return false;
            });
        });
    }

private:
    std::vector<Vec3<S>> positions_;
    std::vector<Index> indices_;
    /// Vertices copied in BVH leaf order, four triangles to a block: blocks_[first / 4] onwards
    /// holds the leaf (first, count) of the BVH (built with leaf_block = 4).
    std::vector<detail::Triangle4<S>, HugePageAllocator<detail::Triangle4<S>>> blocks_;
    Bvh<S> bvh_;
};

template <Scalar S>
TriangleMesh<S>::TriangleMesh(std::vector<Vec3<S>> positions, std::vector<Index> triangles, BvhConfig config)
    : positions_(std::move(positions)), indices_(std::move(triangles)) {
    for (const Vec3<S>& p : positions_)
        if (!is_finite(p)) throw std::invalid_argument("mesh: vertex positions must be finite");
    for (std::size_t t = 0; t < indices_.size(); ++t)
        for (std::uint32_t v : indices_[t])
            if (v >= positions_.size())
                throw std::invalid_argument("mesh: triangle " + std::to_string(t) + " refers to vertex " +
                                            std::to_string(v) + " of " + std::to_string(positions_.size()));
    // The loops below write by index, on the BVH build's threads. The boxes: 24 bytes a triangle,
    // fresh pages at every build (glibc maps arrays this large anew), so huge pages spare most of
    // the page faults.
    constexpr std::size_t grain = 1 << 14;
    std::vector<BBox<S>, HugePageAllocator<BBox<S>>> boxes(indices_.size());
    parallel_for(indices_.size(), grain, config.threads, [&](std::size_t first, std::size_t last) {
        for (std::size_t t = first; t < last; ++t) {
            const Index& idx = indices_[t];
            boxes[t] = BBox<S>::of_point(positions_[idx[0]]);
            boxes[t].extend(positions_[idx[1]]).extend(positions_[idx[2]]);
        }
    });
    config.leaf_block = 4;
    bvh_ = Bvh<S>(boxes, config);
    const auto ids = bvh_.primitive_indices();
    blocks_.resize(ids.size() / 4);
    parallel_for(blocks_.size(), grain / 4, config.threads, [&](std::size_t first, std::size_t last) {
        for (std::size_t i = 4 * first; i < 4 * last; ++i) {
            if (ids[i] == Bvh<S>::padding) continue;  // stays NaN
            const Index& idx = indices_[ids[i]];
            const Vec3<S>& v0 = positions_[idx[0]];
            // A triangle without a normal (collinear or coincident vertices, or an area that
            // underflows) stays NaN and is never hit. Its own vertices would not do, as rounding
            // can make the determinant non-zero for exactly collinear vertices, and the hit would
            // carry a NaN normal.
            if (detail::triangle_normal(positions_[idx[1]] - v0, positions_[idx[2]] - v0) != Vec3<S>(S(0)))
                blocks_[i / 4].set(int(i % 4), v0, positions_[idx[1]], positions_[idx[2]]);
        }
    });
}

}  // namespace photon
