// SPDX-License-Identifier: MIT
#pragma once
// A colour with POV-Ray's filter and transmit: what a layer of a layered texture (layered.hpp)
// and an image map's pixel (image_map.hpp) give at a point.

#include "../math/vec.hpp"

namespace photon {

/// A colour with POV-Ray's filter (see-through tinted by the colour) and transmit (see-through
/// untinted), each >= 0 with filter + transmit <= 1.
template <Scalar S> struct LayerColor {
    Rgb<S> color{S(0)};
    S filter = S(0), transmit = S(0);

    /// The share of the layer's own colour: POV-Ray 3.7's opacity.
    [[nodiscard]] S opacity() const noexcept { return S(1) - filter - transmit; }
    /// What the layer lets through of the light from below (POV-Ray's TransmittedColour).
    [[nodiscard]] Rgb<S> passed() const noexcept { return filter * color + Rgb<S>(transmit); }
};

/// A layer's filter and transmit, one per colour map entry.
template <Scalar S> struct FilterTransmit {
    S filter = S(0), transmit = S(0);
};

}  // namespace photon
