// SPDX-License-Identifier: MIT
#pragma once
// Data-parallel loops on std::thread. Work is split into fixed chunks handed out dynamically;
// results must be written by index (never appended in completion order), which is what keeps
// every pass deterministic for any thread count.

#include <algorithm>
#include <atomic>
#include <cstddef>
#include <exception>
#include <mutex>
#include <thread>
#include <vector>

namespace photon {

/// Threads to use for `requested` (0 means all hardware threads).
[[nodiscard]] inline unsigned resolve_threads(unsigned requested) noexcept {
    if (requested > 0) return requested;
    return std::max(1u, std::thread::hardware_concurrency());
}

/// Calls body(begin, end) for consecutive chunks of at most `grain` indices covering [0, count),
/// on `threads` threads (0: all). Blocks until all are done. The first exception thrown by a body
/// is rethrown here after the others finish; remaining chunks are skipped.
template <class Body>
void parallel_for(std::size_t count, std::size_t grain, unsigned threads, Body&& body) {
    if (count == 0) return;
    grain = std::max<std::size_t>(1, grain);
    const std::size_t chunks = (count + grain - 1) / grain;
    const unsigned workers = static_cast<unsigned>(std::min<std::size_t>(resolve_threads(threads), chunks));
    std::atomic<std::size_t> next{0};
    std::exception_ptr error;
    std::mutex error_mutex;
    auto work = [&] {
        for (;;) {
            const std::size_t chunk = next.fetch_add(1, std::memory_order_relaxed);
            if (chunk >= chunks) return;
            const std::size_t begin = chunk * grain;
            try {
                body(begin, std::min(count, begin + grain));
            } catch (...) {
                const std::lock_guard lock(error_mutex);
                if (!error) error = std::current_exception();
                next.store(chunks, std::memory_order_relaxed);
            }
        }
    };
    if (workers <= 1) {
        work();
    } else {
        std::vector<std::jthread> pool;
        pool.reserve(workers - 1);
        for (unsigned t = 1; t < workers; ++t) pool.emplace_back(work);
        work();
    }  // jthreads join here
    if (error) std::rethrow_exception(error);
}

}  // namespace photon
