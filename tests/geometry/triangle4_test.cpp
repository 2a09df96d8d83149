// SPDX-License-Identifier: MIT
// The four-at-once watertight test (detail::intersect_watertight4) against the one-triangle test
// it must reproduce bit for bit, on random triangles and on rays aimed exactly at vertices and
// edges (grazing hits and the double-precision fallback); and the padded leaf layout the BVH
// builds for it (BvhConfig::leaf_block).

#include <catch2/catch.hpp>

#include <photon/geometry/bvh.hpp>
#include <photon/geometry/triangle4.hpp>
#include <photon/math/rng.hpp>

#include <algorithm>
#include <array>
#include <cstring>
#include <vector>

using namespace photon;

namespace {

template <class S> Vec3<S> random_point(Pcg32& rng) {
    return Vec3<S>(rng.uniform<S>(), rng.uniform<S>(), rng.uniform<S>()) * S(2) - S(1);
}

template <class S> bool same_bits(S a, S b) { return std::memcmp(&a, &b, sizeof(S)) == 0; }

}  // namespace

TEMPLATE_TEST_CASE("four triangles at once give the one-triangle test's hits and distances bit for bit",
                   "[geometry][mesh]", float, double) {
    using S = TestType;
    Pcg32 rng(11, 3);
    std::size_t hits = 0, edge_rays = 0;
    for (int round = 0; round < 3000; ++round) {
        std::array<std::array<Vec3<S>, 3>, 4> tri;
        detail::Triangle4<S> block;
        const unsigned count = 1 + unsigned(round % 4);
        for (unsigned lane = 0; lane < count; ++lane) {
            for (auto& v : tri[lane]) v = random_point<S>(rng);
            // Neighbours sharing an edge with lane 0, and some axis-aligned triangles whose edge
            // functions come out exactly zero for axis-aligned rays.
            if (lane == 1 && round % 2 == 0) tri[1][0] = tri[0][1], tri[1][1] = tri[0][0];
            if (lane == 2 && round % 5 == 0) tri[2] = {Vec3<S>(0, 0, 1), Vec3<S>(1, 0, 1), Vec3<S>(0, 1, 1)};
            block.set(int(lane), tri[lane][0], tri[lane][1], tri[lane][2]);
        }
        Ray<S> ray{random_point<S>(rng) * S(2), {}};
        switch (round % 4) {
        case 0: ray.direction = random_point<S>(rng); break;  // anywhere
        case 1: ray.direction = tri[0][round % 3] - ray.origin; ++edge_rays; break;  // at a vertex
        case 2: ray.direction = (tri[0][0] + tri[0][1]) * S(0.5) - ray.origin; ++edge_rays; break;  // at an edge
        default: ray = {{S(0.25), S(0), S(-1)}, {0, 0, 1}}; break;  // along z through an axis-aligned edge
        }
        if (round % 3 == 0) ray.t_max = S(0.5) + rng.uniform<S>();
        const detail::WatertightRay<S> prepared(ray);
        detail::with_shear_axis(prepared, [&](auto kz) {
            std::array<S, 4> t{};
            const unsigned mask = detail::intersect_watertight4<kz()>(prepared, ray.t_max, block, count, t);
            for (unsigned lane = 0; lane < 4; ++lane) {
                INFO("round " << round << " lane " << lane);
                const auto one = lane < count ? detail::intersect_watertight<kz()>(prepared, ray.t_max, tri[lane][0],
                                                                                   tri[lane][1], tri[lane][2])
                                              : std::nullopt;
                REQUIRE(bool(mask & (1u << lane)) == one.has_value());
                if (one) {
                    CHECK(same_bits(t[lane], *one));
                    ++hits;
                }
            }
        });
    }
    CHECK(edge_rays == 1500);
    CHECK(hits > 1000);  // both outcomes are exercised
}

TEST_CASE("leaf blocks start every leaf at a multiple of the block and keep each primitive once", "[geometry][mesh]") {
    Pcg32 rng(5, 9);
    std::vector<BBox<float>> boxes;
    std::vector<Vec3<float>> centers;
    for (int i = 0; i < 3001; ++i) {
        const Vec3<float> c = random_point<float>(rng);
        boxes.push_back(BBox<float>::of_point(c - 0.01f).extend(c + 0.01f));
        centers.push_back(c);
    }
    for (unsigned block : {1u, 4u}) {
        const Bvh<float> bvh(boxes, centers, {.max_leaf_size = 8, .intersection_cost = 2.0f, .leaf_block = block});
        std::vector<int> seen(boxes.size(), 0);
        std::size_t leaves = 0;
        for (const auto& node : bvh.nodes())
            for (int c = 0; c < Bvh<float>::width; ++c) {
                if (node.count[c] == 0) continue;
                ++leaves;
                CHECK(node.first[c] % block == 0);
                for (std::uint32_t i = node.first[c]; i < node.first[c] + node.count[c]; ++i) {
                    REQUIRE(bvh.primitive_indices()[i] != Bvh<float>::padding);
                    ++seen[bvh.primitive_indices()[i]];
                }
            }
        CHECK(std::all_of(seen.begin(), seen.end(), [](int n) { return n == 1; }));
        CHECK(bvh.primitive_indices().size() % block == 0);
        const auto padded = std::count(bvh.primitive_indices().begin(), bvh.primitive_indices().end(), Bvh<float>::padding);
        CHECK(std::size_t(padded) == bvh.primitive_indices().size() - boxes.size());
        if (block == 1) CHECK(padded == 0);
        CHECK(leaves > 100);
    }
}
