// SPDX-License-Identifier: MIT
#pragma once
// Bounding volume hierarchy over anything with a bounding box. The BVH never sees primitives: it
// is built from spans of boxes and centres, and traversal calls back into the caller for each
// primitive in a reached leaf (the design of madmann91/bvh).

#include <algorithm>
#include <array>
#include <cstdint>
#include <limits>
#include <numeric>
#include <span>
#include <vector>

#include "../config.hpp"
#include "bbox.hpp"
#include "ray.hpp"

namespace photon {

/// Build options. Costs are in units of one node visit.
struct BvhConfig {
    unsigned max_leaf_size = 8;    ///< never more primitives per leaf than this, except identical centres
    unsigned bins = 16;            ///< SAH bins per axis
    float intersection_cost = 1.0f;  ///< cost of one primitive test relative to a node visit
};

/// Binary BVH, binned SAH build (Wald 2007, "On fast Construction of SAH-based Bounding Volume
/// Hierarchies"), ordered stack traversal with the robust slab test of Ize (2013).
template <Scalar S> class Bvh {
public:
    struct Node {
        BBox<S> bounds;
        std::uint32_t first = 0;  ///< leaf: first index into primitive_indices(); inner: left child
        std::uint32_t count = 0;  ///< primitives in a leaf; 0 marks an inner node (right = first + 1)
        [[nodiscard]] bool is_leaf() const noexcept { return count != 0; }
    };

    Bvh() = default;
    /// Builds over `boxes[i]` with representative points `centers[i]` (usually box centres).
    Bvh(std::span<const BBox<S>> boxes, std::span<const Vec3<S>> centers, BvhConfig config = {});

    [[nodiscard]] bool empty() const noexcept { return nodes_.empty(); }
    [[nodiscard]] std::span<const Node> nodes() const noexcept { return nodes_; }
    /// Primitive ids in leaf order: leaf nodes refer to ranges of this array.
    [[nodiscard]] std::span<const std::uint32_t> primitive_indices() const noexcept { return prim_ids_; }
    [[nodiscard]] BBox<S> bounds() const noexcept { return nodes_.empty() ? BBox<S>{} : nodes_[0].bounds; }
    [[nodiscard]] std::size_t depth() const noexcept { return depth_; }
    [[nodiscard]] std::size_t memory_bytes() const noexcept {
        return nodes_.capacity() * sizeof(Node) + prim_ids_.capacity() * sizeof(std::uint32_t);
    }

    /// Closest-hit traversal. For every primitive in a reached leaf calls `test(leaf_position,
    /// ray)`, where `leaf_position` indexes primitive_indices(); the callback shortens ray.t_max
    /// when it finds a closer hit and returns whether it did.
    template <class TestFn> bool intersect(Ray<S>& ray, TestFn&& test) const;
    /// Any-hit traversal: stops at the first primitive for which `test` returns true.
    template <class TestFn> bool any_hit(const Ray<S>& ray, TestFn&& test) const;

private:
    struct Bin {
        BBox<S> bounds;
        std::uint32_t count = 0;
    };
    void build(std::span<const BBox<S>> boxes, std::span<const Vec3<S>> centers, BvhConfig config);

    static constexpr std::uint32_t forced_median_depth = 64;
    static constexpr std::size_t stack_size = 128;  // > forced_median_depth + log2(2^32)

    std::vector<Node> nodes_;
    std::vector<std::uint32_t> prim_ids_;
    std::size_t depth_ = 0;
};

namespace detail {

/// Precomputed ray data for slab tests.
template <Scalar S> struct SlabRay {
    Vec3<S> origin, inv_dir;
    std::array<int, 3> negative;
    explicit SlabRay(const Ray<S>& ray) noexcept : origin(ray.origin) {
        for (int a = 0; a < 3; ++a) {
            inv_dir[a] = S(1) / ray.direction[a];  // +-inf for zero components is intended
            negative[a] = ray.direction[a] < S(0) ? 1 : 0;
        }
    }
    /// Entry distance into `b` if the ray overlaps it within (0, t_max), else +inf. The exit is
    /// widened by 1 + 2 gamma(3) so that rounding never culls a box the ray grazes (Ize 2013).
    [[nodiscard]] S enter(const BBox<S>& b, S t_max) const noexcept {
        constexpr S widen = S(1) + S(6) * std::numeric_limits<S>::epsilon();
        const Vec3<S>* bounds[2] = {&b.min, &b.max};
        S t0 = S(0), t1 = t_max;
        for (int a = 0; a < 3; ++a) {
            const S near_t = ((*bounds[negative[a]])[a] - origin[a]) * inv_dir[a];
            const S far_t = ((*bounds[1 - negative[a]])[a] - origin[a]) * inv_dir[a] * widen;
            // NaN (0 * inf, a ray in a slab's plane) must not cull: the comparisons keep t0/t1.
            t0 = near_t > t0 ? near_t : t0;
            t1 = far_t < t1 ? far_t : t1;
        }
        return t0 <= t1 ? t0 : std::numeric_limits<S>::infinity();
    }
};

}  // namespace detail

template <Scalar S>
Bvh<S>::Bvh(std::span<const BBox<S>> boxes, std::span<const Vec3<S>> centers, BvhConfig config) {
    PHOTON_ASSERT(boxes.size() == centers.size());
    PHOTON_ASSERT(boxes.size() < std::numeric_limits<std::uint32_t>::max());
    build(boxes, centers, config);
}

template <Scalar S>
void Bvh<S>::build(std::span<const BBox<S>> boxes, std::span<const Vec3<S>> centers, BvhConfig config) {
    const std::size_t n = boxes.size();
    nodes_.clear();
    prim_ids_.resize(n);
    std::iota(prim_ids_.begin(), prim_ids_.end(), 0u);
    if (n == 0) return;
    const unsigned bin_count = std::max(2u, config.bins);
    const unsigned max_leaf = std::max(1u, config.max_leaf_size);
    nodes_.reserve(2 * n);
    nodes_.push_back({});
    nodes_[0].first = 0;
    nodes_[0].count = static_cast<std::uint32_t>(n);

    struct Task {
        std::uint32_t node, depth;
    };
    std::vector<Task> stack{{0, 1}};
    std::vector<Bin> bins(bin_count);
    std::vector<BBox<S>> right_bounds(bin_count);

    while (!stack.empty()) {
        const Task task = stack.back();
        stack.pop_back();
        depth_ = std::max<std::size_t>(depth_, task.depth);
        Node& node = nodes_[task.node];
        const std::uint32_t begin = node.first, count = node.count, end = begin + count;

        BBox<S> box, centroid_box;
        for (std::uint32_t i = begin; i < end; ++i) {
            box.extend(boxes[prim_ids_[i]]);
            centroid_box.extend(centers[prim_ids_[i]]);
        }
        node.bounds = box;
        if (count <= 1) continue;

        // Best SAH split over all axes; cost relative to node visits (a constant factor of the
        // parent's area cancels, so costs are compared as area-weighted primitive counts).
        S best_cost = std::numeric_limits<S>::infinity();
        int best_axis = -1;
        unsigned best_bin = 0;
        const Vec3<S> extent = centroid_box.extent();
        for (int axis = 0; axis < 3; ++axis) {
            if (!(extent[axis] > S(0))) continue;
            const S scale = S(bin_count) / extent[axis];
            std::fill(bins.begin(), bins.end(), Bin{});
            for (std::uint32_t i = begin; i < end; ++i) {
                const std::uint32_t id = prim_ids_[i];
                const auto b = std::min(bin_count - 1,
                                        static_cast<unsigned>((centers[id][axis] - centroid_box.min[axis]) * scale));
                bins[b].bounds.extend(boxes[id]);
                ++bins[b].count;
            }
            BBox<S> acc;
            for (unsigned b = bin_count - 1; b > 0; --b) {
                acc.extend(bins[b].bounds);
                right_bounds[b] = acc;
            }
            acc = {};
            std::uint32_t left_count = 0;
            for (unsigned b = 0; b + 1 < bin_count; ++b) {
                acc.extend(bins[b].bounds);
                left_count += bins[b].count;
                const std::uint32_t right_count = count - left_count;
                if (left_count == 0 || right_count == 0) continue;
                const S cost = acc.half_area() * S(left_count) + right_bounds[b + 1].half_area() * S(right_count);
                if (cost < best_cost) best_cost = cost, best_axis = axis, best_bin = b;
            }
        }

        const S leaf_cost = box.half_area() * S(count) * S(config.intersection_cost);
        const S split_cost = box.half_area() + best_cost * S(config.intersection_cost);
        std::uint32_t mid;
        if (task.depth >= forced_median_depth && count > max_leaf) {
            // Pathological SAH chains: fall back to median splits so that the depth stays below
            // the traversal stack size whatever the input.
            const int axis = max_dimension(extent);
            mid = begin + count / 2;
            std::nth_element(prim_ids_.begin() + begin, prim_ids_.begin() + mid, prim_ids_.begin() + end,
                             [&](std::uint32_t a, std::uint32_t b) { return centers[a][axis] < centers[b][axis]; });
        } else if (best_axis >= 0 && (split_cost < leaf_cost || count > max_leaf)) {
            const S scale = S(bin_count) / extent[best_axis];
            const auto it = std::partition(prim_ids_.begin() + begin, prim_ids_.begin() + end, [&](std::uint32_t id) {
                const auto b = std::min(bin_count - 1, static_cast<unsigned>((centers[id][best_axis] -
                                                                              centroid_box.min[best_axis]) * scale));
                return b <= best_bin;
            });
            mid = static_cast<std::uint32_t>(it - prim_ids_.begin());
        } else if (count > max_leaf && best_axis < 0) {
            // All centres coincide: no plane separates them, so split the list in halves to keep
            // leaves small and the depth logarithmic.
            mid = begin + count / 2;
        } else {
            continue;  // stays a leaf
        }

        const auto left = static_cast<std::uint32_t>(nodes_.size());
        nodes_.push_back({BBox<S>{}, begin, mid - begin});
        nodes_.push_back({BBox<S>{}, mid, end - mid});
        Node& parent = nodes_[task.node];  // push_back may have moved the array
        parent.first = left;
        parent.count = 0;
        stack.push_back({left + 1, task.depth + 1});
        stack.push_back({left, task.depth + 1});
    }
    nodes_.shrink_to_fit();
}

template <Scalar S>
template <class TestFn>
bool Bvh<S>::intersect(Ray<S>& ray, TestFn&& test) const {
    if (nodes_.empty()) return false;
    const detail::SlabRay<S> slab(ray);
    if (slab.enter(nodes_[0].bounds, ray.t_max) == std::numeric_limits<S>::infinity()) return false;
    std::array<std::uint32_t, stack_size> stack;
    std::size_t top = 0;
    std::uint32_t current = 0;
    bool found = false;
    for (;;) {
        const Node& node = nodes_[current];
        if (node.is_leaf()) {
            for (std::uint32_t i = node.first; i < node.first + node.count; ++i) found |= test(i, ray);
        } else {
            const std::uint32_t left = node.first, right = node.first + 1;
            const S t_left = slab.enter(nodes_[left].bounds, ray.t_max);
            const S t_right = slab.enter(nodes_[right].bounds, ray.t_max);
            const bool hit_left = t_left != std::numeric_limits<S>::infinity();
            const bool hit_right = t_right != std::numeric_limits<S>::infinity();
            if (hit_left && hit_right) {
                const bool left_first = t_left <= t_right;
                PHOTON_ASSERT(top < stack.size());
                stack[top++] = left_first ? right : left;
                current = left_first ? left : right;
                continue;
            }
            if (hit_left || hit_right) {
                current = hit_left ? left : right;
                continue;
            }
        }
        // Pop, skipping nodes now farther than the closest hit.
        for (;;) {
            if (top == 0) return found;
            current = stack[--top];
            if (slab.enter(nodes_[current].bounds, ray.t_max) != std::numeric_limits<S>::infinity()) break;
        }
    }
}

template <Scalar S>
template <class TestFn>
bool Bvh<S>::any_hit(const Ray<S>& ray, TestFn&& test) const {
    if (nodes_.empty()) return false;
    const detail::SlabRay<S> slab(ray);
    std::array<std::uint32_t, stack_size> stack;
    std::size_t top = 0;
    stack[top++] = 0;
    while (top > 0) {
        const Node& node = nodes_[stack[--top]];
        if (slab.enter(node.bounds, ray.t_max) == std::numeric_limits<S>::infinity()) continue;
        if (node.is_leaf()) {
            for (std::uint32_t i = node.first; i < node.first + node.count; ++i)
                if (test(i, ray)) return true;
        } else {
            PHOTON_ASSERT(top + 2 <= stack.size());
            stack[top++] = node.first + 1;
            stack[top++] = node.first;
        }
    }
    return false;
}

}  // namespace photon
