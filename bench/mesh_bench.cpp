// SPDX-License-Identifier: MIT
// photon::TriangleMesh (its BVH) against Embree 3 on the same million-triangle mesh and the same
// rays, single-threaded, one ray at a time: build time (on one thread, and on all cores), memory,
// and closest-hit and any-hit throughput for coherent primary rays and incoherent random rays. Before timing, both must
// agree on every checked ray (hit or miss, and t), or the run stops.
//
//   mesh_bench [--quick] [--photon_leaf=<n>] [--photon_bins=<n>] [--photon_cost=<x>] [google benchmark flags]
//
// --quick uses a 100k-triangle mesh. At the end, a Markdown table of rays/s and ratios.

#include <benchmark/benchmark.h>
#include <embree3/rtcore.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <map>
#include <memory>
#include <string>
#include <thread>
#include <vector>

#include "mesh_bench_data.hpp"
#include "photon/geometry/triangle_mesh.hpp"

namespace {

using photon::Ray;
using photon::Vec3;
using Mesh = photon::TriangleMesh<float>;

int grid_n = 289;  // 12 n^2 triangles: 1,002,252
photon::BvhConfig photon_config{.threads = 1};  // build-all-cores/photon sets 0
constexpr int image_res = 1024;                     // primary rays: 1M
constexpr std::size_t random_count = std::size_t(1) << 20;
constexpr std::size_t check_count = std::size_t(1) << 18;  // rays per set compared before timing

// ---- Embree -----------------------------------------------------------------------------------

/// One Embree device with `threads` build threads (0: all cores) and a memory monitor (net bytes
/// allocated).
struct EmbreeDevice {
    RTCDevice device = nullptr;
    long long bytes = 0;
    explicit EmbreeDevice(int threads) {
        // EMBREE_CONFIG adds to the configuration, e.g. EMBREE_CONFIG=hugepages=1.
        const char* extra = std::getenv("EMBREE_CONFIG");
        const std::string config =
            "threads=" + std::to_string(threads) + (extra ? std::string(",") + extra : std::string());
        device = rtcNewDevice(config.c_str());
        if (!device) {
            std::fprintf(stderr, "embree: rtcNewDevice failed (%d)\n", int(rtcGetDeviceError(nullptr)));
            std::exit(1);
        }
        rtcSetDeviceMemoryMonitorFunction(
            device,
            [](void* user, ssize_t delta, bool) {
                *static_cast<long long*>(user) += delta;
                return true;
            },
            &bytes);
    }
    ~EmbreeDevice() { rtcReleaseDevice(device); }
};

struct EmbreeScene {
    RTCScene scene = nullptr;
    long long bytes = 0;  ///< everything the device allocated for it, vertex and index copies included
    EmbreeScene(EmbreeDevice& dev, const photon::bench::MeshData& m, RTCBuildQuality quality) {
        const long long before = dev.bytes;
        scene = rtcNewScene(dev.device);
        rtcSetSceneBuildQuality(scene, quality);
        RTCGeometry geom = rtcNewGeometry(dev.device, RTC_GEOMETRY_TYPE_TRIANGLE);
        rtcSetGeometryBuildQuality(geom, quality);
        // Embree reads 16 bytes per vertex: its buffers get one padding float at the end.
        auto* v = static_cast<float*>(rtcSetNewGeometryBuffer(geom, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3,
                                                              3 * sizeof(float), m.positions.size()));
        std::memcpy(v, m.positions.data(), m.positions.size() * sizeof(Vec3<float>));
        auto* idx = static_cast<unsigned*>(rtcSetNewGeometryBuffer(geom, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3,
                                                                   3 * sizeof(unsigned), m.triangles.size()));
        std::memcpy(idx, m.triangles.data(), m.triangles.size() * 3 * sizeof(unsigned));
        rtcCommitGeometry(geom);
        rtcAttachGeometry(scene, geom);
        rtcReleaseGeometry(geom);
        rtcCommitScene(scene);
        bytes = dev.bytes - before;
    }
    EmbreeScene(const EmbreeScene&) = delete;
    EmbreeScene& operator=(const EmbreeScene&) = delete;
    ~EmbreeScene() { rtcReleaseScene(scene); }

    /// Distance to the closest hit, or +inf.
    [[nodiscard]] float intersect(const Ray<float>& r) const {
        RTCIntersectContext context;
        rtcInitIntersectContext(&context);
        RTCRayHit rh;
        rh.ray.org_x = r.origin.x, rh.ray.org_y = r.origin.y, rh.ray.org_z = r.origin.z;
        rh.ray.dir_x = r.direction.x, rh.ray.dir_y = r.direction.y, rh.ray.dir_z = r.direction.z;
        rh.ray.tnear = 0.0f;
        rh.ray.tfar = r.t_max;
        rh.ray.time = 0.0f;
        rh.ray.mask = ~0u;
        rh.ray.id = 0;
        rh.ray.flags = 0;
        rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
        rtcIntersect1(scene, &context, &rh);
        return rh.hit.geomID == RTC_INVALID_GEOMETRY_ID ? INFINITY : rh.ray.tfar;
    }
    [[nodiscard]] bool occluded(const Ray<float>& r) const {
        RTCIntersectContext context;
        rtcInitIntersectContext(&context);
        RTCRay ray;
        ray.org_x = r.origin.x, ray.org_y = r.origin.y, ray.org_z = r.origin.z;
        ray.dir_x = r.direction.x, ray.dir_y = r.direction.y, ray.dir_z = r.direction.z;
        ray.tnear = 0.0f;
        ray.tfar = r.t_max;
        ray.time = 0.0f;
        ray.mask = ~0u;
        ray.id = 0;
        ray.flags = 0;
        rtcOccluded1(scene, &context, &ray);
        return ray.tfar < 0.0f;  // Embree sets tfar to -inf on a hit
    }
};

// ---- data shared by the benchmarks ------------------------------------------------------------

struct World {
    photon::bench::MeshData data;
    std::vector<Ray<float>> primary, random;
    // The random rays, cut at the photon hit distance (or at 4), for any-hit queries that
    // do not stop at the first box: half end just short of the surface, like shadow rays.
    std::vector<Ray<float>> shadow;
    std::unique_ptr<Mesh> mesh;
    EmbreeDevice device{1};
    std::unique_ptr<EmbreeDevice> all_cores_device;  // made by the first all-cores build
    std::map<int, std::unique_ptr<EmbreeScene>> embree;  // by RTCBuildQuality

    World() : data(photon::bench::displaced_sphere(grid_n)) {
        primary = photon::bench::primary_rays(image_res);
        random = photon::bench::random_rays(random_count, 20261124);
    }
    const Mesh& photon_mesh() {
        if (!mesh) mesh = std::make_unique<Mesh>(data.positions, data.triangles, photon_config);
        return *mesh;
    }
    const EmbreeScene& embree_scene(RTCBuildQuality q) {
        auto& s = embree[int(q)];
        if (!s) s = std::make_unique<EmbreeScene>(device, data, q);
        return *s;
    }
    const std::vector<Ray<float>>& shadow_rays() {
        if (shadow.empty()) {
            const Mesh& m = photon_mesh();
            shadow = random;
            for (std::size_t i = 0; i < shadow.size(); ++i) {
                const auto h = m.intersect(shadow[i]);
                shadow[i].t_max = h ? (i % 2 == 0 ? h->t * 0.999f : h->t * 1.001f) : 4.0f;
            }
        }
        return shadow;
    }
};

World& world() {
    static World w;
    return w;
}

const std::vector<Ray<float>>& rays_of(const std::string& set) {
    return set == "primary" ? world().primary : set == "random" ? world().random : world().shadow_rays();
}

RTCBuildQuality quality_of(const std::string& impl) {
    return impl == "embree-high" ? RTC_BUILD_QUALITY_HIGH : RTC_BUILD_QUALITY_MEDIUM;
}

// ---- agreement check ---------------------------------------------------------------------------

/// Closest hit over all triangles in double precision: the referee when photon and Embree differ.
double brute_force(const Ray<float>& r) {
    const auto& m = world().data;
    const Ray<double> ray{Vec3<double>(r.origin), Vec3<double>(r.direction), double(r.t_max)};
    double best = INFINITY;
    for (const auto& t : m.triangles) {
        const Vec3<double> v0(m.positions[t[0]]);
        const auto hit = photon::detail::intersect_triangle(ray, v0, Vec3<double>(m.positions[t[1]]) - v0,
                                                            Vec3<double>(m.positions[t[2]]) - v0);
        if (hit && *hit < best) best = *hit;
    }
    return best;
}

/// Photon and Embree must agree on hit or miss and on t (1e-4 relative to max(t, 1)) for the
/// first check_count rays of a set. A ray through an edge or vertex may legitimately differ; each
/// disagreement is refereed by brute force in double precision, and the run stops if photon is
/// wrong on more than 1 ray in 100,000.
void check_agreement(const std::string& set, const std::string& impl) {
    static std::map<std::string, bool> done;
    const std::string referee = impl == "embree-high" ? impl : "embree";
    if (done[set + referee]) return;
    done[set + referee] = true;
    const Mesh& mesh = world().photon_mesh();
    const EmbreeScene& es = world().embree_scene(quality_of(impl));
    const auto& rays = rays_of(set);
    const std::size_t checked = std::min(check_count, rays.size());
    std::size_t disagreements = 0, photon_wrong = 0, hits = 0;
    auto same = [](double a, double b) { return std::isinf(a) == std::isinf(b) && (std::isinf(a) || std::abs(a - b) <= 1e-4 * std::max(b, 1.0)); };
    for (std::size_t i = 0; i < checked; ++i) {
        if (set == "shadow") {
            const bool p = mesh.occluded(rays[i]);
            hits += p ? 1 : 0;
            if (p == es.occluded(rays[i])) continue;
            ++disagreements;
            photon_wrong += p != (brute_force(rays[i]) < double(rays[i].t_max)) ? 1 : 0;
            continue;
        }
        const auto h = mesh.intersect(rays[i]);
        const double tp = h ? double(h->t) : INFINITY, te = es.intersect(rays[i]);
        hits += h ? 1 : 0;
        if (same(tp, te)) continue;
        ++disagreements;
        const double exact = brute_force(rays[i]);
        photon_wrong += same(tp, exact) ? 0 : 1;
        if (std::getenv("MESH_BENCH_VERBOSE"))
            std::fprintf(stderr, "  ray %zu: o=(%.9g %.9g %.9g) d=(%.9g %.9g %.9g) photon t=%.9g embree t=%.9g exact %.9g\n",
                         i, rays[i].origin.x, rays[i].origin.y, rays[i].origin.z, rays[i].direction.x,
                         rays[i].direction.y, rays[i].direction.z, tp, te, exact);
    }
    std::fprintf(stderr, "check %s rays, photon against %s: %zu rays, %zu hits, %zu disagreements, photon wrong on %zu\n",
                 set.c_str(), referee.c_str(), checked, hits, disagreements, photon_wrong);
    if (photon_wrong * 100000 > checked) {
        std::fprintf(stderr, "photon is wrong on %zu of %zu %s rays: stopping\n", photon_wrong, checked, set.c_str());
        std::exit(1);
    }
}

// ---- the benchmarks ----------------------------------------------------------------------------

/// Rays per iteration: a contiguous slice of the set, so coherent rays stay coherent.
constexpr std::size_t batch = 1 << 14;

void trace(benchmark::State& state, const std::string& set, const std::string& impl) {
    check_agreement(set, impl);
    const auto& rays = rays_of(set);
    std::size_t next = 0, hits = 0;
    const bool any_hit = set == "shadow";
    if (impl == "photon") {
        const Mesh& mesh = world().photon_mesh();
        for (auto _ : state) {
            for (std::size_t i = 0; i < batch; ++i, next = next + 1 == rays.size() ? 0 : next + 1)
                hits += any_hit ? mesh.occluded(rays[next]) : mesh.intersect(rays[next]).has_value();
        }
    } else {
        const EmbreeScene& es = world().embree_scene(quality_of(impl));
        for (auto _ : state) {
            for (std::size_t i = 0; i < batch; ++i, next = next + 1 == rays.size() ? 0 : next + 1)
                hits += any_hit ? es.occluded(rays[next]) : std::isfinite(es.intersect(rays[next]));
        }
    }
    benchmark::DoNotOptimize(hits);
    state.SetItemsProcessed(std::int64_t(state.iterations()) * std::int64_t(batch));
}

/// Builds on one thread, or on all cores (timed by the wall clock, UseRealTime).
void build(benchmark::State& state, const std::string& impl, bool all_cores) {
    const auto& data = world().data;
    double bytes = 0;
    photon::BvhConfig config = photon_config;
    if (all_cores) config.threads = 0;
    // Embree's all-cores device is made only for its own build: its idle worker threads would
    // compete with photon's.
    const bool embree_on_all_cores = all_cores && impl != "photon";
    if (embree_on_all_cores && !world().all_cores_device) world().all_cores_device = std::make_unique<EmbreeDevice>(0);
    EmbreeDevice& device = embree_on_all_cores ? *world().all_cores_device : world().device;
    for (auto _ : state) {
        if (impl == "photon") {
            const Mesh mesh(data.positions, data.triangles, config);
            bytes = double(mesh.memory_bytes());
            benchmark::DoNotOptimize(&mesh);
        } else {
            const EmbreeScene es(device, data, quality_of(impl));
            bytes = double(es.bytes);
        }
    }
    state.counters["B/tri"] = bytes / double(data.triangles.size());
    state.counters["MiB"] = bytes / (1024.0 * 1024.0);
}

// ---- summary table -----------------------------------------------------------------------------

class Summary : public benchmark::ConsoleReporter {
public:
    void ReportRuns(const std::vector<Run>& runs) override {
        ConsoleReporter::ReportRuns(runs);
        for (const Run& run : runs) {
            if (run.error_occurred || run.run_type == Run::RT_Aggregate) continue;
            Result& r = results_[run.run_name.function_name];
            r.cpu_seconds = run.GetAdjustedCPUTime() * unit(run.time_unit);
            r.real_seconds = run.GetAdjustedRealTime() * unit(run.time_unit);
            for (const auto& [key, counter] : run.counters) r.counters[key] = counter.value;
            if (run.counters.count("items_per_second")) r.rays_per_second = run.counters.at("items_per_second").value;
        }
    }
    void Finalize() override {
        ConsoleReporter::Finalize();
        std::printf("\n| rays (%zu triangles) | photon Mrays/s | Embree Mrays/s | photon / Embree | Embree high-quality "
                    "Mrays/s | photon / Embree high |\n|---|---:|---:|---:|---:|---:|\n",
                    world().data.triangles.size());
        for (const char* set : {"primary", "random", "shadow"}) {
            const Result* p = find(std::string("trace/") + set + "/photon");
            const Result* e = find(std::string("trace/") + set + "/embree");
            const Result* h = find(std::string("trace/") + set + "/embree-high");
            if (!p) continue;
            std::printf("| %s | %.2f | %s | %s | %s | %s |\n", set, p->rays_per_second / 1e6, mrays(e).c_str(),
                        ratio(p, e).c_str(), mrays(h).c_str(), ratio(p, h).c_str());
        }
        std::printf("\n| build (one thread) | time ms | bytes per triangle | MiB |\n|---|---:|---:|---:|\n");
        for (const char* impl : {"photon", "embree", "embree-high"})
            if (const Result* r = find(std::string("build/") + impl))
                std::printf("| %s | %.0f | %.1f | %.1f |\n", impl, r->cpu_seconds * 1e3, r->counters.at("B/tri"),
                            r->counters.at("MiB"));
        const Result* p = find("build-all-cores/photon");
        const Result* e = find("build-all-cores/embree");
        if (p && e)
            std::printf("\n| build on all %u cores | photon wall ms | Embree wall ms | photon / Embree |\n|---|---:|---:|---:|\n"
                        "| default quality | %.0f | %.0f | %.2fx |\n",
                        std::thread::hardware_concurrency(), p->real_seconds * 1e3, e->real_seconds * 1e3,
                        p->real_seconds / e->real_seconds);
        std::fflush(stdout);
    }

private:
    struct Result {
        double cpu_seconds = 0, real_seconds = 0, rays_per_second = 0;
        std::map<std::string, double> counters;
    };
    static double unit(benchmark::TimeUnit u) {
        return u == benchmark::kNanosecond ? 1e-9 : u == benchmark::kMicrosecond ? 1e-6 : u == benchmark::kMillisecond ? 1e-3 : 1.0;
    }
    const Result* find(const std::string& name) const {
        const auto it = results_.find(name);
        return it == results_.end() ? nullptr : &it->second;
    }
    static std::string mrays(const Result* r) {
        char buf[32];
        std::snprintf(buf, sizeof buf, "%.2f", r ? r->rays_per_second / 1e6 : 0.0);
        return r ? buf : "-";
    }
    static std::string ratio(const Result* p, const Result* e) {
        char buf[32];
        std::snprintf(buf, sizeof buf, "%.2fx", p && e ? p->rays_per_second / e->rays_per_second : 0.0);
        return p && e ? buf : "-";
    }
    std::map<std::string, Result> results_;
};

}  // namespace

int main(int argc, char** argv) {
    std::vector<char*> args;
    for (int i = 0; i < argc; ++i) {
        if (std::strcmp(argv[i], "--quick") == 0) grid_n = 91;  // 99,372 triangles
        else if (std::strncmp(argv[i], "--photon_leaf=", 14) == 0) photon_config.max_leaf_size = unsigned(std::atoi(argv[i] + 14));
        else if (std::strncmp(argv[i], "--photon_bins=", 14) == 0) photon_config.bins = unsigned(std::atoi(argv[i] + 14));
        else if (std::strncmp(argv[i], "--photon_cost=", 14) == 0) photon_config.intersection_cost = float(std::atof(argv[i] + 14));
        else args.push_back(argv[i]);
    }
    for (const char* impl : {"photon", "embree", "embree-high"})
        benchmark::RegisterBenchmark((std::string("build/") + impl).c_str(),
                                     [impl](benchmark::State& s) { build(s, impl, false); })
            ->Unit(benchmark::kMillisecond)
            ->Iterations(impl == std::string("embree-high") ? 1 : 3);
    for (const char* impl : {"photon", "embree"})
        benchmark::RegisterBenchmark((std::string("build-all-cores/") + impl).c_str(),
                                     [impl](benchmark::State& s) { build(s, impl, true); })
            ->Unit(benchmark::kMillisecond)
            ->Iterations(10)  // the wall clock moves more than CPU time on this shared machine
            ->UseRealTime();
    for (const char* set : {"primary", "random", "shadow"})
        for (const char* impl : {"photon", "embree", "embree-high"})
            benchmark::RegisterBenchmark((std::string("trace/") + set + "/" + impl).c_str(),
                                         [set, impl](benchmark::State& s) { trace(s, set, impl); })
                ->Unit(benchmark::kMicrosecond)
                ->MinTime(1.0);
    int count = int(args.size());
    benchmark::Initialize(&count, args.data());
    Summary reporter;
    benchmark::RunSpecifiedBenchmarks(&reporter);
    benchmark::Shutdown();
    return 0;
}
