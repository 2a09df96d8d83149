// SPDX-License-Identifier: MIT
#pragma once
// Bounding volume hierarchy over anything with a bounding box. The BVH never sees primitives: it
// is built from spans of boxes and centres, and traversal calls back into the caller for each
// primitive in a reached leaf (the design of madmann91/bvh).

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numeric>
#include <span>
#include <type_traits>
#include <utility>
#include <vector>

#include "../config.hpp"
#include "../memory/huge_page_allocator.hpp"
#include "../parallel/parallel_for.hpp"
#include "bbox.hpp"
#include "ray.hpp"

// The float slab test uses SSE (part of x86-64's baseline); elsewhere, and for double, the same
// test runs in plain code.
#if defined(__SSE2__) || defined(_M_X64)
#include <emmintrin.h>
#define PHOTON_BVH_SSE 1
#else
#define PHOTON_BVH_SSE 0
#endif

namespace photon {

/// Build options. Costs are in units of one node visit.
struct BvhConfig {
    unsigned max_leaf_size = 8;    ///< never more primitives per leaf than this, except identical centres
    unsigned bins = 16;            ///< SAH bins per axis of large nodes (see Bvh::node_bins)
    float intersection_cost = 1.0f;  ///< cost of one primitive test (one block's, see leaf_block) relative to a node visit
    /// Leaves start at multiples of this in primitive_indices(), padded with `padding` entries, so
    /// that a caller can store primitives in blocks tested together (TriangleMesh: 4 per SSE test).
    /// With 1, leaves are neither padded nor reordered.
    unsigned leaf_block = 1;
    /// Build threads (0: all cores). Builds of fewer than 16,384 primitives use the calling thread
    /// alone. The tree is the same for any count.
    unsigned threads = 0;
};

/// BVH built as a binary tree by binned SAH (Wald 2007, "On fast Construction of SAH-based
/// Bounding Volume Hierarchies"), then collapsed into an 8-wide tree for traversal (as Embree's
/// BVH8): each node holds its eight children's boxes side by side, so two SSE tests (float; the
/// same test in plain code for double) check them all with the robust slab test of Ize (2013).
/// Eight children rather than four cut the chain of dependent node loads that random rays wait
/// on by a third (bench/README.md, '8-wide nodes').
/// Traversal is ordered by entry distance and skips stacked nodes the closest hit has passed.
template <Scalar S> class Bvh {
public:
    static constexpr int width = 8;
    /// Up to eight children. A child is an inner node (count 0), a leaf (a range of
    /// primitive_indices()) or an unused slot (an empty box, which no ray enters).
    struct alignas(64) Node {
        std::array<std::array<S, width>, 3> min, max;  ///< [axis][child]: structure of arrays
        std::array<std::uint32_t, width> first{};      ///< leaf: first index into primitive_indices(); inner: node index
        std::array<std::uint32_t, width> count{};      ///< primitives in a leaf child; 0 for an inner child or unused slot
        [[nodiscard]] BBox<S> child_bounds(int c) const noexcept {
            return {{min[0][c], min[1][c], min[2][c]}, {max[0][c], max[1][c], max[2][c]}};
        }
    };

    Bvh() = default;
    /// Builds over `boxes[i]` with representative points `centers[i]` (usually box centres).
    Bvh(std::span<const BBox<S>> boxes, std::span<const Vec3<S>> centers, BvhConfig config = {});
    /// Builds over `boxes[i]` represented by their centres (meshes, scenes), without an array of
    /// them.
    explicit Bvh(std::span<const BBox<S>> boxes, BvhConfig config = {});

    [[nodiscard]] bool empty() const noexcept { return nodes_.empty(); }
    /// The wide nodes; nodes()[0] is the root.
    [[nodiscard]] std::span<const Node> nodes() const noexcept { return nodes_; }
    /// Primitive ids in leaf order: leaf nodes refer to ranges of this array (with leaf_block > 1,
    /// each leaf's range starts at a multiple of it and the slots between leaves hold `padding`).
    static constexpr std::uint32_t padding = ~std::uint32_t(0);
    [[nodiscard]] std::span<const std::uint32_t> primitive_indices() const noexcept { return prim_ids_; }
    [[nodiscard]] BBox<S> bounds() const noexcept { return bounds_; }
    /// Depth of the binary tree before collapsing (the wide tree is shallower).
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
    /// The same two traversals calling `leaf(first, count, ray)` once per reached leaf, for
    /// callers that test a leaf's primitives together.
    template <class LeafFn> bool intersect_leaves(Ray<S>& ray, LeafFn&& leaf) const;
    template <class LeafFn> bool any_hit_leaves(const Ray<S>& ray, LeafFn&& leaf) const;
    /// Calls `visit(leaf_position)` for every primitive in a leaf whose box overlaps `box`; a
    /// `visit` that returns bool stops the walk by returning false.
    template <class VisitFn> void for_each_overlapping(const BBox<S>& box, VisitFn&& visit) const;

private:
    struct BinaryNode {
        BBox<S> bounds;
        std::uint32_t first = 0;  ///< leaf: first index into prim_ids_; inner: left child (right = first + 1)
        std::uint32_t count = 0;  ///< primitives in a leaf; 0 marks an inner node
        [[nodiscard]] bool is_leaf() const noexcept { return count != 0; }
    };
    /// Whether a build of n primitives on `threads` threads (0: all) splits in parallel.
    [[nodiscard]] static bool parallel_build(std::size_t n, unsigned threads) noexcept {
        return n >= (1u << 14) && resolve_threads(threads) > 1;
    }
    /// The binary tree: room for the most nodes a build can write (2n - 1; 4n in parallel, whose
    /// top and subtrees have regions of their own), allocated but never initialised as a whole,
    /// so that only the pages written are touched, in huge pages.
    class BinaryNodes {
    public:
        std::size_t count = 0;  ///< nodes in the tree (regions leave unused slots between them)

        /// For a build of n primitives on `threads` threads.
        BinaryNodes(std::size_t n, unsigned threads)
            : capacity_((parallel_build(n, threads) ? 4 : 2) * n),
              nodes_(n > 0 ? HugePageAllocator<BinaryNode>().allocate(capacity_) : nullptr) {}
        BinaryNodes(BinaryNodes&& other) noexcept
            : count(other.count), capacity_(std::exchange(other.capacity_, 0)),
              nodes_(std::exchange(other.nodes_, nullptr)) {}
        BinaryNodes& operator=(BinaryNodes&&) = delete;
        ~BinaryNodes() {
            if (nodes_) HugePageAllocator<BinaryNode>().deallocate(nodes_, capacity_);
        }
        [[nodiscard]] BinaryNode* data() const noexcept { return nodes_; }
        [[nodiscard]] const BinaryNode& operator[](std::size_t i) const noexcept { return nodes_[i]; }

    private:
        std::size_t capacity_;
        BinaryNode* nodes_;  // aggregates: writing one begins its lifetime
    };
    /// A region of a BinaryNodes array, its nodes numbered from its start.
    struct NodeRegion {
        BinaryNode* base;
        std::uint32_t used = 0;
        [[nodiscard]] BinaryNode& operator[](std::uint32_t i) const noexcept { return base[i]; }
        [[nodiscard]] std::uint32_t size() const noexcept { return used; }
        void push_back(const BinaryNode& node) noexcept { base[used++] = node; }
    };
    struct Bin {
        BBox<S> bounds;
        std::uint32_t count = 0;
    };
    /// A subtree waiting on the traversal stack: a node or a leaf, and where the ray enters it.
    struct StackEntry {
        std::uint32_t first, count;
        S t;
    };
    BinaryNodes build_binary(std::span<const BBox<S>> boxes, std::span<const Vec3<S>> centers,
                                         BvhConfig config);
#if PHOTON_BVH_SSE
    /// The same build for float in SSE (see bvh_build_sse.hpp); BoxCentres: every centre is its
    /// box's (`centers` may then be empty).
    template <bool BoxCentres>
    BinaryNodes build_binary_sse(std::span<const BBox<S>> boxes, std::span<const Vec3<S>> centers,
                                             BvhConfig config);
#endif
    /// Drives a build's node splits from the root `nodes[0]` (see bvh_build.hpp); `make_split()`
    /// gives a callable with its own scratch space that splits one node of a NodeRegion.
    template <class Task, class MakeSplit>
    void run_splits(BinaryNodes& nodes, Task root, unsigned threads, MakeSplit make_split);
    void collapse(const BinaryNodes& binary, unsigned leaf_block);
    /// Starts loading both cache lines of a node the ray entered, so that the misses of sibling
    /// subtrees overlap instead of queueing one after another.
    PHOTON_FORCEINLINE void prefetch(std::uint32_t node) const noexcept {
#if defined(__GNUC__)
        const char* p = reinterpret_cast<const char*>(&nodes_[node]);
        for (std::size_t line = 0; line < sizeof(Node); line += 64) __builtin_prefetch(p + line);
#else
        (void)node;
#endif
    }

    /// SAH bins per axis for a node of `count` primitives: as Embree, 4 + count / 20 up to `most`
    /// (config.bins), since the work per bin, not per primitive, dominates small nodes.
    [[nodiscard]] static unsigned node_bins(std::uint32_t count, unsigned most) noexcept {
        return std::min(most, 4 + count / 20);
    }
    static constexpr std::uint32_t forced_median_depth = 64;
    // The binary depth stays below forced_median_depth + log2(2^32) + 1; each wide level
    // pushes at most width - 1 entries.
    static constexpr std::size_t stack_size = (width - 1) * (forced_median_depth + 33) + 1;

    std::vector<Node, HugePageAllocator<Node>> nodes_;
    BBox<S> bounds_;
    std::vector<std::uint32_t> prim_ids_;
    std::size_t depth_ = 0;
};

namespace detail {

/// Precomputed ray data for slab tests: the inverse direction and its signs, once per ray.
template <Scalar S> struct SlabRay {
    Vec3<S> origin, inv_dir;
    std::array<bool, 3> negative;
#if PHOTON_BVH_SSE
    // Each coordinate repeated four times, for the SSE path (float only).
    alignas(16) std::array<std::array<float, 4>, 3> origin4, inv_dir4;
#endif

    explicit SlabRay(const Ray<S>& ray) noexcept : origin(ray.origin) {
        for (int a = 0; a < 3; ++a) {
            inv_dir[a] = S(1) / ray.direction[a];  // +-inf for zero components is intended
            negative[a] = std::signbit(ray.direction[a]);  // -0 too, so that it pairs with -inf
#if PHOTON_BVH_SSE
            if constexpr (std::is_same_v<S, float>) origin4[a].fill(origin[a]), inv_dir4[a].fill(inv_dir[a]);
#endif
        }
    }

    /// Tests the ray against the W boxes of `node` within (0, t_max). Returns a bit mask of the
    /// boxes it enters and writes their entry distances to `t_enter`. The exit is widened by
    /// 1 + 2 gamma(3) so that rounding never culls a box the ray grazes (Ize 2013).
    template <class Node, std::size_t W>
    [[nodiscard]] PHOTON_FORCEINLINE unsigned enter(const Node& node, S t_max, std::array<S, W>& t_enter) const noexcept {
        constexpr S widen = S(1) + S(6) * std::numeric_limits<S>::epsilon();
#if PHOTON_BVH_SSE
        if constexpr (std::is_same_v<S, float>) {
            // Four children per SSE test: two tests for an 8-wide node.
            unsigned mask = 0;
            for (std::size_t g = 0; g < W; g += 4) {
                __m128 t0 = _mm_setzero_ps(), t1 = _mm_set1_ps(t_max);
                for (int a = 0; a < 3; ++a) {
                    const __m128 o = _mm_load_ps(origin4[a].data()), inv = _mm_load_ps(inv_dir4[a].data());
                    const float* near_side = (negative[a] ? node.max : node.min)[a].data() + g;
                    const float* far_side = (negative[a] ? node.min : node.max)[a].data() + g;
                    const __m128 near_t = _mm_mul_ps(_mm_sub_ps(_mm_load_ps(near_side), o), inv);
                    const __m128 far_t = _mm_mul_ps(_mm_mul_ps(_mm_sub_ps(_mm_load_ps(far_side), o), inv), _mm_set1_ps(widen));
                    // maxps/minps return their second operand when either is NaN (0 * inf, a ray in
                    // a slab's plane), so NaN never culls, as in the scalar code below.
                    t0 = _mm_max_ps(near_t, t0);
                    t1 = _mm_min_ps(far_t, t1);
                }
                _mm_storeu_ps(t_enter.data() + g, t0);
                mask |= static_cast<unsigned>(_mm_movemask_ps(_mm_cmple_ps(t0, t1))) << g;
            }
            return mask;
        }
#endif
        std::array<S, W> t0{}, t1;
        t1.fill(t_max);
        for (int a = 0; a < 3; ++a) {
            const auto& near_side = negative[a] ? node.max[a] : node.min[a];
            const auto& far_side = negative[a] ? node.min[a] : node.max[a];
            for (std::size_t c = 0; c < W; ++c) {
                const S near_t = (near_side[c] - origin[a]) * inv_dir[a];
                const S far_t = (far_side[c] - origin[a]) * inv_dir[a] * widen;
                // NaN (0 * inf, a ray in a slab's plane) must not cull: the comparisons keep t0/t1.
                t0[c] = near_t > t0[c] ? near_t : t0[c];
                t1[c] = far_t < t1[c] ? far_t : t1[c];
            }
        }
        unsigned mask = 0;
        for (std::size_t c = 0; c < W; ++c) mask |= (t0[c] <= t1[c] ? 1u : 0u) << c;
        t_enter = t0;
        return mask;
    }
};

}  // namespace detail

template <Scalar S>
template <class TestFn>
bool Bvh<S>::intersect(Ray<S>& ray, TestFn&& test) const {
    return intersect_leaves(ray, [&](std::uint32_t first, std::uint32_t count, Ray<S>& r) {
        bool found = false;
        for (std::uint32_t i = first; i < first + count; ++i) found |= test(i, r);
        return found;
    });
}

template <Scalar S>
template <class TestFn>
bool Bvh<S>::any_hit(const Ray<S>& ray, TestFn&& test) const {
    return any_hit_leaves(ray, [&](std::uint32_t first, std::uint32_t count, const Ray<S>& r) {
        for (std::uint32_t i = first; i < first + count; ++i)
            if (test(i, r)) return true;
        return false;
    });
}

template <Scalar S>
template <class LeafFn>
bool Bvh<S>::intersect_leaves(Ray<S>& ray, LeafFn&& leaf) const {
    if (nodes_.empty()) return false;
    const detail::SlabRay<S> slab(ray);
    std::array<StackEntry, stack_size> stack;
    std::size_t top = 0;
    StackEntry current{0, 0, S(0)};
    bool found = false;
    for (;;) {
        if (current.count == 0) {
            const Node& node = nodes_[current.first];
            std::array<S, width> t;
            unsigned mask = slab.enter(node, ray.t_max, t);
            if (mask != 0) {
                // The children entered, farthest first: all but the nearest go on the stack.
                std::array<StackEntry, width> hits;
                int n = 0;
                for (; mask != 0; mask &= mask - 1) {
                    const int c = std::countr_zero(mask);
                    StackEntry e{node.first[c], node.count[c], t[c]};
                    if (e.count == 0) prefetch(e.first);
                    int i = n++;
                    for (; i > 0 && hits[i - 1].t < e.t; --i) hits[i] = hits[i - 1];
                    hits[i] = e;
                }
                PHOTON_ASSERT(top + std::size_t(n - 1) <= stack.size());
                for (int i = 0; i + 1 < n; ++i) stack[top++] = hits[i];
                current = hits[n - 1];
                continue;
            }
        } else {
            found |= leaf(current.first, current.count, ray);
        }
        // Pop, skipping subtrees the ray enters beyond the closest hit found since.
        for (;;) {
            if (top == 0) return found;
            current = stack[--top];
            if (current.t <= ray.t_max) break;
        }
    }
}

template <Scalar S>
template <class LeafFn>
bool Bvh<S>::any_hit_leaves(const Ray<S>& ray, LeafFn&& leaf) const {
    if (nodes_.empty()) return false;
    const detail::SlabRay<S> slab(ray);
    std::array<StackEntry, stack_size> stack;
    std::size_t top = 0;
    stack[top++] = {0, 0, S(0)};
    while (top > 0) {
        const StackEntry e = stack[--top];
        if (e.count != 0) {
            if (leaf(e.first, e.count, ray)) return true;
            continue;
        }
        const Node& node = nodes_[e.first];
        std::array<S, width> t;
        PHOTON_ASSERT(top + width <= stack.size());
        for (unsigned mask = slab.enter(node, ray.t_max, t); mask != 0; mask &= mask - 1) {
            const int c = std::countr_zero(mask);
            if (node.count[c] == 0) prefetch(node.first[c]);
            stack[top++] = {node.first[c], node.count[c], t[c]};
        }
    }
    return false;
}

template <Scalar S>
template <class VisitFn>
void Bvh<S>::for_each_overlapping(const BBox<S>& box, VisitFn&& visit) const {
    if (nodes_.empty()) return;
    std::array<std::uint32_t, stack_size> stack;
    std::size_t top = 0;
    stack[top++] = 0;
    while (top > 0) {
        const Node& node = nodes_[stack[--top]];
        PHOTON_ASSERT(top + width <= stack.size());
        for (int c = 0; c < width; ++c) {
            if (!node.child_bounds(c).overlaps(box)) continue;  // also skips unused slots (empty boxes)
            if (node.count[c] == 0) {
                stack[top++] = node.first[c];
                continue;
            }
            for (std::uint32_t i = node.first[c]; i < node.first[c] + node.count[c]; ++i) {
                if constexpr (std::is_same_v<std::invoke_result_t<VisitFn&, std::uint32_t>, bool>) {
                    if (!visit(i)) return;
                } else {
                    visit(i);
                }
            }
        }
    }
}

}  // namespace photon

#include "bvh_build.hpp"      // the build: Bvh's constructor, build_binary, collapse
#include "bvh_build_sse.hpp"  // build_binary_sse
