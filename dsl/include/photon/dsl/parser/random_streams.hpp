// SPDX-License-Identifier: MIT
#pragma once
// POV-Ray's `seed(N)` and `rand(S)`: numbered streams of a 32-bit linear congruential generator,
// the one POV-Ray's parser uses (state = state * 1812433253 + 12345 mod 2^32, value = state /
// (2^32 - 1)), so that a scene that scatters objects with rand() places them where POV-Ray does.

#include <cstddef>
#include <cstdint>
#include <optional>
#include <vector>

#include "builtin_math.hpp"

namespace photon::dsl::detail {

class RandomStreams {
public:
    /// A new stream started at `seed` (truncated to an int as POV-Ray does); returns its number,
    /// the value of `seed(N)` (0 for the first stream, 1 for the next, ...).
    double add(double seed) {
        state_.push_back(std::uint32_t(pov_int(seed)));
        return double(state_.size() - 1);
    }
    /// The next value of stream `stream` in [0, 1]; nullopt when there is no such stream.
    std::optional<double> next(double stream) {
        const std::int32_t i = pov_int(stream);
        if (i < 0 || std::size_t(i) >= state_.size()) return std::nullopt;
        std::uint32_t& s = state_[std::size_t(i)];
        s = s * 1812433253u + 12345u;
        return double(s) / double(0xFFFFFFFFu);
    }
    [[nodiscard]] std::size_t size() const noexcept { return state_.size(); }

private:
    std::vector<std::uint32_t> state_;
};

}  // namespace photon::dsl::detail
