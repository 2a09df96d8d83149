// SPDX-License-Identifier: MIT
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <span>
#include <vector>

#include "../light/light.hpp"

namespace photon {

/// Splits `count` emitted photons among lights in proportion to their power (channel average),
/// so that every photon of a pass starts with about the same power. Largest-remainder rounding:
/// the counts sum to `count` exactly and depend only on the inputs. `emits[i] == false` gives
/// light i no photons (the light-path plan found that none of its light reaches the image);
/// an empty `emits` lets every light emit. `shares`, when given (one per light), replaces the
/// powers as the proportions (the light-path plan's visible-power shares, visible_power.hpp).
template <Scalar S>
[[nodiscard]] std::vector<std::size_t> photons_per_light(std::span<const Light<S>> lights, std::size_t count,
                                                         const std::vector<bool>& emits = {},
                                                         const std::vector<double>& shares = {}) {
    std::vector<std::size_t> result(lights.size(), 0);
    auto power = [&](std::size_t i) {
        if (i < emits.size() && !emits[i]) return 0.0;
        return shares.size() == lights.size() ? std::max(0.0, shares[i]) : double(average(light_power(lights[i])));
    };
    double total = 0;
    for (std::size_t i = 0; i < lights.size(); ++i) total += power(i);
    if (lights.empty() || !(total > 0)) return result;
    std::vector<double> remainder(lights.size());
    std::size_t assigned = 0;
    for (std::size_t i = 0; i < lights.size(); ++i) {
        const double exact = double(count) * power(i) / total;
        result[i] = static_cast<std::size_t>(std::floor(exact));
        remainder[i] = exact - double(result[i]);
        assigned += result[i];
    }
    while (assigned < count) {
        std::size_t best = 0;
        for (std::size_t i = 1; i < lights.size(); ++i)
            if (remainder[i] > remainder[best]) best = i;
        ++result[best];
        remainder[best] = -1;
        ++assigned;
    }
    return result;
}

}  // namespace photon
