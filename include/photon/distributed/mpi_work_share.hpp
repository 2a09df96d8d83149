// SPDX-License-Identifier: MIT
#pragma once
// A WorkShare (parallel/work_share.hpp) over MPI: the ranks of MPI_COMM_WORLD share one render,
// every exchange an MPI_Allgather of the sizes and an MPI_Allgatherv of the bytes. This header
// is the only part of photon that includes <mpi.h>; link photon::distributed (CMake option
// PHOTON_MPI) to use it. It counts the bytes each exchange moves, per phase, for the statistics.
//
//   photon::distributed::MpiWorkShare share;   // MPI_Init unless already initialised
//   settings.share = &share;
//   auto result = photon::render(scene, camera, settings);   // the whole image on every rank
//   if (share.rank() == 0) write(result.film);

// The C API only: not the deprecated C++ bindings some MPIs pull in (and link) by default.
#ifndef OMPI_SKIP_MPICXX
#define OMPI_SKIP_MPICXX 1
#endif
#ifndef MPICH_SKIP_MPICXX
#define MPICH_SKIP_MPICXX 1
#endif
#include <mpi.h>

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <limits>
#include <map>
#include <stdexcept>
#include <string>

#include "../parallel/work_share.hpp"

namespace photon::distributed {

/// What one phase's exchanges moved, as seen by one rank.
struct ExchangeCount {
    std::uint64_t calls = 0;
    std::uint64_t sent = 0;      ///< bytes this rank contributed (each delivered to every other rank)
    std::uint64_t received = 0;  ///< bytes it got from the other ranks
    double seconds = 0;          ///< time in the exchange, waiting for slower ranks included
};

/// Whether this process was started by an MPI launcher (mpirun, srun) rather than by hand: a
/// program started alone stays out of MPI entirely (no singleton start-up).
[[nodiscard]] inline bool launched_by_mpi() noexcept {
    for (const char* v : {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE", "PMIX_RANK", "MPI_LOCALNRANKS"})
        if (std::getenv(v)) return true;
    return false;
}

class MpiWorkShare final : public WorkShare {
public:
    MpiWorkShare() {
        int initialised = 0;
        MPI_Initialized(&initialised);
        if (!initialised) {
            MPI_Init(nullptr, nullptr);
            owns_mpi_ = true;
        }
        int r = 0, n = 1;
        MPI_Comm_rank(MPI_COMM_WORLD, &r);
        MPI_Comm_size(MPI_COMM_WORLD, &n);
        rank_ = unsigned(r), ranks_ = unsigned(n);
    }
    MpiWorkShare(const MpiWorkShare&) = delete;
    MpiWorkShare& operator=(const MpiWorkShare&) = delete;
    /// Unwinding from an exception on one rank while the others wait in an exchange would hang
    /// them: abort the whole job instead, which makes mpirun exit non-zero.
    ~MpiWorkShare() override {
        if (!owns_mpi_) return;
        if (std::uncaught_exceptions() > 0) {
            std::fprintf(stderr, "photon: rank %u of %u failed: aborting every rank\n", rank_, ranks_);
            MPI_Abort(MPI_COMM_WORLD, 1);
        }
        MPI_Finalize();
    }

    [[nodiscard]] unsigned rank() const noexcept override { return rank_; }
    [[nodiscard]] unsigned ranks() const noexcept override { return ranks_; }

    [[nodiscard]] std::vector<std::vector<std::byte>> all_gather(std::span<const std::byte> mine, const char* phase) override {
        const auto start = std::chrono::steady_clock::now();
        // MPI counts are int: larger exchanges go in pieces of at most 1 GiB per rank.
        constexpr std::uint64_t piece = std::uint64_t(1) << 30;
        const std::uint64_t size = mine.size();
        std::vector<std::uint64_t> sizes(ranks_);
        check(MPI_Allgather(&size, 1, MPI_UINT64_T, sizes.data(), 1, MPI_UINT64_T, MPI_COMM_WORLD), "size exchange");
        std::vector<std::vector<std::byte>> all(ranks_);
        for (unsigned r = 0; r < ranks_; ++r) all[r].resize(sizes[r]);
        std::uint64_t most = 0;
        for (auto s : sizes) most = std::max(most, s);
        std::vector<int> counts(ranks_), offsets(ranks_);
        std::vector<std::byte> buffer;
        for (std::uint64_t at = 0; at < most || at == 0; at += piece) {
            int total = 0;
            for (unsigned r = 0; r < ranks_; ++r) {
                counts[r] = int(sizes[r] > at ? std::min(piece, sizes[r] - at) : 0);
                offsets[r] = total;
                total += counts[r];
            }
            buffer.resize(std::size_t(total));
            check(MPI_Allgatherv(mine.data() + std::min(at, size), counts[rank_], MPI_BYTE, buffer.data(), counts.data(),
                                 offsets.data(), MPI_BYTE, MPI_COMM_WORLD),
                  phase);
            for (unsigned r = 0; r < ranks_; ++r)
                std::copy_n(buffer.data() + offsets[r], counts[r], all[r].data() + at);
            if (most == 0) break;
        }
        ExchangeCount& c = counts_[phase];
        ++c.calls;
        c.sent += size;
        for (unsigned r = 0; r < ranks_; ++r)
            if (r != rank_) c.received += sizes[r];
        c.seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        return all;
    }

    /// This rank's exchanges so far, by phase.
    [[nodiscard]] const std::map<std::string, ExchangeCount>& counts() const noexcept { return counts_; }

    /// Every rank's counts of `phase` on rank 0 (a collective), indexed by rank; empty elsewhere.
    [[nodiscard]] std::vector<ExchangeCount> counts_by_rank(const std::string& phase) {
        const ExchangeCount mine = counts_.count(phase) ? counts_.at(phase) : ExchangeCount{};
        std::vector<ExchangeCount> all(rank_ == 0 ? ranks_ : 0);
        check(MPI_Gather(&mine, sizeof mine, MPI_BYTE, all.data(), sizeof mine, MPI_BYTE, 0, MPI_COMM_WORLD), "statistics");
        return all;
    }

private:
    static void check(int code, const char* what) {
        if (code == MPI_SUCCESS) return;
        char text[MPI_MAX_ERROR_STRING];
        int length = 0;
        MPI_Error_string(code, text, &length);
        throw std::runtime_error(std::string("MPI exchange (") + what + ") failed: " + std::string(text, std::size_t(length)));
    }

    unsigned rank_ = 0, ranks_ = 1;
    bool owns_mpi_ = false;
    std::map<std::string, ExchangeCount> counts_;
};

}  // namespace photon::distributed
