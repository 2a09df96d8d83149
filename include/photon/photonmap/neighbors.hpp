// SPDX-License-Identifier: MIT
#pragma once
// Search policies for KdTree::search (nanoflann's result sets, with clearer names): a visitor
// says how far the search must look and receives every point closer than that.

#include <algorithm>
#include <concepts>
#include <cstdint>
#include <limits>
#include <span>
#include <type_traits>
#include <utility>
#include <vector>

#include "../config.hpp"
#include "../math/vec.hpp"

namespace photon {

/// One search result: squared distance to the query and index of the point in tree order
/// (read it back with KdTree::position / KdTree::payload).
template <Scalar S = float> struct Neighbor {
    S distance2;
    std::uint32_t index;
};

/// What KdTree::search drives. `max_distance2()` is the current pruning radius, squared; it may
/// shrink while the search runs (k-nearest) but must never grow. `visit(index, distance2)` is
/// called exactly once for each point with distance2 < max_distance2() at the time of the call.
/// A visitor stops the search early by returning 0 from max_distance2().
template <class V, class S>
concept NeighborVisitor = Scalar<S> && requires(V& v, const V& cv, std::uint32_t index, S distance2) {
    { cv.max_distance2() } -> std::convertible_to<S>;
    v.visit(index, distance2);
};

/// The default accept predicate: every point the tree reports is kept.
struct AcceptAll {
    template <class S> constexpr bool operator()(std::uint32_t, S) const noexcept { return true; }
};

/// The k nearest points within a maximum radius, the photon-map query (Jensen 1996). Results go
/// to caller-owned storage of k entries, so one buffer per thread serves every query without
/// allocating. It fills unsorted until k points are found, then becomes a max-heap on distance
/// and replaces its top, O(log k) per insert (Jensen 2001, "Realistic Image Synthesis Using
/// Photon Mapping", ch. 6). `Accept(index, distance2) -> bool` can reject points, e.g. photons
/// off the query's tangent plane.
template <Scalar S, class Accept = AcceptAll> class KNearest {
public:
    /// k = storage.size(); only points with distance2 < max_distance2 are kept.
    KNearest(std::span<Neighbor<S>> storage, S max_distance2, Accept accept = {}) noexcept;

    [[nodiscard]] S max_distance2() const noexcept { return max_distance2_; }
    void visit(std::uint32_t index, S distance2) noexcept(noexcept(std::declval<Accept&>()(index, distance2)));

    /// The points kept so far, in no particular order.
    [[nodiscard]] std::span<const Neighbor<S>> neighbors() const noexcept { return {data_, count_}; }
    [[nodiscard]] std::size_t size() const noexcept { return count_; }
    [[nodiscard]] bool full() const noexcept { return count_ == k_; }
    /// Squared radius of the gathering disc: the distance to the k-th neighbour when k >= 1 points
    /// were found, else the maximum radius the search started with.
    [[nodiscard]] S radius2() const noexcept { return count_ == k_ && k_ > 0 ? max_distance2_ : limit_distance2_; }
    /// Sorts the kept points by increasing distance (ties by index). The visitor is spent after this.
    void sort() noexcept;

private:
    void sift_down(std::size_t i, Neighbor<S> n) noexcept;

    Neighbor<S>* data_;
    std::size_t k_;
    std::size_t count_ = 0;
    S max_distance2_;
    S limit_distance2_;
    [[no_unique_address]] Accept accept_;
};

/// Every point with distance2 < radius2 (nanoflann's RadiusResultSet). Results are appended to a
/// caller-owned vector, cleared first; reusing the vector across queries allocates only when it
/// has to grow.
template <Scalar S, class Accept = AcceptAll> class WithinRadius {
public:
    WithinRadius(std::vector<Neighbor<S>>& out, S radius2, Accept accept = {}) noexcept
        : out_(&out), radius2_(radius2), accept_(std::move(accept)) {
        out.clear();
    }

    [[nodiscard]] S max_distance2() const noexcept { return radius2_; }
    void visit(std::uint32_t index, S distance2) {
        if (accept_(index, distance2)) out_->push_back({distance2, index});
    }
    [[nodiscard]] std::span<const Neighbor<S>> neighbors() const noexcept { return *out_; }

private:
    std::vector<Neighbor<S>>* out_;
    S radius2_;
    [[no_unique_address]] Accept accept_;
};

/// What KdTree::k_nearest returns: the neighbours (a view into the caller's buffer, unsorted) and
/// the squared radius the density estimate should divide by (KNearest::radius2).
template <Scalar S> struct KNearestResult {
    std::span<const Neighbor<S>> neighbors;
    S radius2;
};

// ---------------------------------------------------------------------------------------------

template <Scalar S, class Accept>
KNearest<S, Accept>::KNearest(std::span<Neighbor<S>> storage, S max_distance2, Accept accept) noexcept
    : data_(storage.data()),
      k_(storage.size()),
      max_distance2_(storage.empty() ? S(0) : max_distance2),
      limit_distance2_(max_distance2),
      accept_(std::move(accept)) {
    PHOTON_ASSERT(!(max_distance2 < S(0)) && max_distance2 == max_distance2);
}

template <Scalar S, class Accept>
PHOTON_FORCEINLINE void KNearest<S, Accept>::visit(std::uint32_t index, S distance2) noexcept(
    noexcept(std::declval<Accept&>()(index, distance2))) {
    if constexpr (!std::is_same_v<Accept, AcceptAll>) {
        if (!accept_(index, distance2)) return;
    }
    if (count_ < k_) {
        data_[count_++] = {distance2, index};
        if (count_ == k_) {
            for (std::size_t i = k_ / 2; i-- > 0;) sift_down(i, data_[i]);
            max_distance2_ = data_[0].distance2;
        }
        return;
    }
    sift_down(0, {distance2, index});
    max_distance2_ = data_[0].distance2;
}

template <Scalar S, class Accept>
PHOTON_FORCEINLINE void KNearest<S, Accept>::sift_down(std::size_t i, Neighbor<S> n) noexcept {
    Neighbor<S>* PHOTON_RESTRICT h = data_;
    const std::size_t k = k_;
    for (std::size_t c = 2 * i + 1; c < k; c = 2 * i + 1) {
        c += c + 1 < k && h[c + 1].distance2 > h[c].distance2 ? 1 : 0;
        if (!(h[c].distance2 > n.distance2)) break;
        h[i] = h[c];
        i = c;
    }
    h[i] = n;
}

template <Scalar S, class Accept> void KNearest<S, Accept>::sort() noexcept {
    std::sort(data_, data_ + count_, [](const Neighbor<S>& a, const Neighbor<S>& b) {
        return a.distance2 < b.distance2 || (a.distance2 == b.distance2 && a.index < b.index);
    });
}

}  // namespace photon
