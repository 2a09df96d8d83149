// SPDX-License-Identifier: MIT
// The photon map at its limits: empty, fewer photons than an estimate asks for, and every photon
// at one point. The tree must stay balanced and shallow and its queries cheap; the cost is
// asserted by counting depth and visited photons, not by timing.

#include "hard_case_util.hpp"

#include <cmath>

using namespace photon;

namespace {

std::vector<Photon> photons_at(const std::vector<Vec3<float>>& positions, float power) {
    std::vector<Photon> out;
    for (const auto& p : positions) out.push_back({p, PackedPhoton(Rgb<float>(power), {0, -1, 0}, PathKind::direct)});
    return out;
}

/// k-nearest search that counts the photons the tree hands it.
struct CountingKNearest {
    std::size_t k;
    std::vector<float> heap{};  // max-heap of the k best squared distances
    std::size_t visits = 0;
    [[nodiscard]] float max_distance2() const noexcept {
        return heap.size() == k ? heap.front() : std::numeric_limits<float>::infinity();
    }
    void visit(std::uint32_t, float d2) {
        ++visits;
        if (heap.size() < k) {
            heap.push_back(d2);
            std::push_heap(heap.begin(), heap.end());
        } else if (d2 < heap.front()) {
            std::pop_heap(heap.begin(), heap.end());
            heap.back() = d2;
            std::push_heap(heap.begin(), heap.end());
        }
    }
};

std::uint32_t balanced_depth(std::size_t n, std::size_t leaf) {
    std::uint32_t d = 0;
    while ((std::size_t(1) << d) * leaf < n) ++d;
    return d;
}

}  // namespace

TEMPLATE_TEST_CASE("estimates from an empty map and from a map smaller than k", "[hard][kdtree]", float, double) {
    using S = TestType;
    EstimateScratch scratch;
    const EstimateSettings es{.k = 100, .max_radius = 0.5f};
    const PhotonMap empty;
    CHECK(estimate_irradiance(empty, Vec3<S>(0), Vec3<S>(0, 1, 0), es, scratch) == Rgb<S>(0));
    const std::vector<Photon> none;
    const PhotonMap built_empty{std::span<const Photon>(none)};
    CHECK(built_empty.empty());
    CHECK(estimate_irradiance(built_empty, Vec3<S>(0), Vec3<S>(0, 1, 0), es, scratch) == Rgb<S>(0));
    // Five photons, k = 100: every photon within the maximum radius counts, over pi r_max^2.
    const PhotonMap five(photons_at({{0, 0, 0}, {0.1f, 0, 0}, {0, 0, 0.2f}, {-0.3f, 0, 0}, {2, 0, 0}}, 1.0f));
    const Rgb<S> e = estimate_irradiance(five, Vec3<S>(0), Vec3<S>(0, 1, 0), es, scratch);
    CHECK(e.x == Approx(4.0 / (pi<double> * 0.25)).epsilon(1e-3));
    // k = 1 asks for nothing but the radius: no photon is left to count, and no NaN.
    const Rgb<S> k1 = estimate_irradiance(five, Vec3<S>(0), Vec3<S>(0, 1, 0), EstimateSettings{.k = 1, .max_radius = 0.5f}, scratch);
    CHECK(is_finite(k1));
    std::vector<Neighbor<float>> buffer;
    CHECK(five.k_nearest({0, 0, 0}, 1000, INFINITY, buffer).neighbors.size() == 5);
}

TEMPLATE_TEST_CASE("every photon at one point: a shallow balanced tree, cheap queries, finite estimates",
                   "[hard][kdtree]", float, double) {
    using S = TestType;
    const Vec3<float> at{0.25f, 1.0f, -0.5f};
    std::size_t previous_visits = 0;
    for (const std::size_t n : {std::size_t(1'000), std::size_t(10'000), std::size_t(100'000), std::size_t(1'000'000)}) {
        INFO(n << " photons at one point");
        const PhotonMap map(photons_at(std::vector<Vec3<float>>(n, at), 1.0f / float(n)), {.max_leaf_size = 32});
        // Split by count, not by value: the depth is that of a balanced tree, about log2(n / 32).
        CHECK(map.depth() == balanced_depth(n, 32));
        CHECK(map.depth() <= 15);
        // A k-nearest query at the point, and one beside it, visit O(k + leaf) photons, not n:
        // once k are found at distance d, every cell at distance >= d is skipped.
        for (const Vec3<float>& q : {at, at + Vec3<float>(0, 0.01f, 0)}) {
            CountingKNearest visitor{.k = 50};
            map.search(q, visitor);
            CHECK(visitor.heap.size() == 50);
            CHECK(visitor.visits <= 50 + 2 * 32);
            if (n > 1'000) CHECK(visitor.visits <= previous_visits + 32);  // does not grow with n
            previous_visits = visitor.visits;
        }
        EstimateScratch scratch;
        const EstimateSettings es{.k = 100, .max_radius = 0.5f};
        // At the point itself the k-th photon is at distance 0: no area to divide by. The estimate
        // is 0, not a division by zero.
        const Rgb<S> on = estimate_irradiance(map, Vec3<S>(at), Vec3<S>(0, 1, 0), es, scratch);
        CHECK(is_finite(on));
        // Beside it (in the tangent plane), the 99 photons over the disc to the 100th.
        const Rgb<S> beside = estimate_irradiance(map, Vec3<S>(at) + Vec3<S>(0.01, 0, 0), Vec3<S>(0, 1, 0), es, scratch);
        CHECK(beside.x == Approx(99.0 / double(n) / (pi<double> * 1e-4)).epsilon(1e-3));
    }
}

TEMPLATE_TEST_CASE("photons on one plane and on one line stay balanced too", "[hard][kdtree]", float, double) {
    using S = TestType;
    Pcg32 rng(3, 3);
    const std::size_t n = 200'000;
    std::vector<Vec3<float>> plane, line;
    for (std::size_t i = 0; i < n; ++i) {
        const Vec2<float> u = rng.uniform2<float>();
        plane.push_back({u.x, 0.5f, u.y});
        line.push_back({u.x, 0.5f, 0.5f});
    }
    for (const auto* positions : {&plane, &line}) {
        const PhotonMap map(photons_at(*positions, 1.0f / float(n)));
        CHECK(map.depth() == balanced_depth(n, 32));
        CountingKNearest visitor{.k = 100};
        map.search({0.5f, 0.5f, 0.5f}, visitor);
        CHECK(visitor.visits < 2'000);  // a few leaves of 32, not a scan of 200,000
        EstimateScratch scratch;
        CHECK(is_finite(estimate_irradiance(map, Vec3<S>(0.5), Vec3<S>(0, 1, 0), EstimateSettings{.k = 100, .max_radius = 0.1f}, scratch)));
    }
}
