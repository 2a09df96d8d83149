// SPDX-License-Identifier: MIT
#pragma once
// Bvh's binary build for float in SSE, Embree's way (see build_binary_sse below). Included at the
// end of bvh.hpp, which declares the class; the scalar build and the collapse are in bvh_build.hpp.

#include "bvh.hpp"

namespace photon {

#if PHOTON_BVH_SSE
namespace detail {

/// A primitive of the float build, as Embree's PrimRef: its box in two SSE registers, its id in
/// the fourth lane of `hi`. The build partitions these in place, so that binning reads them in order.
struct alignas(16) SsePrim {
    __m128 lo, hi;
    SsePrim() noexcept {}  // uninitialised, so that a vector of them is sized without writing it
    SsePrim(__m128 l, __m128 h) noexcept : lo(l), hi(h) {}
    [[nodiscard]] std::uint32_t id() const noexcept {
        return static_cast<std::uint32_t>(_mm_cvtsi128_si32(_mm_shuffle_epi32(_mm_castps_si128(hi), 0xff)));
    }
};

/// A box (or a centroid box) in two SSE registers; lane 3 is ignored.
struct SseBox {
    __m128 lo = _mm_set1_ps(std::numeric_limits<float>::infinity());
    __m128 hi = _mm_set1_ps(-std::numeric_limits<float>::infinity());
    // Ties keep the old value, as glm::min/max (BBox::extend) do, for the same sign of zero.
    PHOTON_FORCEINLINE void extend(__m128 l, __m128 h) noexcept { lo = _mm_min_ps(l, lo), hi = _mm_max_ps(h, hi); }
    [[nodiscard]] BBox<float> bbox() const noexcept {
        alignas(16) float l[4], h[4];
        _mm_store_ps(l, lo), _mm_store_ps(h, hi);
        return {{l[0], l[1], l[2]}, {h[0], h[1], h[2]}};
    }
};

struct SseLanes {
    __m128 v;  // in a struct, as std::vector<__m128> drops the type's alignment attribute
};

/// BBox::half_area of three boxes at once, one in each lane, with the same operations in the same order.
PHOTON_FORCEINLINE __m128 half_areas(const SseBox& a, const SseBox& b, const SseBox& c) noexcept {
    __m128 x = _mm_max_ps(_mm_sub_ps(a.hi, a.lo), _mm_setzero_ps());
    __m128 y = _mm_max_ps(_mm_sub_ps(b.hi, b.lo), _mm_setzero_ps());
    __m128 z = _mm_max_ps(_mm_sub_ps(c.hi, c.lo), _mm_setzero_ps());
    __m128 w = _mm_setzero_ps();
    _MM_TRANSPOSE4_PS(x, y, z, w);  // now x holds the three boxes' x extents, and so on
    return _mm_add_ps(_mm_add_ps(_mm_mul_ps(x, y), _mm_mul_ps(y, z)), _mm_mul_ps(z, x));
}

}  // namespace detail

// Wald (2007) as Embree does it: one pass per node bins all three axes at once, with one SSE
// multiply for the three bin indices and SSE min/max into the bins; the partition then yields the
// children's boxes and centroid boxes, so no node needs a pass of its own for them. The bin index,
// the SAH costs and std::partition's order of swaps are the scalar build's, so the tree is the same.
template <Scalar S>
template <bool BoxCentres>
auto Bvh<S>::build_binary_sse(std::span<const BBox<S>> boxes, std::span<const Vec3<S>> centers, BvhConfig config)
    -> BinaryNodes {
    using detail::SseBox, detail::SsePrim;
    const std::size_t n = boxes.size();
    BinaryNodes nodes(n, config.threads);
    prim_ids_.resize(n);
    if (n == 0) return nodes;
    const unsigned bin_count = std::max(2u, config.bins);
    const unsigned max_leaf = std::max(1u, config.max_leaf_size);
    const unsigned block = std::max(1u, config.leaf_block);
    // tests() of the scalar build, with a shift for the usual power-of-two blocks.
    const int block_shift = std::has_single_bit(block) ? std::countr_zero(block) : -1;
    const auto tests = [block, block_shift](std::uint32_t count) {
        return S(block_shift >= 0 ? (count + block - 1) >> block_shift : (count + block - 1) / block);
    };
    const __m128 xyz = _mm_castsi128_ps(_mm_setr_epi32(-1, -1, -1, 0));
    // 32 bytes a primitive, written once and read at every level: huge pages spare page faults
    // and TLB misses.
    std::vector<SsePrim, HugePageAllocator<SsePrim>> prims;
    const auto make_prim = [boxes](std::uint32_t id) {
        const BBox<S>& b = boxes[id];
        return SsePrim{_mm_setr_ps(b.min.x, b.min.y, b.min.z, 0.0f),
                       _mm_setr_ps(b.max.x, b.max.y, b.max.z, std::bit_cast<float>(id))};
    };
    // BBox::center's operations; lane 3 (the id) is masked so that it never meets arithmetic.
    const auto centre = [=](const SsePrim& p) {  // copies: xyz, or centers
        if constexpr (BoxCentres) {
            return _mm_mul_ps(_mm_add_ps(p.lo, _mm_and_ps(p.hi, xyz)), _mm_set1_ps(0.5f));
        } else {
            const Vec3<S>& c = centers[p.id()];
            return _mm_setr_ps(c.x, c.y, c.z, 0.0f);
        }
    };
    const auto range_bounds = [&](std::uint32_t begin, std::uint32_t end, SseBox& box, SseBox& cbox) {
        for (std::uint32_t i = begin; i < end; ++i) {
            box.extend(prims[i].lo, prims[i].hi);
            const __m128 c = centre(prims[i]);
            cbox.extend(c, c);
        }
    };
    // Made and bounded in parallel, in fixed chunks merged in order: the bounds are the serial
    // loop's, as a tie keeps the earlier value.
    constexpr std::size_t grain = 1 << 14;
    prims.resize(n);
    std::vector<std::array<SseBox, 2>> chunk_bounds((n + grain - 1) / grain);
    parallel_for(n, grain, config.threads, [&](std::size_t first, std::size_t last) {
        for (std::size_t i = first; i < last; ++i) prims[i] = make_prim(static_cast<std::uint32_t>(i));
        auto& [box, cbox] = chunk_bounds[first / grain];
        range_bounds(static_cast<std::uint32_t>(first), static_cast<std::uint32_t>(last), box, cbox);
    });
    SseBox root_box, root_cbox;
    for (const auto& [box, cbox] : chunk_bounds) root_box.extend(box.lo, box.hi), root_cbox.extend(cbox.lo, cbox.hi);
    nodes.data()[0] = {root_box.bbox(), 0, static_cast<std::uint32_t>(n)};
    nodes.count = 1;

    struct Task {
        std::uint32_t node, depth;
        SseBox centroids;
    };
    const __m128i round_up = _mm_set1_epi32(static_cast<int>(block - 1));
    const __m128i shift = _mm_cvtsi32_si128(std::max(block_shift, 0));
    const auto tests4 = [=](__m128i counts) {
        if (block_shift >= 0) return _mm_cvtepi32_ps(_mm_srl_epi32(_mm_add_epi32(counts, round_up), shift));
        alignas(16) std::uint32_t c[4];
        _mm_store_si128(reinterpret_cast<__m128i*>(c), counts);
        return _mm_setr_ps(tests(c[0]), tests(c[1]), tests(c[2]), tests(c[3]));
    };

    // bins[3 * b + axis]; bin_counts[4 * b + axis], so that a bin's three counts load together;
    // each twice, for the even and odd primitives of large nodes.
    const auto make_split = [&] {
        return [&, bins = std::vector<SseBox>(2 * 3 * bin_count), bin_counts = std::vector<std::uint32_t>(2 * 4 * bin_count),
                right_area = std::vector<detail::SseLanes>(bin_count)](NodeRegion& tree, const Task& task,
                                                                       std::vector<Task>& stack) mutable {
            // Copies of the enclosing function's values, held here rather than reached through
            // the closure: SSE stores may alias anything, so the compiler would reload those
            // in every inner loop, slower (bench/README.md).
            const auto centre_of = centre;
            SseBox* const box_bins = bins.data();
            std::uint32_t* const count_bins = bin_counts.data();
            detail::SseLanes* const right_areas = right_area.data();
            const auto tests4_of = tests4;
            SsePrim* const prim = prims.data();
            const BinaryNode node = tree[task.node];
            const std::uint32_t begin = node.first, count = node.count, end = begin + count;
            if (count <= 1) return;
            const unsigned bins_per_axis = node_bins(count, bin_count);
            const __m128 max_bin = _mm_set1_ps(float(bins_per_axis - 1));
            const BBox<S> box = node.bounds, centroid_box = task.centroids.bbox();
            const Vec3<S> extent = centroid_box.extent();
            const S leaf_cost = box.half_area() * tests(count) * S(config.intersection_cost);
            // A split costs at least the box's area (plus non-negative child costs), so a node that
            // may be a leaf and costs no more than that as one stays a leaf: the scalar build's
            // choice, without binning (with the defaults, every node of up to four primitives).
            if (count <= max_leaf && !(box.half_area() < leaf_cost)) return;

            // Bin indices as the scalar build's: (c - min) * (bins / extent), truncated, at most the
            // last bin; axes without extent get scale 0 (bin 0) and are skipped below.
            const __m128 cmin = task.centroids.lo;
            const __m128 ext = _mm_sub_ps(task.centroids.hi, cmin);
            const __m128 scale = _mm_and_ps(_mm_and_ps(_mm_div_ps(_mm_set1_ps(float(bins_per_axis)), ext),
                                                       _mm_cmpgt_ps(ext, _mm_setzero_ps())), xyz);
            const auto bin_position = [&](__m128 c) {
                // max(.., 0) also turns NaN into bin 0.
                return _mm_max_ps(_mm_mul_ps(_mm_sub_ps(c, cmin), scale), _mm_setzero_ps());
            };
            // Large nodes bin even and odd primitives into two sets of bins, to halve the chains of
            // loads and stores through one bin that neighbouring (so mostly same-bin) primitives
            // make. A bin's box only feeds areas, so the order of merging does not matter.
            const bool two_sets = count >= 256;
            std::fill_n(box_bins, (two_sets ? 2 : 1) * 3 * bins_per_axis, SseBox{});
            std::fill_n(count_bins, (two_sets ? 2 : 1) * 4 * bins_per_axis, 0u);
            const auto bin_prim = [&](const SsePrim& p, SseBox* to, std::uint32_t* counts) PHOTON_FORCEINLINE_LAMBDA {
                const __m128i b = _mm_cvttps_epi32(_mm_min_ps(bin_position(centre_of(p)), max_bin));
                const auto b0 = static_cast<unsigned>(_mm_cvtsi128_si32(b));
                const auto b1 = static_cast<unsigned>(_mm_cvtsi128_si32(_mm_shuffle_epi32(b, 1)));
                const auto b2 = static_cast<unsigned>(_mm_cvtsi128_si32(_mm_shuffle_epi32(b, 2)));
                to[3 * b0].extend(p.lo, p.hi), ++counts[4 * b0];
                to[3 * b1 + 1].extend(p.lo, p.hi), ++counts[4 * b1 + 1];
                to[3 * b2 + 2].extend(p.lo, p.hi), ++counts[4 * b2 + 2];
            };
            SseBox* const odd_bins = box_bins + 3 * bins_per_axis;
            std::uint32_t* const odd_counts = count_bins + 4 * bins_per_axis;
            std::uint32_t next = begin;
            for (; two_sets && next + 1 < end; next += 2) {
                bin_prim(prim[next], box_bins, count_bins);
                bin_prim(prim[next + 1], odd_bins, odd_counts);
            }
            for (; next < end; ++next) bin_prim(prim[next], box_bins, count_bins);
            if (two_sets) {
                for (unsigned b = 0; b < 3 * bins_per_axis; ++b) box_bins[b].extend(odd_bins[b].lo, odd_bins[b].hi);
                for (unsigned b = 0; b < 4 * bins_per_axis; ++b) count_bins[b] += odd_counts[b];
            }

            // The scalar build's sweep with the three axes in the lanes: the same areas, counts and
            // costs; per lane the first bin of least cost, then the first axis of least cost, which
            // is the scalar build's choice (strict <, axes then bins in order).
            const SseBox* bin = box_bins;
            const auto counts_of = [&](unsigned b) {
                return _mm_loadu_si128(reinterpret_cast<const __m128i*>(count_bins + 4 * b));
            };
            SseBox r0, r1, r2;
            for (unsigned b = bins_per_axis - 1; b > 0; --b) {
                r0.extend(bin[3 * b].lo, bin[3 * b].hi);
                r1.extend(bin[3 * b + 1].lo, bin[3 * b + 1].hi);
                r2.extend(bin[3 * b + 2].lo, bin[3 * b + 2].hi);
                right_areas[b].v = detail::half_areas(r0, r1, r2);
            }
            const __m128 inf = _mm_set1_ps(std::numeric_limits<float>::infinity());
            const __m128 axis_valid = _mm_cmpgt_ps(_mm_and_ps(ext, xyz), _mm_setzero_ps());
            const __m128i all = _mm_set1_epi32(static_cast<int>(count)), zero = _mm_setzero_si128();
            SseBox l0, l1, l2;
            __m128i left_count = zero, best_bins = zero;
            __m128 best_costs = inf;
            for (unsigned b = 0; b + 1 < bins_per_axis; ++b) {
                l0.extend(bin[3 * b].lo, bin[3 * b].hi);
                l1.extend(bin[3 * b + 1].lo, bin[3 * b + 1].hi);
                l2.extend(bin[3 * b + 2].lo, bin[3 * b + 2].hi);
                left_count = _mm_add_epi32(left_count, counts_of(b));
                const __m128i right_count = _mm_sub_epi32(all, left_count);
                const __m128 cost = _mm_add_ps(_mm_mul_ps(detail::half_areas(l0, l1, l2), tests4_of(left_count)),
                                               _mm_mul_ps(right_areas[b + 1].v, tests4_of(right_count)));
                const __m128 empty_side = _mm_castsi128_ps(
                    _mm_or_si128(_mm_cmpeq_epi32(left_count, zero), _mm_cmpeq_epi32(right_count, zero)));
                const __m128 valid = _mm_andnot_ps(empty_side, axis_valid);
                const __m128 better = _mm_cmplt_ps(_mm_or_ps(_mm_and_ps(valid, cost), _mm_andnot_ps(valid, inf)), best_costs);
                best_costs = _mm_or_ps(_mm_and_ps(better, cost), _mm_andnot_ps(better, best_costs));
                best_bins = _mm_or_si128(_mm_and_si128(_mm_castps_si128(better), _mm_set1_epi32(static_cast<int>(b))),
                                         _mm_andnot_si128(_mm_castps_si128(better), best_bins));
            }
            S best_cost = std::numeric_limits<S>::infinity();
            int best_axis = -1;
            unsigned best_bin = 0;
            alignas(16) float axis_costs[4];
            alignas(16) std::int32_t axis_bins[4];
            _mm_store_ps(axis_costs, best_costs);
            _mm_store_si128(reinterpret_cast<__m128i*>(axis_bins), best_bins);
            for (int axis = 0; axis < 3; ++axis)
                if (axis_costs[axis] < best_cost)
                    best_cost = axis_costs[axis], best_axis = axis, best_bin = static_cast<unsigned>(axis_bins[axis]);

            const S split_cost = box.half_area() + best_cost * S(config.intersection_cost);
            std::uint32_t mid;
            SseBox left_box, left_cbox, right_box, right_cbox;
            if (task.depth >= forced_median_depth && count > max_leaf) {
                // As the scalar build: nth_element on the ids in their current order.
                const int axis = max_dimension(extent);
                mid = begin + count / 2;
                std::vector<std::uint32_t> ids(count);
                for (std::uint32_t i = 0; i < count; ++i) ids[i] = prim[begin + i].id();
                std::nth_element(ids.begin(), ids.begin() + count / 2, ids.end(),
                                 [&](std::uint32_t a, std::uint32_t b) {
                                     if constexpr (BoxCentres) return boxes[a].center()[axis] < boxes[b].center()[axis];
                                     else return centers[a][axis] < centers[b][axis];
                                 });
                for (std::uint32_t i = 0; i < count; ++i) prim[begin + i] = make_prim(ids[i]);
                range_bounds(begin, mid, left_box, left_cbox);
                range_bounds(mid, end, right_box, right_cbox);
            } else if (best_axis >= 0 && (split_cost < leaf_cost || count > max_leaf)) {
                // std::partition's swaps (libstdc++, bidirectional), so that the leaves' order is the
                // scalar build's too; every primitive is classified once and extends its side's boxes.
                const float split = float(best_bin + 1);  // bin <= best_bin exactly when position < best_bin + 1
                const int bit = 1 << best_axis;
                SsePrim* first = prim + begin;
                SsePrim* last = prim + end;
                const auto goes_left = [&](__m128 c) {
                    return (_mm_movemask_ps(_mm_cmplt_ps(bin_position(c), _mm_set1_ps(split))) & bit) != 0;
                };
                for (;;) {
                    for (;;) {
                        if (first == last) goto partitioned;
                        const __m128 c = centre_of(*first);
                        if (!goes_left(c)) {
                            right_box.extend(first->lo, first->hi), right_cbox.extend(c, c);
                            break;
                        }
                        left_box.extend(first->lo, first->hi), left_cbox.extend(c, c);
                        ++first;
                    }
                    --last;
                    for (;;) {
                        if (first == last) goto partitioned;
                        const __m128 c = centre_of(*last);
                        if (goes_left(c)) {
                            left_box.extend(last->lo, last->hi), left_cbox.extend(c, c);
                            break;
                        }
                        right_box.extend(last->lo, last->hi), right_cbox.extend(c, c);
                        --last;
                    }
                    std::swap(*first, *last);
                    ++first;
                }
            partitioned:
                mid = static_cast<std::uint32_t>(first - prim);
            } else if (count > max_leaf && best_axis < 0) {
                // All centres coincide: halves, as the scalar build.
                mid = begin + count / 2;
                range_bounds(begin, mid, left_box, left_cbox);
                range_bounds(mid, end, right_box, right_cbox);
            } else {
                return;  // stays a leaf
            }

            const auto left = static_cast<std::uint32_t>(tree.size());
            tree.push_back({left_box.bbox(), begin, mid - begin});
            tree.push_back({right_box.bbox(), mid, end - mid});
            tree[task.node].first = left;
            tree[task.node].count = 0;
            stack.push_back({left + 1, task.depth + 1, right_cbox});
            stack.push_back({left, task.depth + 1, left_cbox});
        };
    };
    run_splits(nodes, Task{0, 1, root_cbox}, config.threads, make_split);
    for (std::size_t i = 0; i < n; ++i) prim_ids_[i] = prims[i].id();
    return nodes;
}
#endif

}  // namespace photon
