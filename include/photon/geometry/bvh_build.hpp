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

template <Scalar S> Bvh<S>::Bvh(std::span<const BBox<S>> boxes, BvhConfig config) {
    PHOTON_ASSERT(boxes.size() < std::numeric_limits<std::uint32_t>::max());
    collapse(build_binary(boxes, {}, config), std::max(1u, config.leaf_block));
}

// No `centers`: the boxes' centres.
template <Scalar S>
auto Bvh<S>::build_binary(std::span<const BBox<S>> boxes, std::span<const Vec3<S>> centers, BvhConfig config)
    -> BinaryNodes {
#if PHOTON_BVH_SSE
    // The SSE build counts in signed 32-bit lanes. With box centres it recomputes them instead of
    // loading them.
    if constexpr (std::is_same_v<S, float>) {
        if (boxes.size() < (std::size_t(1) << 31)) {
            bool box_centres = true;
            for (std::size_t i = 0; i < centers.size() && box_centres; ++i) box_centres = centers[i] == boxes[i].center();
            return box_centres ? build_binary_sse<true>(boxes, {}, config) : build_binary_sse<false>(boxes, centers, config);
        }
    }
#endif
    std::vector<Vec3<S>> box_centres;
    if (centers.empty()) {
        box_centres.reserve(boxes.size());
        for (const BBox<S>& b : boxes) box_centres.push_back(b.center());
        centers = box_centres;
    }
    const std::size_t n = boxes.size();
    BinaryNodes nodes(n, config.threads);
    prim_ids_.resize(n);
    std::iota(prim_ids_.begin(), prim_ids_.end(), 0u);
    if (n == 0) return nodes;
    const unsigned bin_count = std::max(2u, config.bins);
    const unsigned max_leaf = std::max(1u, config.max_leaf_size);
    // Primitives tested together in blocks cost by the block (Embree's SAH does the same).
    const unsigned block = std::max(1u, config.leaf_block);
    const auto tests = [block](std::uint32_t count) { return S((count + block - 1) / block); };
    nodes.data()[0] = {BBox<S>{}, 0, static_cast<std::uint32_t>(n)};
    nodes.count = 1;

    struct Task {
        std::uint32_t node, depth;
    };
    const auto make_split = [&] {
        return [&, bins = std::vector<Bin>(bin_count), right_bounds = std::vector<BBox<S>>(bin_count)](
                   NodeRegion& tree, const Task& task, std::vector<Task>& stack) mutable {
            BinaryNode& node = tree[task.node];
            const std::uint32_t begin = node.first, count = node.count, end = begin + count;

            BBox<S> box, centroid_box;
            for (std::uint32_t i = begin; i < end; ++i) {
                box.extend(boxes[prim_ids_[i]]);
                centroid_box.extend(centers[prim_ids_[i]]);
            }
            node.bounds = box;
            if (count <= 1) return;
            const unsigned bins_per_axis = node_bins(count, bin_count);

            // Best SAH split over all axes; cost relative to node visits (a constant factor of the
            // parent's area cancels, so costs are compared as area-weighted primitive counts).
            S best_cost = std::numeric_limits<S>::infinity();
            int best_axis = -1;
            unsigned best_bin = 0;
            const Vec3<S> extent = centroid_box.extent();
            for (int axis = 0; axis < 3; ++axis) {
                if (!(extent[axis] > S(0))) continue;
                const S scale = S(bins_per_axis) / extent[axis];
                std::fill_n(bins.begin(), bins_per_axis, Bin{});
                for (std::uint32_t i = begin; i < end; ++i) {
                    const std::uint32_t id = prim_ids_[i];
                    const auto b = std::min(bins_per_axis - 1,
                                            static_cast<unsigned>((centers[id][axis] - centroid_box.min[axis]) * scale));
                    bins[b].bounds.extend(boxes[id]);
                    ++bins[b].count;
                }
                BBox<S> acc;
                for (unsigned b = bins_per_axis - 1; b > 0; --b) {
                    acc.extend(bins[b].bounds);
                    right_bounds[b] = acc;
                }
                acc = {};
                std::uint32_t left_count = 0;
                for (unsigned b = 0; b + 1 < bins_per_axis; ++b) {
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
                const S scale = S(bins_per_axis) / extent[best_axis];
                const auto it = std::partition(prim_ids_.begin() + begin, prim_ids_.begin() + end, [&](std::uint32_t id) {
                    const auto b = std::min(bins_per_axis - 1, static_cast<unsigned>((centers[id][best_axis] -
                                                                                  centroid_box.min[best_axis]) * scale));
                    return b <= best_bin;
                });
                mid = static_cast<std::uint32_t>(it - prim_ids_.begin());
            } else if (count > max_leaf && best_axis < 0) {
                // All centres coincide: no plane separates them, so split the list in halves to keep
                // leaves small and the depth logarithmic.
                mid = begin + count / 2;
            } else {
                return;  // stays a leaf
            }

            const auto left = static_cast<std::uint32_t>(tree.size());
            tree.push_back({BBox<S>{}, begin, mid - begin});
            tree.push_back({BBox<S>{}, mid, end - mid});
            BinaryNode& parent = tree[task.node];  // push_back may have moved the array
            parent.first = left;
            parent.count = 0;
            stack.push_back({left + 1, task.depth + 1});
            stack.push_back({left, task.depth + 1});
        };
    };
    run_splits(nodes, Task{0, 1}, config.threads, make_split);
    return nodes;
}

// Splits run on `threads` threads in two phases. First the top of the tree, level by level: the
// nodes of a level that hold at least `cutoff` primitives are split once each, in parallel, and
// nodes below it wait. Then each waiting node's whole subtree is one task, largest first, written
// in place into a region of its own (a subtree of c primitives has at most 2c - 1 nodes). A split
// reads and reorders only its node's primitives and depends on nothing else, so the tree is the
// same for any thread count (only the binary nodes' numbering differs, which the collapse
// ignores).
template <Scalar S>
template <class Task, class MakeSplit>
void Bvh<S>::run_splits(BinaryNodes& nodes, Task root, unsigned threads, MakeSplit make_split) {
    const std::uint32_t n = nodes[0].count;
    const unsigned workers = resolve_threads(threads);
    // Splits until the tree below `tree[task.node]` is done, or once when `once`; returns the
    // depth reached and leaves the split node's children on `stack`.
    const auto run = [](NodeRegion& tree, std::vector<Task>& stack, auto& split, bool once) {
        std::size_t depth = 0;
        while (!stack.empty()) {
            const Task task = stack.back();
            stack.pop_back();
            depth = std::max<std::size_t>(depth, task.depth);
            split(tree, task, stack);
            if (once) break;
        }
        return depth;
    };
    NodeRegion top{nodes.data(), 1};  // the root; room for 2n nodes
    if (!parallel_build(n, threads)) {
        auto split = make_split();
        std::vector<Task> stack{root};
        depth_ = run(top, stack, split, false);
        nodes.count = top.used;
        return;
    }
    // A task writes a copy of its node and the nodes below it into `region`, numbered from 0,
    // leaving the children of its last split on `stack`; `place` then numbers them from `offset`
    // and puts the copy in the node's place.
    const auto split_in = [&](NodeRegion& region, Task task, std::vector<Task>& stack, bool once) {
        region.push_back(top[task.node]);
        task.node = 0;
        stack = {task};
        auto split = make_split();
        return run(region, stack, split, once);
    };
    const auto place = [&](std::uint32_t at, NodeRegion region, std::uint32_t offset) {
        for (std::uint32_t k = 0; k < region.used; ++k)
            if (!region[k].is_leaf()) region[k].first += offset;
        top[at] = region[0];
    };

    // About sixteen subtrees per thread, so that the largest-first order balances the threads, of
    // at least 4,096 primitives, so that a task is worth handing out.
    const std::uint32_t cutoff = std::max<std::uint32_t>(4096, n / (16 * workers));
    depth_ = 0;
    std::vector<Task> level{root}, subtrees;
    while (!level.empty()) {
        std::vector<Task> large;
        for (const Task& task : level) (top[task.node].count < cutoff ? subtrees : large).push_back(task);
        struct Split {
            std::array<BinaryNode, 3> tree;  // the node and its two children
            std::uint32_t used = 0;
            std::vector<Task> children;
        };
        std::vector<Split> done(large.size());
        parallel_for(large.size(), 1, workers, [&](std::size_t first, std::size_t last) {
            for (std::size_t i = first; i < last; ++i) {
                NodeRegion region{done[i].tree.data(), 0};
                split_in(region, large[i], done[i].children, true);
                done[i].used = region.used;
            }
        });
        level.clear();
        for (std::size_t i = 0; i < large.size(); ++i) {
            depth_ = std::max<std::size_t>(depth_, large[i].depth);
            const std::uint32_t offset = top.used - 1;  // children 1 and 2 go to top.used and on
            NodeRegion region{done[i].tree.data(), done[i].used};
            for (std::uint32_t k = 1; k < region.used; ++k) top.push_back(region[k]);
            place(large[i].node, region, offset);
            for (auto child = done[i].children.rbegin(); child != done[i].children.rend(); ++child)
                level.push_back(*child), level.back().node += offset;
        }
    }
    std::vector<std::uint32_t> offsets(subtrees.size());
    std::size_t end = 2 * std::size_t(n);
    for (std::size_t i = 0; i < subtrees.size(); ++i) {
        offsets[i] = static_cast<std::uint32_t>(end);
        end += 2 * std::size_t(top[subtrees[i].node].count) - 1;
    }
    std::vector<std::size_t> order(subtrees.size()), depths(subtrees.size());
    std::vector<std::uint32_t> used(subtrees.size());
    std::iota(order.begin(), order.end(), std::size_t(0));
    std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
        return top[subtrees[a].node].count > top[subtrees[b].node].count;
    });
    parallel_for(subtrees.size(), 1, workers, [&](std::size_t first, std::size_t last) {
        for (std::size_t k = first; k < last; ++k) {
            const std::size_t i = order[k];
            NodeRegion region{nodes.data() + offsets[i], 0};
            std::vector<Task> stack;
            depths[i] = split_in(region, subtrees[i], stack, false);
            used[i] = region.used;
            place(subtrees[i].node, region, offsets[i]);  // writes only this task's node of the top
        }
    });
    nodes.count = top.used;
    for (std::size_t i = 0; i < subtrees.size(); ++i) {
        depth_ = std::max(depth_, depths[i]);
        nodes.count += used[i] - 1;
    }
}

template <Scalar S> void Bvh<S>::collapse(const BinaryNodes& binary, unsigned leaf_block) {
    nodes_.clear();
    if (binary.count == 0) return;
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
    nodes_.reserve(binary.count / 3 + 1);
    nodes_.push_back({});
    std::vector<std::pair<std::uint32_t, std::uint32_t>> work{{0u, 0u}};  // (binary node, wide node)
    while (!work.empty()) {
        const auto [from, to] = work.back();
        work.pop_back();
        std::array<std::uint32_t, width> kids{};
        std::array<S, width> area{};  // of an inner kid, -1 for a leaf: each computed once
        const auto set_kid = [&](int at, std::uint32_t kid) {
            kids[at] = kid;
            area[at] = binary[kid].is_leaf() ? S(-1) : binary[kid].bounds.half_area();
        };
        int n = 0;
        if (binary[from].is_leaf()) {
            kids[n++] = from;  // a root that is a leaf
        } else {
            set_kid(n++, binary[from].first);
            set_kid(n++, binary[from].first + 1);
            while (n < width) {
                int open = -1;
                S largest = -1;
                for (int i = 0; i < n; ++i)
                    if (area[i] > largest) open = i, largest = area[i];
                if (open < 0) break;
                const std::uint32_t inner = kids[open];
                set_kid(open, binary[inner].first);
                set_kid(n++, binary[inner].first + 1);
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
