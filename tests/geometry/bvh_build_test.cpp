// SPDX-License-Identifier: MIT
// The BVH build on several threads: subtrees are built as independent tasks and spliced, and the
// tree must be the one-thread tree, node for node and leaf for leaf, for any thread count.

#include <catch2/catch.hpp>

#include <photon/geometry/bvh.hpp>
#include <photon/math/rng.hpp>

#include <cstring>
#include <vector>

using namespace photon;

namespace {

template <class S> bool same_nodes(const Bvh<S>& a, const Bvh<S>& b) {
    if (a.nodes().size() != b.nodes().size()) return false;
    for (std::size_t i = 0; i < a.nodes().size(); ++i) {
        const auto &x = a.nodes()[i], &y = b.nodes()[i];
        // Bytes, not values: the same signs of zero and the same unused slots too.
        if (std::memcmp(&x.min, &y.min, sizeof x.min) != 0 || std::memcmp(&x.max, &y.max, sizeof x.max) != 0 ||
            x.first != y.first || x.count != y.count)
            return false;
    }
    return true;
}

}  // namespace

// Large enough (40,000 boxes) that builds on two or more threads hand out subtrees; clusters of
// coincident centres and flat boxes give the build's special splits a part in the subtrees too.
TEMPLATE_TEST_CASE("BVH built on 2, 3 or 5 threads is the one-thread tree", "[geometry][bvh]", float, double) {
    using S = TestType;
    Pcg32 rng(11, 0);
    std::vector<BBox<S>> boxes;
    std::vector<Vec3<S>> centres, points;
    for (int i = 0; i < 40000; ++i) {
        Vec3<S> lo{rng.uniform<S>() * 50, rng.uniform<S>() * 50, rng.uniform<S>() * 5};
        if (i % 97 < 12) lo = Vec3<S>(S(7), S(3), S(1));  // coincident boxes
        const Vec3<S> size{rng.uniform<S>(), i % 4 == 0 ? S(0) : rng.uniform<S>(), rng.uniform<S>() * 2};
        boxes.push_back({lo, lo + size});
        centres.push_back(boxes.back().center());
        points.push_back(lo + size * Vec3<S>{rng.uniform<S>(), rng.uniform<S>(), rng.uniform<S>()});
    }
    const bool box_centres = GENERATE(true, false);  // the float build's two variants
    const unsigned block = GENERATE(1u, 4u);
    const auto& at = box_centres ? centres : points;
    BvhConfig config{.leaf_block = block, .threads = 1};
    const Bvh<S> one(boxes, at, config);
    REQUIRE(one.depth() > 10);
    for (const unsigned threads : {2u, 3u, 5u}) {
        config.threads = threads;
        const Bvh<S> many(boxes, at, config);
        INFO("threads " << threads << ", leaf block " << block << ", box centres " << box_centres);
        CHECK(same_nodes(one, many));
        CHECK(std::equal(one.primitive_indices().begin(), one.primitive_indices().end(),
                         many.primitive_indices().begin(), many.primitive_indices().end()));
        CHECK(one.depth() == many.depth());
        const BBox<S> a = one.bounds(), b = many.bounds();
        CHECK(std::memcmp(&a, &b, sizeof a) == 0);
    }
}
