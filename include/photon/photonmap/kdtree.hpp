// SPDX-License-Identifier: MIT
#pragma once
// The photon map: a balanced kd-tree over a copy of the points (Jensen 1996, "Global
// Illumination using Photon Maps"), laid out as an implicit complete tree with leaf buckets.

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <span>
#include <thread>
#include <type_traits>
#include <utility>
#include <vector>

#include "../config.hpp"
#include "../geometry/bbox.hpp"
#include "../math/vec.hpp"
#include "neighbors.hpp"
#include "point_traits.hpp"

namespace photon {

/// Build options for KdTree.
struct KdTreeConfig {
    /// Most points a leaf bucket holds; leaves hold between about half of it and all of it.
    /// Clamped to [2, 64]. Nodes cost 5 bytes per leaf (float positions), so any size from 4 up
    /// keeps KdTree<Photon> within 24 bytes per photon; query speed is flat from 24 to 64 on
    /// the benchmarks (bench/README.md).
    std::uint32_t max_leaf_size = 32;
    /// Threads the build may use (0: std::thread::hardware_concurrency()). The tree is identical
    /// for every thread count.
    unsigned threads = 1;
};

/// A balanced kd-tree over any SpatialPoint, built once after photon tracing. It copies what it
/// needs (positions, structure-of-arrays, and one payload per point, both in tree order), so the
/// input can go away. The tree is implicit: 2^depth() leaves, all at the same depth, the points of
/// leaf j are [j*n / 2^depth, (j+1)*n / 2^depth), and an inner node is only a split value and an
/// axis (the widest extent of its points). Splitting by counts keeps the tree balanced whatever
/// the data (duplicates, planes, clusters) and the build O(n log n).
/// Queries are `const` and thread-safe for concurrent readers; each thread brings its own visitor.
template <SpatialPoint P> class KdTree {
public:
    using point_type = P;
    using scalar_type = position_scalar_t<P>;
    using payload_type = payload_t<P>;

    /// An empty tree.
    KdTree() = default;
    /// Builds over a copy of `points` (fewer than 2^32 of them, positions finite).
    explicit KdTree(std::span<const P> points, KdTreeConfig config = {});
    KdTree(const KdTree&) = default;
    KdTree& operator=(const KdTree&) = default;
    /// Moving leaves an empty tree behind.
    KdTree(KdTree&& other) noexcept { *this = std::move(other); }
    KdTree& operator=(KdTree&& other) noexcept;

    [[nodiscard]] std::size_t size() const noexcept { return size_; }
    [[nodiscard]] bool empty() const noexcept { return size_ == 0; }
    /// Position of the point with tree-order index `i` (the index visitors receive).
    [[nodiscard]] Vec3<scalar_type> position(std::size_t i) const noexcept { return {xs_[i], ys_[i], zs_[i]}; }
    /// Payload (point_traits<P>::payload) of the point with tree-order index `i`.
    [[nodiscard]] const payload_type& payload(std::size_t i) const noexcept { return payloads_[i]; }
    /// Bounding box of all points; empty for an empty tree.
    [[nodiscard]] const BBox<scalar_type>& bounds() const noexcept { return bounds_; }
    /// Number of splits from the root to every leaf.
    [[nodiscard]] std::uint32_t depth() const noexcept { return depth_; }
    /// Bytes held by the tree: positions, payloads, nodes and the object itself.
    [[nodiscard]] std::size_t memory_bytes() const noexcept;

    /// Calls `visitor.visit(i, d2)` for every point i with squared distance d2 to `query` below
    /// visitor.max_distance2(). Near child first, with an explicit stack; a subtree is skipped
    /// when the distance from the query to its cell, kept per axis as the search descends (Arya
    /// and Mount 1993), is not below the current radius.
    template <class Visitor>
    void search(const Vec3<scalar_type>& query, Visitor& visitor) const
        requires NeighborVisitor<Visitor, scalar_type>;

    /// The k nearest points strictly within `max_radius` (not squared; infinity for a plain
    /// k-nearest search). `buffer` is grown to k entries if needed and reused; the result views it.
    [[nodiscard]] KNearestResult<scalar_type> k_nearest(const Vec3<scalar_type>& query, std::size_t k,
                                                        scalar_type max_radius,
                                                        std::vector<Neighbor<scalar_type>>& buffer) const;
    /// As above, keeping only points for which `accept(index, distance2)` is true.
    template <class Accept>
    [[nodiscard]] KNearestResult<scalar_type> k_nearest(const Vec3<scalar_type>& query, std::size_t k,
                                                        scalar_type max_radius,
                                                        std::vector<Neighbor<scalar_type>>& buffer,
                                                        Accept accept) const;
    /// Every point strictly within `radius` (not squared), unsorted; `buffer` is cleared and reused.
    std::span<const Neighbor<scalar_type>> within_radius(const Vec3<scalar_type>& query, scalar_type radius,
                                                         std::vector<Neighbor<scalar_type>>& buffer) const;

private:
    using S = scalar_type;
    static constexpr std::uint32_t block_ = 8;          // distance loop width; arrays carry this much padding
    static constexpr std::uint32_t max_leaf_limit_ = 64;
    static constexpr std::uint32_t max_depth_ = 32;
    static constexpr std::size_t small_node_ = 256;     // below this, select in place
    static constexpr std::size_t parallel_grain_ = 1 << 16;

    struct BuildItem {
        S p[3];
        std::uint32_t index;
    };

    [[nodiscard]] std::size_t leaf_begin(std::size_t leaf) const noexcept {
        return static_cast<std::size_t>((std::uint64_t(leaf) * size_) >> depth_);
    }
    void build(BuildItem* src, BuildItem* dst, std::uint32_t* order, std::uint32_t node, std::size_t first_leaf,
               std::size_t leaves, unsigned threads) noexcept;
    static int widest_axis(const BuildItem* items, std::size_t n, std::size_t samples) noexcept;
    static void select(BuildItem* a, BuildItem* tmp, std::size_t n, std::size_t nth, int axis) noexcept;
    static int select_out_of_place(BuildItem* src, BuildItem* dst, std::size_t n, std::size_t nth,
                                   std::uint32_t node) noexcept;
    template <class Visitor> void scan_leaf(std::size_t leaf, const S* q, Visitor& visitor, S& max_d2) const;

    std::uint32_t size_ = 0;
    std::uint32_t depth_ = 0;
    std::uint32_t leaf_count_ = 1;
    std::vector<S> xs_, ys_, zs_;
    std::vector<payload_type> payloads_;
    std::vector<S> splits_;
    std::vector<std::uint8_t> axes_;
    BBox<S> bounds_;
};

/// `KdTree(std::span(photons))` and `KdTree(photons)` (a vector) deduce the point type.
template <class P, std::size_t Extent> KdTree(std::span<P, Extent>) -> KdTree<std::remove_const_t<P>>;
template <class P, std::size_t Extent> KdTree(std::span<P, Extent>, KdTreeConfig) -> KdTree<std::remove_const_t<P>>;
template <class P, class Alloc> KdTree(const std::vector<P, Alloc>&) -> KdTree<P>;
template <class P, class Alloc> KdTree(const std::vector<P, Alloc>&, KdTreeConfig) -> KdTree<P>;

// ---------------------------------------------------------------------------------------------

namespace detail {

/// Runs f(chunk, begin, end) on at most `threads` contiguous chunks of [0, n), each at least
/// `grain` long, the first on the calling thread; a chunk whose thread cannot start runs inline.
template <class F> void kdtree_parallel_chunks(unsigned threads, std::size_t n, std::size_t grain, const F& f) {
    threads = unsigned(std::min<std::size_t>(threads, std::max<std::size_t>(1, n / grain)));
    if (threads <= 1) {
        f(0u, std::size_t(0), n);
        return;
    }
    const std::size_t chunk = (n + threads - 1) / threads;
    std::vector<std::thread> pool;
    pool.reserve(threads - 1);
    for (unsigned t = 1; t < threads; ++t) {
        const std::size_t b = std::min(n, t * chunk), e = std::min(n, b + chunk);
        try {
            pool.emplace_back([&f, t, b, e] { f(t, b, e); });
        } catch (...) {
            f(t, b, e);
        }
    }
    f(0u, std::size_t(0), std::min(n, chunk));
    for (auto& t : pool) t.join();
}

}  // namespace detail

template <SpatialPoint P> KdTree<P>::KdTree(std::span<const P> points, KdTreeConfig config) {
    PHOTON_ASSERT(points.size() < (std::size_t(1) << 32));
    size_ = static_cast<std::uint32_t>(points.size());
    if (size_ == 0) return;
    const std::size_t leaf_size = std::clamp<std::uint32_t>(config.max_leaf_size, 2, max_leaf_limit_);
    const std::size_t min_leaves = (size_ + leaf_size - 1) / leaf_size;
    while ((std::size_t(1) << depth_) < min_leaves) ++depth_;
    leaf_count_ = std::uint32_t(1) << depth_;
    const unsigned threads = config.threads == 0 ? std::max(1u, std::thread::hardware_concurrency()) : config.threads;

    auto items = std::make_unique_for_overwrite<BuildItem[]>(size_);
    auto scratch = std::make_unique_for_overwrite<BuildItem[]>(size_);
    auto order = std::make_unique_for_overwrite<std::uint32_t[]>(size_);
    std::vector<BBox<S>> chunk_bounds(threads);
    detail::kdtree_parallel_chunks(threads, size_, parallel_grain_, [&](unsigned chunk, std::size_t b, std::size_t e) {
        BBox<S> box;
        for (std::size_t i = b; i < e; ++i) {
            const auto p = point_traits<P>::position(points[i]);
            items[i] = {{S(p.x), S(p.y), S(p.z)}, static_cast<std::uint32_t>(i)};
            box.extend(Vec3<S>(items[i].p[0], items[i].p[1], items[i].p[2]));
        }
        chunk_bounds[chunk] = box;
    });
    for (const auto& box : chunk_bounds) bounds_.extend(box);

    splits_.assign(leaf_count_, S(0));
    axes_.assign(leaf_count_, 0);
    xs_.resize(size_ + block_);
    ys_.resize(size_ + block_);
    zs_.resize(size_ + block_);
    payloads_.resize(size_);
    build(items.get(), scratch.get(), order.get(), 1, 0, leaf_count_, threads);
    items.reset();
    scratch.reset();
    detail::kdtree_parallel_chunks(threads, size_, parallel_grain_, [&](unsigned, std::size_t b, std::size_t e) {
        constexpr std::size_t ahead = 16;
        for (std::size_t i = b; i < e; ++i) {
#if defined(__GNUC__) || defined(__clang__)
            if (i + ahead < e) __builtin_prefetch(&points[order[i + ahead]]);
#endif
            payloads_[i] = point_traits<P>::payload(points[order[i]]);
        }
    });
}

// Splits the points of leaves [first_leaf, first_leaf + leaves), held in `src`, at the median of
// their widest axis. Large nodes partition out of place into `dst`, and their children continue
// from there (the two buffers swap roles); small ones select in place. Leaves write the positions
// and the input order.
template <SpatialPoint P>
void KdTree<P>::build(BuildItem* src, BuildItem* dst, std::uint32_t* order, std::uint32_t node, std::size_t first_leaf,
                      std::size_t leaves, unsigned threads) noexcept {
    const std::size_t begin = leaf_begin(first_leaf), end = leaf_begin(first_leaf + leaves);
    if (leaves == 1) {
        for (std::size_t i = begin; i < end; ++i) {
            xs_[i] = src[i].p[0];
            ys_[i] = src[i].p[1];
            zs_[i] = src[i].p[2];
            order[i] = src[i].index;
        }
        return;
    }
    const std::size_t n = end - begin, half = leaves / 2, mid = leaf_begin(first_leaf + half);
    int axis = 0;
    if (n <= small_node_) {
        axis = widest_axis(src + begin, n, n);
        select(src + begin, dst + begin, n, mid - begin, axis);
    } else {
        axis = select_out_of_place(src + begin, dst + begin, n, mid - begin, node);
        std::swap(src, dst);
    }
    splits_[node] = src[mid].p[axis];
    axes_[node] = static_cast<std::uint8_t>(axis);
    if (threads > 1 && n >= parallel_grain_) {
        try {
            std::thread right([=, this] { build(src, dst, order, 2 * node + 1, first_leaf + half, half, threads / 2); });
            build(src, dst, order, 2 * node, first_leaf, half, threads - threads / 2);
            right.join();
            return;
        } catch (...) {
        }
    }
    build(src, dst, order, 2 * node, first_leaf, half, 1);
    build(src, dst, order, 2 * node + 1, first_leaf + half, half, 1);
}

template <SpatialPoint P> int KdTree<P>::widest_axis(const BuildItem* items, std::size_t n, std::size_t samples) noexcept {
    S lo[3] = {items[0].p[0], items[0].p[1], items[0].p[2]};
    S hi[3] = {lo[0], lo[1], lo[2]};
    const std::size_t stride = n / samples;
    for (std::size_t s = 0, i = 0; s < samples; ++s, i += stride) {
        for (int a = 0; a < 3; ++a) {
            lo[a] = std::min(lo[a], items[i].p[a]);
            hi[a] = std::max(hi[a], items[i].p[a]);
        }
    }
    return max_dimension(Vec3<S>(hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]));
}

// Quickselect with a median-of-3 pivot and a branch-free three-way partition through `tmp`
// (equal keys end the search, so duplicates cost nothing); std::nth_element after too many rounds.
template <SpatialPoint P>
void KdTree<P>::select(BuildItem* a, BuildItem* tmp, std::size_t n, std::size_t nth, int axis) noexcept {
    auto run = [&]<int A>() {
        for (int rounds = 0; n > 16; ++rounds) {
            if (rounds > 64) {
                std::nth_element(a, a + nth, a + n, [](const BuildItem& x, const BuildItem& y) { return x.p[A] < y.p[A]; });
                return;
            }
            const S k0 = a[n / 4].p[A], k1 = a[n / 2].p[A], k2 = a[n - 1 - n / 4].p[A];
            const S pivot = std::max(std::min(k0, k1), std::min(std::max(k0, k1), k2));
            std::size_t below = 0, equal = 0, above = 0;
            for (std::size_t i = 0; i < n; ++i) {
                const BuildItem item = a[i];
                tmp[below] = item;
                tmp[n - 1 - above] = item;
                a[equal] = item;
                const bool is_below = item.p[A] < pivot, is_above = pivot < item.p[A];
                below += is_below ? 1 : 0;
                above += is_above ? 1 : 0;
                equal += !is_below && !is_above ? 1 : 0;
            }
            std::move_backward(a, a + equal, a + below + equal);
            std::copy(tmp, tmp + below, a);
            std::copy(tmp + n - above, tmp + n, a + below + equal);
            if (nth < below) {
                n = below;
            } else if (nth < below + equal) {
                return;
            } else {
                a += below + equal;
                nth -= below + equal;
                n = above;
            }
        }
        for (std::size_t i = 1; i < n; ++i) {
            const BuildItem x = a[i];
            std::size_t k = i;
            for (; k > 0 && x.p[A] < a[k - 1].p[A]; --k) a[k] = a[k - 1];
            a[k] = x;
        }
    };
    if (axis == 0) run.template operator()<0>();
    else if (axis == 1) run.template operator()<1>();
    else run.template operator()<2>();
}

// Selection for large nodes, src -> dst (Floyd and Rivest 1975): two pivots drawn from a random
// sample bracket the wanted rank, one branch-free pass splits the points into below / between /
// above, and only the small middle part is searched further. The sample's widest axis is the
// node's split axis. `src` is left as scratch.
template <SpatialPoint P>
int KdTree<P>::select_out_of_place(BuildItem* src, BuildItem* dst, std::size_t n, std::size_t nth, std::uint32_t node) noexcept {
    constexpr std::size_t max_samples = 1024;
    std::uint32_t rng = node * 2654435761u + 1u;
    int axis = -1;
    for (;;) {
        std::size_t samples = 16;
        while (samples < max_samples && samples * 32 <= n) samples *= 2;
        const std::size_t slack = std::size_t(0.7 * std::sqrt(double(samples)));
        const std::size_t stride = n / samples;
        BuildItem* sample = dst;
        for (std::size_t s = 0; s < samples; ++s) {
            rng = rng * 1664525u + 1013904223u;
            sample[s] = src[s * stride + std::size_t((std::uint64_t(rng) * stride) >> 32)];
        }
        if (axis < 0) axis = widest_axis(sample, samples, samples);
        S keys[max_samples];
        for (std::size_t s = 0; s < samples; ++s) keys[s] = sample[s].p[axis];
        std::sort(keys, keys + samples);
        const std::size_t at = nth * samples / n;
        const S lo = keys[at > slack ? at - slack : 0], hi = keys[std::min(samples - 1, at + slack)];

        std::size_t below = 0, inside = 0, above = 0;
        auto run = [&]<int A>() {
            for (std::size_t i = 0; i < n; ++i) {
                const BuildItem item = src[i];
                dst[below] = item;
                dst[n - 1 - above] = item;
                src[inside] = item;
                const bool is_below = item.p[A] < lo, is_above = hi < item.p[A];
                below += is_below ? 1 : 0;
                above += is_above ? 1 : 0;
                inside += !is_below && !is_above ? 1 : 0;
            }
        };
        if (axis == 0) run.template operator()<0>();
        else if (axis == 1) run.template operator()<1>();
        else run.template operator()<2>();
        if (nth < below || nth >= below + inside || !(lo < hi) || inside <= small_node_ || inside == n) {
            std::copy(src, src + inside, dst + below);
            if (nth < below) select(dst, src, below, nth, axis);
            else if (nth >= below + inside) select(dst + below + inside, src, above, nth - below - inside, axis);
            else if (lo < hi) select(dst + below, src, inside, nth - below, axis);
            return axis;
        }
        dst += below;
        nth -= below;
        n = inside;
    }
}

template <SpatialPoint P> KdTree<P>& KdTree<P>::operator=(KdTree&& other) noexcept {
    size_ = std::exchange(other.size_, 0u);
    depth_ = std::exchange(other.depth_, 0u);
    leaf_count_ = std::exchange(other.leaf_count_, 1u);
    xs_ = std::move(other.xs_);
    ys_ = std::move(other.ys_);
    zs_ = std::move(other.zs_);
    payloads_ = std::move(other.payloads_);
    splits_ = std::move(other.splits_);
    axes_ = std::move(other.axes_);
    bounds_ = std::exchange(other.bounds_, BBox<S>{});
    other.xs_.clear();
    other.ys_.clear();
    other.zs_.clear();
    other.payloads_.clear();
    other.splits_.clear();
    other.axes_.clear();
    return *this;
}

template <SpatialPoint P> std::size_t KdTree<P>::memory_bytes() const noexcept {
    return sizeof(*this) + (xs_.capacity() + ys_.capacity() + zs_.capacity() + splits_.capacity()) * sizeof(S) +
           payloads_.capacity() * sizeof(payload_type) + axes_.capacity();
}

template <SpatialPoint P>
template <class Visitor>
void KdTree<P>::search(const Vec3<scalar_type>& query, Visitor& visitor) const
    requires NeighborVisitor<Visitor, scalar_type>
{
    S max_d2 = visitor.max_distance2();
    if (size_ == 0 || !(max_d2 > S(0))) return;
    struct Pending {
        S offset[3];
        S distance2;
        std::uint32_t node;
    };
    Pending stack[max_depth_];
    std::uint32_t top = 0;
    const S q[3] = {query.x, query.y, query.z};
    S offset[3] = {S(0), S(0), S(0)};
    std::uint32_t node = 1;
    for (;;) {
        while (node < leaf_count_) {
            const unsigned axis = axes_[node];
            const S diff = q[axis] - splits_[node];
            const std::uint32_t near = 2 * node + (diff >= S(0) ? 1u : 0u);
            Pending& far = stack[top];
            far.offset[0] = offset[0];
            far.offset[1] = offset[1];
            far.offset[2] = offset[2];
            far.offset[axis] = diff;
            far.distance2 = far.offset[0] * far.offset[0] + far.offset[1] * far.offset[1] + far.offset[2] * far.offset[2];
            far.node = near ^ 1u;
            top += far.distance2 < max_d2 ? 1u : 0u;
            node = near;
        }
        scan_leaf(node - leaf_count_, q, visitor, max_d2);
        for (;;) {
            if (top == 0) return;
            const Pending& p = stack[--top];
            if (p.distance2 < max_d2) {
                offset[0] = p.offset[0];
                offset[1] = p.offset[1];
                offset[2] = p.offset[2];
                node = p.node;
                break;
            }
        }
    }
}

// Distances for a whole leaf first, in blocks the compiler vectorises (reading into the padding),
// then the visitor sees the points below the radius, which is re-read after every visit.
template <SpatialPoint P>
template <class Visitor>
PHOTON_FORCEINLINE void KdTree<P>::scan_leaf(std::size_t leaf, const S* q, Visitor& visitor, S& max_d2) const {
    const std::size_t begin = leaf_begin(leaf), count = leaf_begin(leaf + 1) - begin;
    const S* PHOTON_RESTRICT xs = xs_.data() + begin;
    const S* PHOTON_RESTRICT ys = ys_.data() + begin;
    const S* PHOTON_RESTRICT zs = zs_.data() + begin;
    alignas(64) S d2[max_leaf_limit_ + block_];
    for (std::size_t b = 0; b < count; b += block_) {
        for (std::size_t j = b; j < b + block_; ++j) {
            const S dx = xs[j] - q[0], dy = ys[j] - q[1], dz = zs[j] - q[2];
            d2[j] = dx * dx + dy * dy + dz * dz;
        }
    }
    for (std::size_t b = 0; b < count; b += block_) {
        unsigned mask = 0;
        for (unsigned j = 0; j < block_; ++j) mask |= unsigned(d2[b + j] < max_d2) << j;
        if (count - b < block_) mask &= (1u << (count - b)) - 1u;
        while (mask != 0) {
            const std::size_t j = b + static_cast<std::size_t>(std::countr_zero(mask));
            mask &= mask - 1;
            if (d2[j] < max_d2) {
                visitor.visit(static_cast<std::uint32_t>(begin + j), d2[j]);
                max_d2 = visitor.max_distance2();
            }
        }
    }
}

template <SpatialPoint P>
auto KdTree<P>::k_nearest(const Vec3<S>& query, std::size_t k, S max_radius, std::vector<Neighbor<S>>& buffer) const
    -> KNearestResult<scalar_type> {
    return k_nearest(query, k, max_radius, buffer, AcceptAll{});
}

template <SpatialPoint P>
template <class Accept>
auto KdTree<P>::k_nearest(const Vec3<S>& query, std::size_t k, S max_radius, std::vector<Neighbor<S>>& buffer,
                          Accept accept) const -> KNearestResult<scalar_type> {
    PHOTON_ASSERT(max_radius >= S(0));
    if (buffer.size() < k) buffer.resize(k);
    KNearest<S, Accept> visitor(std::span<Neighbor<S>>(buffer.data(), k), max_radius * max_radius, std::move(accept));
    search(query, visitor);
    return {visitor.neighbors(), visitor.radius2()};
}

template <SpatialPoint P>
auto KdTree<P>::within_radius(const Vec3<S>& query, S radius, std::vector<Neighbor<S>>& buffer) const
    -> std::span<const Neighbor<scalar_type>> {
    PHOTON_ASSERT(radius >= S(0));
    WithinRadius<S> visitor(buffer, radius * radius);
    search(query, visitor);
    return visitor.neighbors();
}

}  // namespace photon
