// SPDX-License-Identifier: MIT
#pragma once
// `mpirun -n N photon render ...`: the ranks of an MPI launch share the render (photon/distributed/),
// rank 0 alone reports and writes. Without PHOTON_MPI, or started without a launcher, there is
// no share and photon renders in this one process.

#include <photon/parallel/work_share.hpp>

#include <memory>
#include <string>

namespace photon::cli {

/// The ranks sharing this render, or null when this process renders alone.
[[nodiscard]] std::unique_ptr<photon::WorkShare> open_work_share();

/// Reports `what` went wrong on this rank and stops every rank (mpirun then exits non-zero).
[[noreturn]] void abort_ranks(photon::WorkShare& share, const char* what);

/// The bytes and time each phase's exchanges took on each rank, as lines for the statistics
/// (a collective: every rank calls it; only rank 0 gets the text).
[[nodiscard]] std::string exchange_stats(photon::WorkShare& share);

}  // namespace photon::cli
