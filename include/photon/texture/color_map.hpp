// SPDX-License-Identifier: MIT
#pragma once
// POV-Ray's color_map: colours at values in [0, 1], searched and interpolated as POV-Ray 3.7's
// Search_Blend_Map and Compute_Pigment do.

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <utility>
#include <vector>

#include "../math/vec.hpp"

namespace photon {

template <Scalar S> class ColorMap {
public:
    struct Entry {
        double value;
        Rgb<S> color;
    };

    ColorMap() = default;
    /// Entries in the order written (POV-Ray searches them in that order and does not sort them).
    /// Throws std::invalid_argument when empty, or on a non-finite value or a colour that is not
    /// finite and >= 0 (the colours are reflectances).
    explicit ColorMap(std::vector<Entry> entries) : entries_(std::move(entries)) {
        if (entries_.empty()) throw std::invalid_argument("color_map: at least one entry is needed");
        for (const Entry& e : entries_)
            if (!std::isfinite(e.value) || !is_finite(e.color) || min_component(e.color) < S(0))
                throw std::invalid_argument("color_map: values and colours must be finite, colours >= 0");
    }

    /// Where `value` falls in the map: the colour there is entry `prev` blended linearly towards
    /// entry `cur` by `fraction` (prev == cur, fraction 0 on an entry or beyond the ends).
    struct Position {
        std::size_t prev = 0, cur = 0;
        S fraction = S(0);
    };
    /// The last entry at or above the last value, else the first entry whose value is not below
    /// `value` with the one before it. Exposed so that values kept beside the colours (a layer's
    /// filter and transmit, texture/layered.hpp) blend exactly as the colours do.
    [[nodiscard]] Position locate(double value) const noexcept {
        const std::size_t last = entries_.size() - 1;
        std::size_t cur = 0, prev = 0;
        if (value >= entries_[last].value) {
            prev = cur = last;
        } else {
            while (value > entries_[cur].value) prev = cur++;
        }
        if (value == entries_[cur].value) prev = cur;
        if (prev == cur) return {cur, cur, S(0)};
        const Entry& p = entries_[prev];
        const Entry& c = entries_[cur];
        return {prev, cur, S((value - p.value) / (c.value - p.value))};
    }
    /// The colour at a position locate() gave.
    [[nodiscard]] Rgb<S> at(const Position& where) const noexcept {
        const Rgb<S>& p = entries_[where.prev].color;
        if (where.prev == where.cur) return p;
        return p + where.fraction * (entries_[where.cur].color - p);
    }
    /// The colour at `value`.
    [[nodiscard]] Rgb<S> operator()(double value) const noexcept { return at(locate(value)); }

    [[nodiscard]] const std::vector<Entry>& entries() const noexcept { return entries_; }
    /// Per channel, the largest colour the map can give (it only interpolates between entries).
    [[nodiscard]] Rgb<S> upper_bound() const noexcept {
        Rgb<S> m(S(0));
        for (const Entry& e : entries_) m = glm::max(m, e.color);
        return m;
    }

private:
    std::vector<Entry> entries_;
};

}  // namespace photon
