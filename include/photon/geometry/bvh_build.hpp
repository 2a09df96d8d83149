// SPDX-License-Identifier: MIT
#pragma once
// Bvh's build: binned SAH into a binary tree, then collapsed into wide nodes. Included at the end
// of bvh.hpp, which declares the class; the float build in SSE is in bvh_build_sse.hpp.

#include "bvh.hpp"

namespace photon {

template <Scalar S>
Bvh<S>::Bvh(std::span<const BBox<S>> boxes, std::span<const Vec3<S>> centers, BvhConfig config) {
    PHOTON_ASSERT(boxes.size() == centers.size());
    PHOTON_ASSERT(boxes.size() < std::numeric_limits<std::uint32_t>::max());
    collapse(build_binary(boxes, centers, config), std::max(1u, config.leaf_block));
}

template <Scalar S>
auto Bvh<S>::build_binary(std::span<const BBox<S>> boxes, std::span<const Vec3<S>> centers, BvhConfig config)
    -> BinaryNodes {
#if PHOTON_BVH_SSE
    // The SSE build counts in signed 32-bit lanes. Meshes and scenes pass box centres: it then
    // recomputes them instead of loading them.
    if constexpr (std::is_same_v<S, float>) {
        if (boxes.size() < (std::size_t(1) << 31)) {
            bool box_centres = true;
            for (std::size_t i = 0; i < boxes.size() && box_centres; ++i) box_centres = centers[i] == boxes[i].center();
            return box_centres ? build_binary_sse<true>(boxes, centers, config)
                               : build_binary_sse<false>(boxes, centers, config);
        }
    }
#endif
    const std::size_t n = boxes.size();
    BinaryNodes nodes;
    prim_ids_.resize(n);
    std::iota(prim_ids_.begin(), prim_ids_.end(), 0u);
    if (n == 0) return nodes;
    const unsigned bin_count = std::max(2u, config.bins);
    const unsigned max_leaf = std::max(1u, config.max_leaf_size);
    // Primitives tested together in blocks cost by the block (Embree's SAH does the same).
    const unsigned block = std::max(1u, config.leaf_block);
    const auto tests = [block](std::uint32_t count) { return S((count + block - 1) / block); };
    nodes.reserve(2 * n);
    nodes.push_back({});
    nodes[0].first = 0;
    nodes[0].count = static_cast<std::uint32_t>(n);

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
        BinaryNode& node = nodes[task.node];
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
                const S cost = acc.half_area() * tests(left_count) + right_bounds[b + 1].half_area() * tests(right_count);
                if (cost < best_cost) best_cost = cost, best_axis = axis, best_bin = b;
            }
        }

        const S leaf_cost = box.half_area() * tests(count) * S(config.intersection_cost);
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

        const auto left = static_cast<std::uint32_t>(nodes.size());
        nodes.push_back({BBox<S>{}, begin, mid - begin});
        nodes.push_back({BBox<S>{}, mid, end - mid});
        BinaryNode& parent = nodes[task.node];  // push_back may have moved the array
        parent.first = left;
        parent.count = 0;
        stack.push_back({left + 1, task.depth + 1});
        stack.push_back({left, task.depth + 1});
    }
    return nodes;
}

template <Scalar S> void Bvh<S>::collapse(const BinaryNodes& binary, unsigned leaf_block) {
    nodes_.clear();
    if (binary.empty()) return;
    // With blocks, leaves are copied in the order the collapse reaches them (depth first, as the
    // nodes), each from a multiple of leaf_block.
    std::vector<std::uint32_t> padded;
    if (leaf_block > 1) padded.reserve(prim_ids_.size() + prim_ids_.size() / 2);
    const auto place_leaf = [&](const BinaryNode& leaf) {
        if (leaf_block == 1) return leaf.first;
        padded.resize((padded.size() + leaf_block - 1) / leaf_block * leaf_block, padding);
        const auto first = static_cast<std::uint32_t>(padded.size());
        padded.insert(padded.end(), prim_ids_.begin() + leaf.first, prim_ids_.begin() + leaf.first + leaf.count);
        return first;
    };
    bounds_ = binary[0].bounds;
    // Each wide node takes a binary node's children, then repeatedly opens its largest inner
    // child (by surface area, the one rays reach most often) until it has `width`.
    nodes_.reserve(binary.size() / 3 + 1);
    nodes_.push_back({});
    std::vector<std::pair<std::uint32_t, std::uint32_t>> work{{0u, 0u}};  // (binary node, wide node)
    while (!work.empty()) {
        const auto [from, to] = work.back();
        work.pop_back();
        std::array<std::uint32_t, width> kids{};
        int n = 0;
        if (binary[from].is_leaf()) {
            kids[n++] = from;  // a root that is a leaf
        } else {
            kids[n++] = binary[from].first;
            kids[n++] = binary[from].first + 1;
            while (n < width) {
                int open = -1;
                S largest = -1;
                for (int i = 0; i < n; ++i)
                    if (!binary[kids[i]].is_leaf() && binary[kids[i]].bounds.half_area() > largest)
                        open = i, largest = binary[kids[i]].bounds.half_area();
                if (open < 0) break;
                const std::uint32_t inner = kids[open];
                kids[open] = binary[inner].first;
                kids[n++] = binary[inner].first + 1;
            }
        }
        Node node;
        for (int c = 0; c < width; ++c) {
            const BBox<S> b = c < n ? binary[kids[c]].bounds : BBox<S>{};  // unused: empty box
            for (int a = 0; a < 3; ++a) node.min[a][c] = b.min[a], node.max[a][c] = b.max[a];
            if (c >= n) continue;
            if (binary[kids[c]].is_leaf()) {
                node.first[c] = place_leaf(binary[kids[c]]);
                node.count[c] = binary[kids[c]].count;
            } else {
                node.first[c] = static_cast<std::uint32_t>(nodes_.size());
                nodes_.push_back({});
                work.push_back({kids[c], node.first[c]});
            }
        }
        nodes_[to] = node;
    }
    nodes_.shrink_to_fit();
    if (leaf_block > 1) {
        padded.resize((padded.size() + leaf_block - 1) / leaf_block * leaf_block, padding);
        prim_ids_ = std::move(padded);
    }
}

}  // namespace photon
