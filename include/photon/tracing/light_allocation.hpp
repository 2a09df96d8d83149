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
/// A sky whose power into the scene (Environment::power_into) is `environment_power` > 0 is
/// one more emitter, the last entry of the result; the lights' shares then split the lights'
/// own total power, so the sky is shared with them by power.
template <Scalar S>
[[nodiscard]] std::vector<std::size_t> photons_per_light(std::span<const Light<S>> lights, std::size_t count,
                                                         const std::vector<bool>& emits = {},
                                                         const std::vector<double>& shares = {},
                                                         double environment_power = 0) {
    const bool sky = environment_power > 0 && std::isfinite(environment_power);
    const std::size_t emitters = lights.size() + (sky ? 1 : 0);
    std::vector<std::size_t> result(emitters, 0);
    const bool by_shares = shares.size() == lights.size();
    double share_scale = 1;  // the shares in watts: only needed beside the sky
    if (sky && by_shares) {
        share_scale = 0;
        for (std::size_t i = 0; i < lights.size(); ++i)
            if (i >= emits.size() || emits[i]) share_scale += std::max(0.0, double(average(light_power(lights[i]))));
    }
    auto power = [&](std::size_t i) {
        if (i == lights.size()) return environment_power;
        if (i < emits.size() && !emits[i]) return 0.0;
        return by_shares ? std::max(0.0, shares[i]) * share_scale : double(average(light_power(lights[i])));
    };
    double total = 0;
    for (std::size_t i = 0; i < emitters; ++i) total += power(i);
    if (emitters == 0 || !(total > 0)) return result;
    std::vector<double> remainder(emitters);
    std::size_t assigned = 0;
    for (std::size_t i = 0; i < emitters; ++i) {
        const double exact = double(count) * power(i) / total;
        result[i] = static_cast<std::size_t>(std::floor(exact));
        remainder[i] = exact - double(result[i]);
        assigned += result[i];
    }
    while (assigned < count) {
        std::size_t best = 0;
        for (std::size_t i = 1; i < emitters; ++i)
            if (remainder[i] > remainder[best]) best = i;
        ++result[best];
        remainder[best] = -1;
        ++assigned;
    }
    return result;
}

}  // namespace photon
