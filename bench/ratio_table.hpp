// SPDX-License-Identifier: MIT
#pragma once
// A Google Benchmark reporter for the kd-tree benchmark: prints the usual console lines, and at
// the end Markdown tables of photon / nanoflann ratios, ready for bench/README.md.
//
// Names it understands (what kdtree_bench.cpp registers):
//   build/<dist>/<n>/<impl>          impl = photon | photon-2threads | nanoflann_L<leaf>
//   query/<dist>/<n>/<mode>/<impl>   mode = k<k>r (capped by a radius) | k<k> (plain k-nearest)
//                                    impl = photon | nanoflann_L<leaf> | nanoflann-presorted_L10 | brute

#include <benchmark/benchmark.h>

#include <algorithm>
#include <cstdio>
#include <map>
#include <string>
#include <vector>

namespace photon::bench {

class RatioTable : public benchmark::ConsoleReporter {
public:
    void ReportRuns(const std::vector<Run>& runs) override {
        ConsoleReporter::ReportRuns(runs);
        for (const Run& run : runs) {
            if (run.error_occurred) continue;
            // With repetitions keep the median; without, the single run. CPU time, except for
            // benchmarks that asked for wall time (multi-threaded ones).
            if (run.run_type == Run::RT_Aggregate && run.aggregate_name != "median") continue;
            if (run.run_type == Run::RT_Iteration && run.repetitions > 1) continue;
            Result r;
            const bool wall = run.run_name.time_type.find("real_time") != std::string::npos;
            r.seconds = (wall ? run.GetAdjustedRealTime() : run.GetAdjustedCPUTime()) * time_unit_seconds(run.time_unit);
            for (const auto& [key, counter] : run.counters) r.counters[key] = counter.value;
            results_[split_name(run.run_name.function_name)] = r;
        }
    }

    void Finalize() override {
        ConsoleReporter::Finalize();
        std::FILE* out = stdout;
        std::fflush(out);
        print_query_tables(out);
        print_build_table(out);
        print_memory_table(out);
        std::fflush(out);
    }

private:
    struct Result {
        double seconds = 0;
        std::map<std::string, double> counters;
    };
    using Key = std::vector<std::string>;

    static double time_unit_seconds(benchmark::TimeUnit u) {
        switch (u) {
        case benchmark::kNanosecond: return 1e-9;
        case benchmark::kMicrosecond: return 1e-6;
        case benchmark::kMillisecond: return 1e-3;
        default: return 1.0;
        }
    }
    static Key split_name(const std::string& name) {
        Key parts;
        std::size_t start = 0;
        while (true) {
            const std::size_t slash = name.find('/', start);
            parts.push_back(name.substr(start, slash - start));
            if (slash == std::string::npos) break;
            start = slash + 1;
        }
        return parts;
    }
    const Result* find(const Key& key) const {
        auto it = results_.find(key);
        return it == results_.end() ? nullptr : &it->second;
    }
    // Rows (dist, n) and columns (mode) in first-seen order.
    template <class F> void for_each_row(const std::string& kind, F f) const {
        std::vector<std::pair<std::string, std::string>> rows;
        for (const auto& [key, r] : results_) {
            if (key.size() < 4 || key[0] != kind) continue;
            std::pair<std::string, std::string> row{key[1], key[2]};
            if (std::find(rows.begin(), rows.end(), row) == rows.end()) rows.push_back(row);
        }
        std::stable_sort(rows.begin(), rows.end(), [](const auto& a, const auto& b) {
            return a.first != b.first ? a.first < b.first : std::stoull(a.second) < std::stoull(b.second);
        });
        for (const auto& [dist, n] : rows) f(dist, n);
    }
    std::vector<std::string> modes() const {
        std::vector<std::string> m;
        for (const auto& [key, r] : results_)
            if (key.size() == 5 && key[0] == "query" && std::find(m.begin(), m.end(), key[3]) == m.end()) m.push_back(key[3]);
        // Radius-capped first, then by k.
        std::sort(m.begin(), m.end(), [](const std::string& a, const std::string& b) {
            const bool ra = a.back() == 'r', rb = b.back() == 'r';
            if (ra != rb) return ra;
            return std::stoul(a.substr(1)) < std::stoul(b.substr(1));
        });
        return m;
    }
    std::vector<std::string> nano_impls(const std::string& kind) const {
        std::vector<std::string> m;
        for (const auto& [key, r] : results_)
            if (key[0] == kind && key.back().rfind("nanoflann_L", 0) == 0 && std::find(m.begin(), m.end(), key.back()) == m.end())
                m.push_back(key.back());
        std::sort(m.begin(), m.end(), [](const std::string& a, const std::string& b) {
            return std::stoul(a.substr(11)) < std::stoul(b.substr(11));
        });
        return m;
    }
    static std::string pretty_n(const std::string& n) {
        const unsigned long long v = std::stoull(n);
        char buf[32];
        if (v >= 1000000 && v % 1000000 == 0) std::snprintf(buf, sizeof buf, "%lluM", v / 1000000);
        else if (v >= 1000 && v % 1000 == 0) std::snprintf(buf, sizeof buf, "%lluk", v / 1000);
        else std::snprintf(buf, sizeof buf, "%llu", v);
        return buf;
    }
    static std::string pretty_mode(const std::string& m) {
        return m.back() == 'r' ? "k=" + m.substr(1, m.size() - 2) + " r<rmax" : "k=" + m.substr(1) + " no r";
    }

    void print_query_tables(std::FILE* out) const {
        const auto ms = modes();
        if (ms.empty()) return;
        const auto nanos = nano_impls("query");
        const std::string base = "nanoflann_L10";
        auto header = [&](const char* title, const char* first) {
            std::fprintf(out, "\n%s\n\n| %s |", title, first);
            for (const auto& m : ms) std::fprintf(out, " %s |", pretty_mode(m).c_str());
            std::fprintf(out, "\n|---|");
            for (std::size_t i = 0; i < ms.size(); ++i) std::fprintf(out, "---:|");
            std::fprintf(out, "\n");
        };
        auto qps = [](const Result* r) { return r ? 1.0 / r->seconds : 0.0; };

        header("Query throughput ratio photon / nanoflann (leaf 10, its default); higher is better", "points");
        for_each_row("query", [&](const std::string& dist, const std::string& n) {
            std::fprintf(out, "| %s %s |", dist.c_str(), pretty_n(n).c_str());
            for (const auto& m : ms) {
                const Result* p = find({"query", dist, n, m, "photon"});
                const Result* f = find({"query", dist, n, m, base});
                if (p && f) std::fprintf(out, " %.2fx |", qps(p) / qps(f));
                else std::fprintf(out, " - |");
            }
            std::fprintf(out, "\n");
        });

        header("Query throughput ratio photon / nanoflann at its best leaf size for that cell (leaf in brackets)", "points");
        for_each_row("query", [&](const std::string& dist, const std::string& n) {
            std::fprintf(out, "| %s %s |", dist.c_str(), pretty_n(n).c_str());
            for (const auto& m : ms) {
                const Result* p = find({"query", dist, n, m, "photon"});
                double best = 0;
                std::string best_impl;
                for (const auto& impl : nanos)
                    if (const Result* f = find({"query", dist, n, m, impl}); f && qps(f) > best) {
                        best = qps(f);
                        best_impl = impl.substr(11);
                    }
                if (p && best > 0) std::fprintf(out, " %.2fx (%s) |", qps(p) / best, best_impl.c_str());
                else std::fprintf(out, " - |");
            }
            std::fprintf(out, "\n");
        });

        header("For reference: photon / nanoflann (leaf 10) reading records pre-sorted in photon's tree order", "points");
        for_each_row("query", [&](const std::string& dist, const std::string& n) {
            std::fprintf(out, "| %s %s |", dist.c_str(), pretty_n(n).c_str());
            for (const auto& m : ms) {
                const Result* p = find({"query", dist, n, m, "photon"});
                const Result* f = find({"query", dist, n, m, "nanoflann-presorted_L10"});
                if (p && f) std::fprintf(out, " %.2fx |", qps(p) / qps(f));
                else std::fprintf(out, " - |");
            }
            std::fprintf(out, "\n");
        });

        header("Queries per second, thousands: photon / nanoflann leaf 10 / brute force where run", "points");
        for_each_row("query", [&](const std::string& dist, const std::string& n) {
            std::fprintf(out, "| %s %s |", dist.c_str(), pretty_n(n).c_str());
            for (const auto& m : ms) {
                const Result* p = find({"query", dist, n, m, "photon"});
                const Result* f = find({"query", dist, n, m, base});
                const Result* b = find({"query", dist, n, m, "brute"});
                std::string cell = p ? fmt(qps(p) / 1e3) : "-";
                cell += " / " + (f ? fmt(qps(f) / 1e3) : std::string("-"));
                if (b) cell += " / " + fmt(qps(b) / 1e3);
                std::fprintf(out, " %s |", cell.c_str());
            }
            std::fprintf(out, "\n");
        });

        header("Max radius of the capped queries, and the share of queries that reach it (k-th neighbour farther)", "points");
        for_each_row("query", [&](const std::string& dist, const std::string& n) {
            std::fprintf(out, "| %s %s |", dist.c_str(), pretty_n(n).c_str());
            for (const auto& m : ms) {
                const Result* p = find({"query", dist, n, m, "photon"});
                if (p && p->counters.count("rmax") && m.back() == 'r')
                    std::fprintf(out, " %.4g (%.0f%%) |", p->counters.at("rmax"), 100.0 * p->counters.at("capped"));
                else std::fprintf(out, " - |");
            }
            std::fprintf(out, "\n");
        });
    }

    void print_build_table(std::FILE* out) const {
        const auto nanos = nano_impls("build");
        bool any = false;
        for_each_row("build", [&](const std::string&, const std::string&) { any = true; });
        if (!any) return;
        std::fprintf(out, "\nBuild time in ms, one thread (ratio = nanoflann / photon, higher is better for photon)\n\n| points | photon |");
        for (const auto& impl : nanos) std::fprintf(out, " nanoflann leaf %s |", impl.substr(11).c_str());
        std::fprintf(out, " ratio vs leaf 10 | photon, 2 threads (wall) |\n|---|---:|");
        for (std::size_t i = 0; i <= nanos.size() + 1; ++i) std::fprintf(out, "---:|");
        std::fprintf(out, "\n");
        for_each_row("build", [&](const std::string& dist, const std::string& n) {
            const Result* p = find({"build", dist, n, "photon"});
            std::fprintf(out, "| %s %s | %s |", dist.c_str(), pretty_n(n).c_str(), p ? fmt(p->seconds * 1e3).c_str() : "-");
            for (const auto& impl : nanos) {
                const Result* f = find({"build", dist, n, impl});
                std::fprintf(out, " %s |", f ? fmt(f->seconds * 1e3).c_str() : "-");
            }
            const Result* f = find({"build", dist, n, "nanoflann_L10"});
            if (p && f) std::fprintf(out, " %.2fx |", f->seconds / p->seconds);
            else std::fprintf(out, " - |");
            const Result* t = find({"build", dist, n, "photon-2threads"});
            std::fprintf(out, " %s |\n", t ? fmt(t->seconds * 1e3).c_str() : "-");
        });
    }

    void print_memory_table(std::FILE* out) const {
        const auto nanos = nano_impls("build");
        bool any = false;
        for_each_row("build", [&](const std::string&, const std::string&) { any = true; });
        if (!any) return;
        std::fprintf(out, "\nBytes per point (photon: KdTree<Photon>::memory_bytes()/N, everything it holds; nanoflann: its "
                          "index, + 24 for the photon records it reads and needs alive)\n\n| points | photon |");
        for (const auto& impl : nanos) std::fprintf(out, " nanoflann leaf %s |", impl.substr(11).c_str());
        std::fprintf(out, "\n|---|---:|");
        for (std::size_t i = 0; i < nanos.size(); ++i) std::fprintf(out, "---:|");
        std::fprintf(out, "\n");
        for_each_row("build", [&](const std::string& dist, const std::string& n) {
            const Result* p = find({"build", dist, n, "photon"});
            std::fprintf(out, "| %s %s | %s |", dist.c_str(), pretty_n(n).c_str(),
                         p && p->counters.count("B/pt") ? fmt(p->counters.at("B/pt")).c_str() : "-");
            for (const auto& impl : nanos) {
                const Result* f = find({"build", dist, n, impl});
                if (f && f->counters.count("B/pt"))
                    std::fprintf(out, " %s + %s |", fmt(f->counters.at("B/pt")).c_str(), fmt(f->counters.at("records_B/pt")).c_str());
                else std::fprintf(out, " - |");
            }
            std::fprintf(out, "\n");
        });
    }

    static std::string fmt(double v) {
        char buf[32];
        if (v >= 100) std::snprintf(buf, sizeof buf, "%.0f", v);
        else if (v >= 10) std::snprintf(buf, sizeof buf, "%.1f", v);
        else std::snprintf(buf, sizeof buf, "%.2f", v);
        return buf;
    }

    std::map<Key, Result> results_;
};

}  // namespace photon::bench
