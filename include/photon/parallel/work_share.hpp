// SPDX-License-Identifier: MIT
#pragma once
// One render's work shared among processes (ranks), with no dependency on any transport: the
// library asks a WorkShare which units of work are this rank's, and to exchange what each rank
// computed, and assembles the results in the order one process would have produced them. The
// units are those the library already draws its random streams from (photon blocks, pixels and
// rows, sample indices), so every rank's part is bit-identical to the same part of a one-process
// render, and so is the whole. The base class is the one process: everything is its own and an
// exchange returns its own bytes. photon/distributed/ has the MPI implementation.

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <span>
#include <type_traits>
#include <vector>

#include "../math/rng.hpp"

namespace photon {

class WorkShare {
public:
    virtual ~WorkShare() = default;
    [[nodiscard]] virtual unsigned rank() const noexcept { return 0; }
    [[nodiscard]] virtual unsigned ranks() const noexcept { return 1; }
    /// Every rank's `mine`, in rank order, on every rank (a collective: every rank calls it, in
    /// the same order). `phase` names the exchange in the byte counts.
    [[nodiscard]] virtual std::vector<std::vector<std::byte>> all_gather(std::span<const std::byte> mine,
                                                                         const char* phase) {
        (void)phase;
        return {std::vector<std::byte>(mine.begin(), mine.end())};
    }
};

/// Whether `share` is absent or a single process: nothing to split.
[[nodiscard]] inline bool single(const WorkShare* share) noexcept { return !share || share->ranks() <= 1; }

/// How units are dealt to the ranks.
enum class Deal {
    /// Round-robin, unit u to rank u mod N: neighbouring rows or blocks cost about the same, so
    /// each rank gets an even share of cheap and dear ones.
    interleaved,
    /// By a hash of the unit: for units whose cost follows a lattice that an interleave would
    /// line up with. The irradiance cache's last level is one: its pixels in odd rows and columns
    /// are the level before's samples and need no gather, so round-robin over rows of even width
    /// (even columns to rank 0) gave rank 0 2,376 gathers and rank 1 1,718 (room 1, 400 x 300).
    hashed,
};

/// The rank that computes unit `unit` under `deal`.
[[nodiscard]] inline unsigned owner(const WorkShare* share, std::size_t unit, Deal deal = Deal::interleaved) noexcept {
    if (single(share)) return 0;
    const std::uint64_t key = deal == Deal::hashed ? mix64(unit) : unit;
    return unsigned(key % share->ranks());
}

/// Whether unit `unit` is this rank's under `deal`.
[[nodiscard]] inline bool owns(const WorkShare* share, std::size_t unit, Deal deal = Deal::interleaved) noexcept {
    return single(share) || owner(share, unit, deal) == share->rank();
}

/// How many of units [0, units) are this rank's (for progress reports).
[[nodiscard]] inline std::size_t owned_count(const WorkShare* share, std::size_t units) noexcept {
    if (single(share)) return units;
    return units > share->rank() ? (units - share->rank() + share->ranks() - 1) / share->ranks() : 0;
}

namespace detail {

template <class T> void append_bytes(std::vector<std::byte>& out, std::span<const T> items) {
    static_assert(std::is_trivially_copyable_v<T>);
    const auto* p = reinterpret_cast<const std::byte*>(items.data());
    out.insert(out.end(), p, p + items.size_bytes());
}

template <class T> [[nodiscard]] T read_one(const std::vector<std::byte>& in, std::size_t& at) {
    T v;
    std::memcpy(&v, in.data() + at, sizeof(T));
    at += sizeof(T);
    return v;
}

}  // namespace detail

/// Per-unit lists (unit u computed by the rank that owns it under `deal`, empty elsewhere) made
/// whole on every rank: each rank sends its units' sizes and items, and every rank puts them back
/// at their units.
template <class T>
void share_lists(WorkShare* share, std::vector<std::vector<T>>& lists, const char* phase,
                 Deal deal = Deal::interleaved) {
    if (single(share)) return;
    std::vector<std::byte> mine;
    for (std::size_t u = 0; u < lists.size(); ++u) {
        if (!owns(share, u, deal)) continue;
        const std::uint64_t n = lists[u].size();
        detail::append_bytes(mine, std::span<const std::uint64_t>(&n, 1));
        detail::append_bytes(mine, std::span<const T>(lists[u]));
    }
    const auto all = share->all_gather(mine, phase);
    std::vector<std::size_t> at(share->ranks(), 0);  // read position in each rank's bytes
    for (std::size_t u = 0; u < lists.size(); ++u) {
        const unsigned r = owner(share, u, deal);
        if (r == share->rank()) continue;
        const auto n = detail::read_one<std::uint64_t>(all[r], at[r]);
        lists[u].resize(n);
        if (n == 0) continue;  // an empty list's data() may be null, which memcpy must not see
        std::memcpy(lists[u].data(), all[r].data() + at[r], n * sizeof(T));
        at[r] += n * sizeof(T);
    }
}

/// Fixed-size runs of `run` items (unit u: items [u * run, (u + 1) * run), the last run may be
/// shorter), unit u computed by the rank that owns it, made whole on every rank: an image's rows,
/// one value per sample.
template <class T>
void share_runs(WorkShare* share, std::span<T> items, std::size_t run, const char* phase) {
    if (single(share) || run == 0) return;
    const std::size_t units = (items.size() + run - 1) / run;
    auto unit = [&](std::size_t u) { return items.subspan(u * run, std::min(run, items.size() - u * run)); };
    std::vector<std::byte> mine;
    for (std::size_t u = share->rank(); u < units; u += share->ranks()) detail::append_bytes(mine, std::span<const T>(unit(u)));
    const auto all = share->all_gather(mine, phase);
    for (unsigned r = 0; r < share->ranks(); ++r) {
        if (r == share->rank()) continue;
        std::size_t at = 0;
        for (std::size_t u = r; u < units; u += share->ranks()) {
            const auto dst = unit(u);
            if (dst.empty()) continue;
            std::memcpy(dst.data(), all[r].data() + at, dst.size_bytes());
            at += dst.size_bytes();
        }
    }
}

/// Rank 0's `value` on every rank: a decision (stop now?) that only one rank may take.
template <class T> [[nodiscard]] T agree(WorkShare* share, T value, const char* phase) {
    if (single(share)) return value;
    const auto all = share->all_gather(std::span<const std::byte>(reinterpret_cast<const std::byte*>(&value), sizeof(T)), phase);
    std::memcpy(&value, all[0].data(), sizeof(T));
    return value;
}

/// Counts (rays, estimates) summed over the ranks, on every rank.
template <class T> [[nodiscard]] T sum_over_ranks(WorkShare* share, T value, const char* phase) {
    if (single(share)) return value;
    const auto all = share->all_gather(std::span<const std::byte>(reinterpret_cast<const std::byte*>(&value), sizeof(T)), phase);
    T total{};
    for (const auto& b : all) {
        T v;
        std::memcpy(&v, b.data(), sizeof(T));
        total += v;
    }
    return total;
}

}  // namespace photon
