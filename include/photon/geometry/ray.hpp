// SPDX-License-Identifier: MIT
#pragma once

#include <limits>

#include "../math/vec.hpp"

namespace photon {

/// A half-line origin + t * direction for t in (0, t_max). The direction need not be unit length
/// (rays transformed into an object's local space are not); t is in units of the direction.
template <Scalar S> struct Ray {
    Vec3<S> origin{};
    Vec3<S> direction{S(0), S(0), S(1)};
    S t_max = std::numeric_limits<S>::infinity();

    [[nodiscard]] Vec3<S> at(S t) const noexcept { return origin + t * direction; }
};

}  // namespace photon
