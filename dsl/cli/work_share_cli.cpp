// SPDX-License-Identifier: MIT
#include "work_share_cli.hpp"

#if defined(PHOTON_HAS_MPI) && PHOTON_HAS_MPI
#include <photon/distributed/mpi_work_share.hpp>
#endif

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <vector>

namespace photon::cli {

#if defined(PHOTON_HAS_MPI) && PHOTON_HAS_MPI

std::unique_ptr<photon::WorkShare> open_work_share() {
    if (!photon::distributed::launched_by_mpi()) return nullptr;
    return std::make_unique<photon::distributed::MpiWorkShare>();
}

void abort_ranks(photon::WorkShare& share, const char* what) {
    std::fprintf(stderr, "photon: error on rank %u of %u, stopping every rank: %s\n", share.rank(), share.ranks(), what);
    std::fflush(stderr);
    MPI_Abort(MPI_COMM_WORLD, 1);
    std::abort();  // MPI_Abort does not return
}

std::string exchange_stats(photon::WorkShare& share) {
    if (share.ranks() == 1) return "exchanges (1 rank): none\n";
    auto& mpi = dynamic_cast<photon::distributed::MpiWorkShare&>(share);
    std::string out;
    char line[200];
    std::snprintf(line, sizeof line, "exchanges (%u ranks; per phase, smallest..largest over the ranks)\n", mpi.ranks());
    out += line;
    // Every rank ran the same exchanges, so the phases of rank 0's counts are every rank's.
    std::vector<std::string> phases;
    for (const auto& [phase, count] : mpi.counts()) phases.push_back(phase);
    for (const std::string& phase : phases) {
        const auto all = mpi.counts_by_rank(phase);
        if (all.empty()) continue;  // not rank 0
        std::uint64_t lo = all[0].sent, hi = all[0].sent;
        double fastest = all[0].seconds, slowest = all[0].seconds;
        for (const auto& c : all) {
            lo = std::min(lo, c.sent), hi = std::max(hi, c.sent);
            fastest = std::min(fastest, c.seconds), slowest = std::max(slowest, c.seconds);
        }
        // The time in an exchange includes the wait for the slowest rank: its spread is the imbalance.
        std::snprintf(line, sizeof line, "  %-18s %5llu calls  %11llu..%llu bytes sent  %.3f..%.3f s in the exchange\n",
                      phase.c_str(), (unsigned long long)all[0].calls, (unsigned long long)lo, (unsigned long long)hi, fastest,
                      slowest);
        out += line;
    }
    return share.rank() == 0 ? out : std::string();
}

#else

std::unique_ptr<photon::WorkShare> open_work_share() { return nullptr; }
std::string exchange_stats(photon::WorkShare&) { return {}; }
void abort_ranks(photon::WorkShare& share, const char* what) {
    std::fprintf(stderr, "photon: error on rank %u of %u: %s\n", share.rank(), share.ranks(), what);
    std::abort();
}

#endif

}  // namespace photon::cli
