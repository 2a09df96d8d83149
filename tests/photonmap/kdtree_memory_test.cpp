// SPDX-License-Identifier: MIT
// The photon map's memory budget: KdTree<Photon> holds at most 24 bytes per photon, tree included
// (positions 12 + PackedPhoton 8 + nodes and padding). A size property, not a timing.

#include <catch2/catch.hpp>

#include <span>
#include <vector>

#include "photon/math/rng.hpp"
#include "photon/photonmap/kdtree.hpp"
#include "photon/photonmap/photon.hpp"

TEST_CASE("KdTree<Photon> stores at most 24 bytes per photon", "[kdtree][memory]") {
    photon::Pcg32 rng(24, 0);
    for (std::size_t n : {1'000u, 10'000u, 100'000u, 1'000'000u}) {
        std::vector<photon::Photon> photons(n);
        for (auto& p : photons)
            p = {{rng.uniform<float>(), rng.uniform<float>(), rng.uniform<float>()},
                 photon::PackedPhoton({1.0f, 0.5f, 0.25f}, {0.0f, -1.0f, 0.0f}, photon::PathKind::indirect)};
        for (std::uint32_t leaf : {8u, photon::KdTreeConfig{}.max_leaf_size}) {
            const photon::KdTree<photon::Photon> tree(std::span<const photon::Photon>(photons), {.max_leaf_size = leaf});
            INFO("n " << n << " leaf " << leaf << ": " << double(tree.memory_bytes()) / double(n) << " bytes per photon");
            REQUIRE(tree.memory_bytes() <= 24 * n);
            REQUIRE(tree.memory_bytes() >= 20 * n);  // it cannot hold less than positions + payloads
        }
    }
}
