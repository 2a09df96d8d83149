// SPDX-License-Identifier: MIT
// KdTree against a brute-force oracle: random, clustered, coplanar, collinear and duplicate point
// sets; edge cases of k and radius; float and double positions; a user point type; the build's
// balance and determinism; the memory budget. Fixed seeds throughout, no timing.

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <span>
#include <thread>
#include <vector>

#include "photon/math/rng.hpp"
#include "photon/photonmap/kdtree.hpp"
#include "photon/photonmap/neighbors.hpp"
#include "photon/photonmap/photon.hpp"

// Every member of the class template compiles (bvh's benchmark.cpp does the same).
template class photon::KdTree<photon::Photon>;

namespace {

using photon::KdTree;
using photon::Neighbor;
using photon::Pcg32;
using photon::Vec3;

// Uses the default point_traits: a `position` member, the whole record as payload.
template <class S> struct TestPoint {
    Vec3<S> position;
    std::uint32_t id;
};

enum class Cloud { uniform, clustered, coplanar, collinear, identical, lattice, two_points };
constexpr Cloud all_clouds[] = {Cloud::uniform,   Cloud::clustered, Cloud::coplanar,  Cloud::collinear,
                                Cloud::identical, Cloud::lattice,   Cloud::two_points};

template <class S> std::vector<TestPoint<S>> make_cloud(Cloud kind, std::size_t n, std::uint64_t seed) {
    Pcg32 rng(seed, 1);
    std::vector<Vec3<S>> centres;
    for (int c = 0; c < 5; ++c) centres.push_back({rng.uniform<S>(), rng.uniform<S>(), rng.uniform<S>()});
    std::vector<TestPoint<S>> pts(n);
    for (std::size_t i = 0; i < n; ++i) {
        Vec3<S>& p = pts[i].position;
        pts[i].id = static_cast<std::uint32_t>(i);
        switch (kind) {
        case Cloud::uniform: p = {rng.uniform<S>(), rng.uniform<S>(), rng.uniform<S>()}; break;
        case Cloud::clustered:
            p = centres[rng.below(5)] +
                Vec3<S>(rng.uniform<S>() - S(0.5), rng.uniform<S>() - S(0.5), rng.uniform<S>() - S(0.5)) * S(0.01);
            break;
        case Cloud::coplanar: p = {rng.uniform<S>(), S(0.25), rng.uniform<S>()}; break;
        case Cloud::collinear: p = {S(0.1), rng.uniform<S>(), S(0.1)}; break;
        case Cloud::identical: p = {S(0.5), S(0.5), S(0.5)}; break;
        case Cloud::lattice:  // many exact ties in every coordinate and distance
            p = {S(rng.below(6)) / S(5), S(rng.below(6)) / S(5), S(rng.below(6)) / S(5)};
            break;
        case Cloud::two_points: p = rng.below(2) == 0 ? Vec3<S>(S(0.2), S(0.3), S(0.4)) : Vec3<S>(S(0.7), S(0.3), S(0.4)); break;
        }
    }
    return pts;
}

template <class S> S distance2(const Vec3<S>& a, const Vec3<S>& b) {
    const S dx = a.x - b.x, dy = a.y - b.y, dz = a.z - b.z;
    return dx * dx + dy * dy + dz * dz;
}

// Sorted squared distances of the k nearest points with distance2 < max_d2.
template <class S>
std::vector<S> brute_k_nearest(const std::vector<TestPoint<S>>& pts, const Vec3<S>& q, std::size_t k, S max_d2) {
    std::vector<S> d;
    for (const auto& p : pts)
        if (const S d2 = distance2(p.position, q); d2 < max_d2) d.push_back(d2);
    std::sort(d.begin(), d.end());
    if (d.size() > k) d.resize(k);
    return d;
}

template <class S> std::vector<S> sorted_distances(std::span<const Neighbor<S>> ns) {
    std::vector<S> d;
    for (const auto& n : ns) d.push_back(n.distance2);
    std::sort(d.begin(), d.end());
    return d;
}

// Equal multisets of distances, up to rounding (ties may come back as different points).
template <class S> void require_same_distances(const std::vector<S>& got, const std::vector<S>& want) {
    REQUIRE(got.size() == want.size());
    for (std::size_t i = 0; i < got.size(); ++i) REQUIRE(got[i] == Approx(want[i]).epsilon(1e-6).margin(1e-30));
}

// Each reported neighbour is a real point of the tree at the reported distance, and no index repeats.
template <class Tree, class S> void require_consistent(const Tree& tree, const Vec3<S>& q, std::span<const Neighbor<S>> ns) {
    std::vector<std::uint32_t> seen;
    for (const auto& n : ns) {
        REQUIRE(n.index < tree.size());
        REQUIRE(std::isfinite(n.distance2));
        REQUIRE(n.distance2 == Approx(distance2(tree.position(n.index), q)).epsilon(1e-6).margin(1e-30));
        seen.push_back(n.index);
    }
    std::sort(seen.begin(), seen.end());
    REQUIRE(std::adjacent_find(seen.begin(), seen.end()) == seen.end());
}

template <class S> Vec3<S> random_query(Pcg32& rng) {
    return {rng.uniform<S>() * S(1.2) - S(0.1), rng.uniform<S>() * S(1.2) - S(0.1), rng.uniform<S>() * S(1.2) - S(0.1)};
}

std::uint32_t expected_depth(std::size_t n, std::uint32_t max_leaf) {
    const std::size_t leaf = std::clamp<std::uint32_t>(max_leaf, 2, 64);
    const std::size_t leaves = (n + leaf - 1) / leaf;
    std::uint32_t d = 0;
    while ((std::size_t(1) << d) < leaves) ++d;
    return d;
}

// Checks the visitor contract while collecting the k nearest.
template <class S> struct CheckingVisitor {
    photon::KNearest<S> inner;
    bool ok = true;
    S max_distance2() const { return inner.max_distance2(); }
    void visit(std::uint32_t i, S d2) {
        ok = ok && d2 < inner.max_distance2();
        inner.visit(i, d2);
    }
};

}  // namespace

// A user's photon: positions as a double array, and only part of the record kept by the tree.
struct UserPhoton {
    double xyz[3];
    float power;
    std::uint32_t id;
    double unused_by_tree;
};
struct UserPayload {
    float power;
    std::uint32_t id;
};
template <> struct photon::point_traits<UserPhoton> {
    using payload_type = UserPayload;
    static Vec3<double> position(const UserPhoton& p) noexcept { return {p.xyz[0], p.xyz[1], p.xyz[2]}; }
    static UserPayload payload(const UserPhoton& p) noexcept { return {p.power, p.id}; }
};

static_assert(photon::SpatialPoint<TestPoint<float>> && photon::SpatialPoint<UserPhoton>);
static_assert(photon::NeighborVisitor<photon::KNearest<float>, float>);
static_assert(photon::NeighborVisitor<photon::WithinRadius<double>, double>);
static_assert(photon::NeighborVisitor<CheckingVisitor<float>, float>);
static_assert(!photon::NeighborVisitor<int, float>);
static_assert(std::is_same_v<KdTree<UserPhoton>::scalar_type, double>);

TEMPLATE_TEST_CASE("k_nearest equals brute force", "[kdtree]", float, double) {
    using S = TestType;
    const std::size_t sizes[] = {1, 2, 3, 31, 64, 65, 500, 3000};
    const std::size_t ks[] = {0, 1, 2, 10, 50, 200, 4000};
    const S radii[] = {S(0), S(0.001), S(0.05), S(0.2), std::numeric_limits<S>::infinity()};
    std::vector<Neighbor<S>> buffer;
    std::uint64_t seed = 100;
    for (Cloud kind : all_clouds) {
        for (std::size_t n : sizes) {
            const auto pts = make_cloud<S>(kind, n, ++seed);
            for (std::uint32_t leaf : {2u, 5u, 32u, 64u}) {
                const KdTree<TestPoint<S>> tree(pts, {.max_leaf_size = leaf});
                REQUIRE(tree.size() == n);
                REQUIRE(tree.depth() == expected_depth(n, leaf));
                Pcg32 rng(seed, 2);
                for (int qi = 0; qi < 6; ++qi) {
                    const Vec3<S> q = qi == 0 ? pts[0].position : random_query<S>(rng);
                    for (std::size_t k : ks) {
                        for (S r : radii) {
                            INFO("cloud " << int(kind) << " n " << n << " leaf " << leaf << " k " << k << " r " << r);
                            const auto got = tree.k_nearest(q, k, r, buffer);
                            const auto want = brute_k_nearest(pts, q, k, r * r);
                            require_same_distances(sorted_distances(got.neighbors), want);
                            require_consistent(tree, q, got.neighbors);
                            REQUIRE_FALSE(std::isnan(got.radius2));
                            if (k > 0 && want.size() == k) REQUIRE(got.radius2 == Approx(want.back()).margin(1e-30));
                            else REQUIRE(got.radius2 == r * r);
                        }
                    }
                }
            }
        }
    }
}

TEMPLATE_TEST_CASE("large sets: every build path against brute force", "[kdtree]", float, double) {
    using S = TestType;
    std::vector<Neighbor<S>> buffer;
    std::uint64_t seed = 500;
    for (Cloud kind : all_clouds) {
        const auto pts = make_cloud<S>(kind, 40'000, ++seed);
        const KdTree<TestPoint<S>> tree(pts);
        REQUIRE(tree.depth() == expected_depth(pts.size(), photon::KdTreeConfig{}.max_leaf_size));
        Pcg32 rng(seed, 3);
        for (int qi = 0; qi < 8; ++qi) {
            const Vec3<S> q = random_query<S>(rng);
            for (std::size_t k : {1u, 50u, 300u}) {
                INFO("cloud " << int(kind) << " k " << k);
                const auto got = tree.k_nearest(q, k, S(0.1), buffer);
                require_same_distances(sorted_distances(got.neighbors), brute_k_nearest(pts, q, k, S(0.01)));
                require_consistent(tree, q, got.neighbors);
            }
        }
    }
}

TEMPLATE_TEST_CASE("within_radius equals brute force", "[kdtree]", float, double) {
    using S = TestType;
    std::vector<Neighbor<S>> buffer;
    std::uint64_t seed = 900;
    for (Cloud kind : all_clouds) {
        for (std::size_t n : {0u, 1u, 40u, 2000u}) {
            const auto pts = make_cloud<S>(kind, n, ++seed);
            const KdTree<TestPoint<S>> tree(pts, {.max_leaf_size = 8});
            Pcg32 rng(seed, 4);
            for (int qi = 0; qi < 10; ++qi) {
                const Vec3<S> q = qi == 0 && n > 0 ? pts[0].position : random_query<S>(rng);
                for (S r : {S(0), S(0.02), S(0.2), S(2)}) {
                    INFO("cloud " << int(kind) << " n " << n << " r " << r);
                    const auto got = tree.within_radius(q, r, buffer);
                    require_same_distances(sorted_distances(got), brute_k_nearest(pts, q, n, r * r));
                    require_consistent(tree, q, got);
                }
            }
        }
    }
}

TEST_CASE("empty map", "[kdtree]") {
    std::vector<Neighbor<float>> buffer;
    const std::vector<photon::Photon> none;
    for (const auto& tree : {KdTree<photon::Photon>(), KdTree<photon::Photon>(std::span<const photon::Photon>(none))}) {
        REQUIRE(tree.empty());
        REQUIRE(tree.size() == 0);
        REQUIRE(tree.depth() == 0);
        REQUIRE(tree.bounds().is_empty());
        REQUIRE(tree.memory_bytes() >= sizeof(tree));
        const auto got = tree.k_nearest({0.0f, 0.0f, 0.0f}, 10, 1.0f, buffer);
        REQUIRE(got.neighbors.empty());
        REQUIRE(got.radius2 == 1.0f);
        REQUIRE(tree.within_radius({0.0f, 0.0f, 0.0f}, 1.0f, buffer).empty());
        const auto all = tree.k_nearest({0.0f, 0.0f, 0.0f}, 10, INFINITY, buffer);
        REQUIRE(all.neighbors.empty());
    }
}

TEST_CASE("k = 0, k larger than the map, radius 0", "[kdtree]") {
    const auto pts = make_cloud<float>(Cloud::uniform, 100, 7);
    const KdTree<TestPoint<float>> tree(pts);
    std::vector<Neighbor<float>> buffer;
    const Vec3<float> q = pts[3].position;

    const auto none = tree.k_nearest(q, 0, 0.5f, buffer);
    REQUIRE(none.neighbors.empty());
    REQUIRE(none.radius2 == 0.25f);

    const auto all = tree.k_nearest(q, 1000, INFINITY, buffer);
    REQUIRE(all.neighbors.size() == 100);
    REQUIRE(all.radius2 == INFINITY);  // fewer than k found: the maximum radius, as documented
    REQUIRE(buffer.size() >= 1000);

    // Strictly inside a zero radius is nothing, even for a point at the query itself.
    const auto zero = tree.k_nearest(q, 5, 0.0f, buffer);
    REQUIRE(zero.neighbors.empty());
    REQUIRE(zero.radius2 == 0.0f);
    REQUIRE(tree.within_radius(q, 0.0f, buffer).empty());

    // The point at the query is found at distance 0 by any positive radius.
    const auto one = tree.k_nearest(q, 1, 1e-3f, buffer);
    REQUIRE(one.neighbors.size() == 1);
    REQUIRE(one.neighbors[0].distance2 == 0.0f);
    REQUIRE(one.radius2 == 0.0f);
    REQUIRE(tree.payload(one.neighbors[0].index).id == 3);
}

TEST_CASE("all points identical: balanced, and every query sees them", "[kdtree]") {
    const std::size_t n = 100'000;
    const auto pts = make_cloud<float>(Cloud::identical, n, 1);
    const KdTree<TestPoint<float>> tree(pts, {.max_leaf_size = 16});
    REQUIRE(tree.depth() == expected_depth(n, 16));
    REQUIRE(tree.depth() <= std::uint32_t(std::ceil(std::log2(double(n)))));
    std::vector<Neighbor<float>> buffer;
    const auto at = tree.k_nearest({0.5f, 0.5f, 0.5f}, 50, 0.1f, buffer);
    REQUIRE(at.neighbors.size() == 50);
    REQUIRE(at.radius2 == 0.0f);
    const auto near = tree.k_nearest({0.5f, 0.5f, 0.6f}, 50, 0.2f, buffer);
    REQUIRE(near.neighbors.size() == 50);
    for (const auto& nb : near.neighbors) REQUIRE(nb.distance2 == Approx(0.01f));
    REQUIRE(tree.within_radius({0.5f, 0.5f, 0.6f}, 0.2f, buffer).size() == n);
    REQUIRE(tree.within_radius({0.5f, 0.5f, 0.6f}, 0.05f, buffer).empty());
}

TEST_CASE("the tree holds a permutation of the input, with matching payloads", "[kdtree]") {
    for (Cloud kind : all_clouds) {
        const auto pts = make_cloud<double>(kind, 5000, 77);
        const KdTree<TestPoint<double>> tree(pts);
        std::vector<std::uint32_t> ids;
        photon::BBox<double> box;
        for (std::size_t i = 0; i < tree.size(); ++i) {
            const auto& rec = tree.payload(i);
            REQUIRE(tree.position(i) == pts[rec.id].position);
            ids.push_back(rec.id);
            box.extend(pts[i].position);
        }
        std::sort(ids.begin(), ids.end());
        for (std::size_t i = 0; i < ids.size(); ++i) REQUIRE(ids[i] == i);
        REQUIRE(tree.bounds().min == box.min);
        REQUIRE(tree.bounds().max == box.max);
    }
}

TEST_CASE("a user point type with its own point_traits", "[kdtree]") {
    Pcg32 rng(5, 5);
    std::vector<UserPhoton> photons(3000);
    for (std::uint32_t i = 0; i < photons.size(); ++i)
        photons[i] = {{rng.uniform<double>(), rng.uniform<double>(), rng.uniform<double>()}, float(i) * 0.5f, i, -1.0};
    const KdTree<UserPhoton> tree(photons);
    for (std::size_t i = 0; i < tree.size(); ++i) {
        const UserPayload& p = tree.payload(i);
        REQUIRE(p.power == float(p.id) * 0.5f);
        const auto pos = tree.position(i);
        REQUIRE(pos == Vec3<double>(photons[p.id].xyz[0], photons[p.id].xyz[1], photons[p.id].xyz[2]));
    }
    std::vector<Neighbor<double>> buffer;
    for (int qi = 0; qi < 20; ++qi) {
        const Vec3<double> q{rng.uniform<double>(), rng.uniform<double>(), rng.uniform<double>()};
        std::vector<double> want;
        for (const auto& p : photons)
            want.push_back(distance2(Vec3<double>(p.xyz[0], p.xyz[1], p.xyz[2]), q));
        std::sort(want.begin(), want.end());
        want.resize(25);
        const auto got = tree.k_nearest(q, 25, INFINITY, buffer);
        require_same_distances(sorted_distances(got.neighbors), want);
    }
}

TEST_CASE("accept predicate filters like brute force", "[kdtree]") {
    const auto pts = make_cloud<float>(Cloud::uniform, 4000, 13);
    const KdTree<TestPoint<float>> tree(pts);
    std::vector<TestPoint<float>> even;
    for (const auto& p : pts)
        if (p.id % 2 == 0) even.push_back(p);
    std::vector<Neighbor<float>> buffer;
    Pcg32 rng(13, 1);
    for (int qi = 0; qi < 30; ++qi) {
        const auto q = random_query<float>(rng);
        const auto got = tree.k_nearest(q, 40, 0.15f, buffer,
                                         [&tree](std::uint32_t i, float) { return tree.payload(i).id % 2 == 0; });
        require_same_distances(sorted_distances(got.neighbors), brute_k_nearest(even, q, 40, 0.15f * 0.15f));
        for (const auto& nb : got.neighbors) REQUIRE(tree.payload(nb.index).id % 2 == 0);
    }
}

TEST_CASE("search drives any NeighborVisitor within its contract", "[kdtree]") {
    const auto pts = make_cloud<float>(Cloud::clustered, 6000, 21);
    const KdTree<TestPoint<float>> tree(pts, {.max_leaf_size = 8});
    Pcg32 rng(21, 1);
    std::vector<Neighbor<float>> storage(60);
    for (int qi = 0; qi < 30; ++qi) {
        const auto q = random_query<float>(rng);
        CheckingVisitor<float> v{photon::KNearest<float>(std::span<Neighbor<float>>(storage), 0.04f)};
        tree.search(q, v);
        REQUIRE(v.ok);
        require_same_distances(sorted_distances(v.inner.neighbors()), brute_k_nearest(pts, q, 60, 0.04f));
        v.inner.sort();
        const auto ns = v.inner.neighbors();
        REQUIRE(std::is_sorted(ns.begin(), ns.end(), [](const auto& a, const auto& b) { return a.distance2 < b.distance2; }));
    }
    // A visitor that stops after the first point.
    struct FirstOnly {
        float radius2 = 1.0f;
        int visits = 0;
        float max_distance2() const { return radius2; }
        void visit(std::uint32_t, float) {
            ++visits;
            radius2 = 0.0f;
        }
    } first;
    tree.search({0.5f, 0.5f, 0.5f}, first);
    REQUIRE(first.visits == 1);
}

TEST_CASE("the tree is the same for every thread count", "[kdtree]") {
    const auto pts = make_cloud<float>(Cloud::clustered, 300'000, 3);
    const KdTree<TestPoint<float>> one(pts, {.threads = 1});
    for (unsigned threads : {2u, 3u, 4u, 0u}) {
        const KdTree<TestPoint<float>> many(pts, {.threads = threads});
        REQUIRE(many.depth() == one.depth());
        REQUIRE(many.memory_bytes() == one.memory_bytes());
        bool same = true;
        for (std::size_t i = 0; i < one.size(); ++i)
            same = same && many.position(i) == one.position(i) && many.payload(i).id == one.payload(i).id;
        REQUIRE(same);
    }
}

TEST_CASE("concurrent readers get the sequential answers", "[kdtree]") {
    const auto pts = make_cloud<float>(Cloud::uniform, 20'000, 8);
    const KdTree<TestPoint<float>> tree(pts);
    std::vector<Vec3<float>> queries(400);
    Pcg32 rng(8, 1);
    for (auto& q : queries) q = random_query<float>(rng);
    auto answer = [&](std::size_t qi, std::vector<Neighbor<float>>& buffer) {
        return sorted_distances(tree.k_nearest(queries[qi], 30, 0.1f, buffer).neighbors);
    };
    std::vector<std::vector<float>> expected(queries.size());
    std::vector<Neighbor<float>> buffer;
    for (std::size_t qi = 0; qi < queries.size(); ++qi) expected[qi] = answer(qi, buffer);
    std::vector<int> mismatches(4, 0);
    std::vector<std::thread> readers;
    for (int t = 0; t < 4; ++t) {
        readers.emplace_back([&, t] {
            std::vector<Neighbor<float>> own;
            for (std::size_t qi = std::size_t(t); qi < queries.size(); qi += 2)
                mismatches[std::size_t(t)] += answer(qi, own) == expected[qi] ? 0 : 1;
        });
    }
    for (auto& r : readers) r.join();
    for (int m : mismatches) REQUIRE(m == 0);
}

TEST_CASE("class template argument deduction from spans and vectors", "[kdtree]") {
    std::vector<photon::Photon> photons(10, photon::Photon{{0.0f, 1.0f, 2.0f}, {}});
    auto from_span = photon::KdTree(std::span(photons));
    auto from_vector = photon::KdTree(photons, {.max_leaf_size = 4});
    static_assert(std::is_same_v<decltype(from_span), KdTree<photon::Photon>>);
    static_assert(std::is_same_v<decltype(from_vector), KdTree<photon::Photon>>);
    REQUIRE(from_vector.size() == 10);
}

TEST_CASE("copies are independent, moves leave an empty tree", "[kdtree]") {
    const auto pts = make_cloud<float>(Cloud::uniform, 1000, 4);
    KdTree<TestPoint<float>> tree(pts);
    const KdTree<TestPoint<float>> copy = tree;
    KdTree<TestPoint<float>> moved = std::move(tree);
    REQUIRE(tree.empty());  // NOLINT(bugprone-use-after-move): the documented moved-from state
    REQUIRE(tree.bounds().is_empty());
    std::vector<Neighbor<float>> buffer;
    REQUIRE(tree.k_nearest({0.5f, 0.5f, 0.5f}, 5, INFINITY, buffer).neighbors.empty());
    for (const KdTree<TestPoint<float>>* t : {&copy, static_cast<const KdTree<TestPoint<float>>*>(&moved)}) {
        REQUIRE(t->size() == 1000);
        REQUIRE(t->k_nearest({0.5f, 0.5f, 0.5f}, 5, INFINITY, buffer).neighbors.size() == 5);
    }
    tree = copy;
    REQUIRE(tree.size() == 1000);
}
