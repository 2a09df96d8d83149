// SPDX-License-Identifier: MIT
// photon::KdTree against nanoflann (Blanco and Rai 2014), single-threaded, same points and queries:
// build time, k-nearest queries capped by a maximum radius (the photon-map query) and plain
// k-nearest queries, memory per point, and brute force at small N. Before timing a query cell,
// both trees must return the same neighbours (as distance multisets) or the run stops. Times are
// CPU times of the one benchmark thread (robust to other load on the machine), except the
// informational two-thread build, which is wall time.
//
//   kdtree_bench [--quick] [--photon_leaf=<n>] [google benchmark flags]
//
// --quick drops N = 4M; --photon_leaf=<n> sets photon's max leaf size (default: the library's).
// At the end, Markdown tables of photon / nanoflann ratios (ratio_table.hpp).

#include <benchmark/benchmark.h>
#include <nanoflann.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <map>
#include <memory>
#include <set>
#include <span>
#include <string>
#include <vector>

#include "kdtree_bench_data.hpp"
#include "photon/photonmap/kdtree.hpp"
#include "photon/photonmap/neighbors.hpp"
#include "photon/photonmap/photon.hpp"
#include "ratio_table.hpp"

namespace {

using photon::Photon;
using photon::Vec3;
using photon::bench::Distribution;
using Tree = photon::KdTree<Photon>;

// nanoflann reads the caller's records in place through this adaptor.
struct PhotonCloud {
    const Photon* points = nullptr;
    std::size_t count = 0;
    [[nodiscard]] std::size_t kdtree_get_point_count() const { return count; }
    [[nodiscard]] float kdtree_get_pt(std::size_t i, std::size_t d) const { return points[i].position[int(d)]; }
    template <class Box> bool kdtree_get_bbox(Box&) const { return false; }
};
using NanoTree = nanoflann::KDTreeSingleIndexAdaptor<nanoflann::L2_Simple_Adaptor<float, PhotonCloud>, PhotonCloud, 3>;

constexpr std::size_t nano_leaf_sizes[] = {5, 10, 20, 40};
photon::KdTreeConfig photon_config;  // --photon_leaf=<n> overrides the default leaf size (for tuning)
constexpr std::size_t query_count = std::size_t(1) << 16;
constexpr std::size_t pilot_queries = 4096;
constexpr std::size_t verify_queries = 256;
constexpr double capped_share = 0.2;  // the max radius is the 80th percentile of the k-th neighbour distance

struct Mode {
    std::size_t k;
    bool capped;
    [[nodiscard]] std::string name() const {
        char buf[32];
        std::snprintf(buf, sizeof buf, "k%zu%s", k, capped ? "r" : "");
        return buf;
    }
};

struct Dataset {
    Distribution dist;
    std::size_t n;
    std::vector<Photon> points;
    std::vector<Vec3<float>> queries;
    PhotonCloud cloud;
    std::unique_ptr<Tree> tree;
    std::map<std::size_t, std::unique_ptr<NanoTree>> nano;
    std::vector<Photon> presorted;  // the same photons in photon's tree order (spatially coherent)
    PhotonCloud presorted_cloud;
    std::unique_ptr<NanoTree> nano_presorted;
    std::map<std::size_t, std::pair<float, double>> radius;  // k -> (max radius, share capped)
    std::set<std::string> verified;

    Dataset(Distribution d, std::size_t count) : dist(d), n(count) {
        const std::uint64_t seed = 20261124 + count;
        points = d == Distribution::cornell ? photon::bench::cornell_photons(count, seed) : photon::bench::cube_points(count, seed);
        queries = d == Distribution::cornell ? photon::bench::cornell_queries(query_count, seed) : photon::bench::cube_queries(query_count, seed);
        cloud = {points.data(), points.size()};
    }
    const Tree& photon_tree() {
        if (!tree) tree = std::make_unique<Tree>(std::span<const Photon>(points), photon_config);
        return *tree;
    }
    NanoTree& nano_tree(std::size_t leaf) {
        auto& t = nano[leaf];
        if (!t) t = std::make_unique<NanoTree>(3, cloud, nanoflann::KDTreeSingleIndexAdaptorParams(leaf));
        return *t;
    }
    // nanoflann reading records that the caller had reordered spatially (here: photon's tree
    // order), to show how much of the gap is memory layout.
    NanoTree& nano_presorted_tree() {
        if (!nano_presorted) {
            const Tree& t = photon_tree();
            presorted.resize(t.size());
            for (std::size_t i = 0; i < t.size(); ++i) presorted[i] = {t.position(i), t.payload(i)};
            presorted_cloud = {presorted.data(), presorted.size()};
            nano_presorted = std::make_unique<NanoTree>(3, presorted_cloud, nanoflann::KDTreeSingleIndexAdaptorParams(10));
        }
        return *nano_presorted;
    }
    // The max radius for k: most queries find k neighbours inside it, some (capped_share) do not.
    std::pair<float, double> radius_for(std::size_t k) {
        auto it = radius.find(k);
        if (it != radius.end()) return it->second;
        const Tree& t = photon_tree();
        std::vector<photon::Neighbor<float>> buf;
        std::vector<float> kth;
        for (std::size_t i = 0; i < pilot_queries; ++i)
            kth.push_back(t.k_nearest(queries[i], k, INFINITY, buf).radius2);
        std::sort(kth.begin(), kth.end());
        const float r = std::sqrt(kth[std::size_t(double(kth.size()) * (1.0 - capped_share))]);
        std::size_t capped = 0;
        for (float d2 : kth) capped += d2 >= r * r ? 1 : 0;
        return radius[k] = {r, double(capped) / double(kth.size())};
    }
};

std::unique_ptr<Dataset> current;

Dataset& dataset(Distribution d, std::size_t n) {
    if (!current || current->dist != d || current->n != n) {
        current.reset();
        current = std::make_unique<Dataset>(d, n);
    }
    return *current;
}

// ---- the queries under test ----------------------------------------------------------------

struct PhotonQuery {
    const Tree* tree;
    std::vector<photon::Neighbor<float>> buf;
    std::size_t count = 0;
    void operator()(const Vec3<float>& q, std::size_t k, float r) {
        const auto res = tree->k_nearest(q, k, r, buf);
        count = res.neighbors.size();
        benchmark::DoNotOptimize(res.radius2);
    }
    std::vector<float> distances() const {
        std::vector<float> d;
        for (std::size_t i = 0; i < count; ++i) d.push_back(buf[i].distance2);
        return d;
    }
};

struct NanoQuery {
    const NanoTree* tree;
    std::vector<std::uint32_t> idx;
    std::vector<float> dist;
    std::size_t count = 0;
    // Debian's nanoflann 1.4.3 has no RKNNResultSet: KNNResultSet::init() sets dists[k-1] to the
    // largest float and worstDist() reads dists[k-1], so starting that slot at r^2 gives the
    // radius-capped k-nearest query (entries below count are always written before being read).
    void operator()(const Vec3<float>& q, std::size_t k, float r) {
        if (idx.size() < k) {
            idx.resize(k);
            dist.resize(k);
        }
        nanoflann::KNNResultSet<float, std::uint32_t, std::size_t> rs(k);
        rs.init(idx.data(), dist.data());
        if (k > 0 && std::isfinite(r)) dist[k - 1] = r * r;
        const float p[3] = {q.x, q.y, q.z};
        tree->findNeighbors(rs, p, nanoflann::SearchParams());
        count = rs.size();
        benchmark::DoNotOptimize(dist.data());
    }
    std::vector<float> distances() const { return {dist.begin(), dist.begin() + std::ptrdiff_t(count)}; }
};

struct BruteQuery {
    const std::vector<Photon>* points;
    std::vector<photon::Neighbor<float>> buf;
    std::size_t count = 0;
    void operator()(const Vec3<float>& q, std::size_t k, float r) {
        if (buf.size() < k) buf.resize(k);
        photon::KNearest<float> v(std::span<photon::Neighbor<float>>(buf.data(), k), r * r);
        const auto& pts = *points;
        for (std::size_t i = 0; i < pts.size(); ++i) {
            const float dx = pts[i].position.x - q.x, dy = pts[i].position.y - q.y, dz = pts[i].position.z - q.z;
            const float d2 = dx * dx + dy * dy + dz * dz;
            if (d2 < v.max_distance2()) v.visit(std::uint32_t(i), d2);
        }
        count = v.size();
        benchmark::DoNotOptimize(v.radius2());
    }
    std::vector<float> distances() const {
        std::vector<float> d;
        for (std::size_t i = 0; i < count; ++i) d.push_back(buf[i].distance2);
        return d;
    }
};

template <class Query> void verify(Dataset& ds, const Mode& m, float r, Query query, const std::string& impl) {
    const std::string key = m.name() + "/" + impl;
    if (ds.verified.count(key)) return;
    PhotonQuery ref{&ds.photon_tree(), {}};
    for (std::size_t i = 0; i < verify_queries; ++i) {
        const auto& q = ds.queries[i];
        ref(q, m.k, r);
        query(q, m.k, r);
        auto a = ref.distances(), b = query.distances();
        std::sort(a.begin(), a.end());
        std::sort(b.begin(), b.end());
        if (a != b) {
            std::fprintf(stderr, "MISMATCH %s/%zu/%s/%s query %zu: photon found %zu, %s found %zu\n", name(ds.dist), ds.n,
                         m.name().c_str(), impl.c_str(), i, a.size(), impl.c_str(), b.size());
            std::exit(EXIT_FAILURE);
        }
    }
    ds.verified.insert(key);
}

template <class Query> void run_queries(benchmark::State& state, Dataset& ds, const Mode& m, float r, Query& query) {
    std::size_t i = 0;
    for (auto _ : state) {
        query(ds.queries[i & (query_count - 1)], m.k, r);
        ++i;
    }
    state.SetItemsProcessed(std::int64_t(state.iterations()));
}

// ---- registration ---------------------------------------------------------------------------

std::string prefix(const char* kind, Distribution d, std::size_t n) {
    return std::string(kind) + "/" + name(d) + "/" + std::to_string(n) + "/";
}

void register_build(Distribution d, std::size_t n) {
    benchmark::RegisterBenchmark((prefix("build", d, n) + "photon").c_str(), [d, n](benchmark::State& state) {
        Dataset& ds = dataset(d, n);
        std::size_t bytes = 0;
        for (auto _ : state) {
            const Tree t(std::span<const Photon>(ds.points), photon_config);
            bytes = t.memory_bytes();
            benchmark::DoNotOptimize(t.size());
        }
        state.counters["B/pt"] = double(bytes) / double(n);
    })->Unit(benchmark::kMillisecond)->MinTime(0.5);
    // Not part of the single-threaded comparison: what KdTreeConfig::threads = 2 buys (wall time).
    benchmark::RegisterBenchmark((prefix("build", d, n) + "photon-2threads").c_str(), [d, n](benchmark::State& state) {
        Dataset& ds = dataset(d, n);
        photon::KdTreeConfig config = photon_config;
        config.threads = 2;
        for (auto _ : state) {
            const Tree t(std::span<const Photon>(ds.points), config);
            benchmark::DoNotOptimize(t.size());
        }
    })->Unit(benchmark::kMillisecond)->MinTime(0.5)->UseRealTime();
    for (std::size_t leaf : nano_leaf_sizes) {
        const std::string impl = "nanoflann_L" + std::to_string(leaf);
        benchmark::RegisterBenchmark((prefix("build", d, n) + impl).c_str(), [d, n, leaf](benchmark::State& state) {
            Dataset& ds = dataset(d, n);
            std::size_t bytes = 0;
            for (auto _ : state) {
                NanoTree t(3, ds.cloud, nanoflann::KDTreeSingleIndexAdaptorParams(leaf));
                bytes = t.usedMemory(t);
                benchmark::DoNotOptimize(t.root_node);
            }
            state.counters["B/pt"] = double(bytes) / double(n);
            state.counters["records_B/pt"] = double(sizeof(Photon));
        })->Unit(benchmark::kMillisecond)->MinTime(0.5);
    }
}

void register_queries(Distribution d, std::size_t n, const Mode& m, bool brute) {
    const std::string base = prefix("query", d, n) + m.name() + "/";
    auto radius = [m](Dataset& ds) { return m.capped ? ds.radius_for(m.k).first : INFINITY; };
    benchmark::RegisterBenchmark((base + "photon").c_str(), [d, n, m, radius](benchmark::State& state) {
        Dataset& ds = dataset(d, n);
        const float r = radius(ds);
        PhotonQuery q{&ds.photon_tree(), {}};
        run_queries(state, ds, m, r, q);
        if (m.capped) {
            state.counters["rmax"] = r;
            state.counters["capped"] = ds.radius_for(m.k).second;
        }
    })->Unit(benchmark::kMicrosecond)->MinTime(0.25);
    for (std::size_t leaf : nano_leaf_sizes) {
        const std::string impl = "nanoflann_L" + std::to_string(leaf);
        benchmark::RegisterBenchmark((base + impl).c_str(), [d, n, m, leaf, impl, radius](benchmark::State& state) {
            Dataset& ds = dataset(d, n);
            const float r = radius(ds);
            NanoQuery q{&ds.nano_tree(leaf), {}, {}};
            verify(ds, m, r, q, impl);
            run_queries(state, ds, m, r, q);
        })->Unit(benchmark::kMicrosecond)->MinTime(0.25);
    }
    benchmark::RegisterBenchmark((base + "nanoflann-presorted_L10").c_str(), [d, n, m, radius](benchmark::State& state) {
        Dataset& ds = dataset(d, n);
        const float r = radius(ds);
        NanoQuery q{&ds.nano_presorted_tree(), {}, {}};
        verify(ds, m, r, q, "nanoflann-presorted_L10");
        run_queries(state, ds, m, r, q);
    })->Unit(benchmark::kMicrosecond)->MinTime(0.25);
    if (brute) {
        benchmark::RegisterBenchmark((base + "brute").c_str(), [d, n, m, radius](benchmark::State& state) {
            Dataset& ds = dataset(d, n);
            const float r = radius(ds);
            BruteQuery q{&ds.points, {}};
            verify(ds, m, r, q, "brute");
            run_queries(state, ds, m, r, q);
        })->Unit(benchmark::kMicrosecond)->MinTime(0.25);
    }
}

}  // namespace

int main(int argc, char** argv) {
    bool quick = false;
    std::vector<char*> args;
    for (int i = 0; i < argc; ++i) {
        if (std::strcmp(argv[i], "--quick") == 0) quick = true;
        else if (std::strncmp(argv[i], "--photon_leaf=", 14) == 0) photon_config.max_leaf_size = std::uint32_t(std::atoi(argv[i] + 14));
        else args.push_back(argv[i]);
    }
    std::vector<std::size_t> sizes = {10'000, 100'000, 1'000'000};
    if (!quick) sizes.push_back(4'000'000);
    const std::size_t ks[] = {50, 200, 1000};
    for (Distribution d : {Distribution::cornell, Distribution::cube}) {
        for (std::size_t n : sizes) {
            register_build(d, n);
            for (bool capped : {true, false})
                for (std::size_t k : ks) register_queries(d, n, {k, capped}, n <= 10'000);
        }
    }
    int count = int(args.size());
    benchmark::Initialize(&count, args.data());
    if (benchmark::ReportUnrecognizedArguments(count, args.data())) return 1;
    photon::bench::RatioTable reporter;
    benchmark::RunSpecifiedBenchmarks(&reporter);
    benchmark::Shutdown();
    return 0;
}
