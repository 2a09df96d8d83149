// SPDX-License-Identifier: MIT
#pragma once
// Random numbers: PCG32 (O'Neill 2014) with SplitMix64 seeding. Every photon, pixel and
// sample draws from its own stream keyed by (seed, index), so results never depend on which
// thread ran which piece of work.

#include <cstdint>

#include "vec.hpp"

namespace photon {

/// SplitMix64 finaliser (Steele et al. 2014): a strong 64-bit mixing function.
[[nodiscard]] constexpr std::uint64_t mix64(std::uint64_t x) noexcept {
    x += 0x9e3779b97f4a7c15ULL;
    x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ULL;
    x = (x ^ (x >> 27)) * 0x94d049bb133111ebULL;
    return x ^ (x >> 31);
}

/// PCG32 (XSH-RR variant): 64-bit state, 32-bit output, period 2^64 per stream.
class Pcg32 {
public:
    /// A generator for stream `stream` of the sequence selected by `seed`.
    constexpr Pcg32(std::uint64_t seed, std::uint64_t stream) noexcept
        : state_(0), inc_((mix64(stream ^ 0x5851f42d4c957f2dULL) << 1u) | 1u) {
        next_u32();
        state_ += mix64(seed + mix64(stream));
        next_u32();
    }

    constexpr std::uint32_t next_u32() noexcept {
        const std::uint64_t old = state_;
        state_ = old * 6364136223846793005ULL + inc_;
        const auto xorshifted = static_cast<std::uint32_t>(((old >> 18u) ^ old) >> 27u);
        const auto rot = static_cast<std::uint32_t>(old >> 59u);
        return (xorshifted >> rot) | (xorshifted << ((32u - rot) & 31u));
    }

    /// Uniform in [0, 1), never 1 (24 random bits for float, 53 for double).
    template <Scalar S> S uniform() noexcept {
        if constexpr (sizeof(S) <= 4) {
            return S(next_u32() >> 8) * S(0x1p-24);
        } else {
            const std::uint64_t hi = next_u32() >> 5, lo = next_u32() >> 6;
            return S((hi << 26) | lo) * S(0x1p-53);
        }
    }
    template <Scalar S> Vec2<S> uniform2() noexcept {
        const S u = uniform<S>();
        return {u, uniform<S>()};
    }

    /// Uniform integer in [0, n) (Lemire's multiply-shift, bias below 2^-32 * n).
    std::uint32_t below(std::uint32_t n) noexcept {
        return static_cast<std::uint32_t>((std::uint64_t(next_u32()) * n) >> 32);
    }

private:
    std::uint64_t state_;
    std::uint64_t inc_;
};

}  // namespace photon
