// SPDX-License-Identifier: MIT
#pragma once
// POV-Ray 3.6's sky_sphere, which POV-Ray 3.7 keeps for a scene whose #version is below 3.7
// (trace.cpp, Trace::ComputeSky): the pigments from the top down, each adding its colour times
// its opacity times the product of the filter-plus-transmit sums above it (a scalar: an upper
// layer's filter does not tint the ones below), and the background under them all times the
// product of the layers' colours times the product of their filters, plus the product of their
// transmits. POV-Ray 3.7's own sky (a layered pigment, texture/layered.hpp) tints and differs
// wherever a layer filters.

#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

#include <photon/texture/layered.hpp>

namespace photon::dsl {

/// The sky of POV-Ray 3.6, a ReflectanceField of directions. Layer weights carry the sky's emission.
template <Scalar S> class LegacySky {
public:
    /// `layers` bottom first, as written; `background` the background colour under them.
    LegacySky(std::vector<PigmentLayer<S>> layers, const Rgb<S>& background)
        : layers_(std::move(layers)), background_(background) {
        S tint = S(1);  // the most the product of the layers' colours reaches
        for (const PigmentLayer<S>& l : layers_) {
            const Rgb<S> brightest = l.envelope().color;
            bound_ += brightest * l.weight();
            tint *= std::max(S(1), max_component(brightest));
        }
        bound_ += background_ * tint;
    }

    [[nodiscard]] Rgb<S> operator()(const Vec3<S>& d) const noexcept {
        Rgb<S> sum(S(0)), tint(S(1));
        S trans = S(1), filter = S(1), transmit = S(1);
        for (auto layer = layers_.rbegin(); layer != layers_.rend(); ++layer) {
            const LayerColor<S> c = (*layer)(d);
            sum += c.color * layer->weight() * (trans * (S(1) - c.filter - c.transmit));
            tint *= c.color;
            filter *= c.filter, transmit *= c.transmit;
            trans = std::abs(filter) + std::abs(transmit);
        }
        return sum + background_ * (tint * filter + Rgb<S>(transmit));
    }
    /// Per channel, no direction is brighter (each layer's brightest colour, and the background).
    [[nodiscard]] Rgb<S> upper_bound() const noexcept { return bound_; }

private:
    std::vector<PigmentLayer<S>> layers_;
    Rgb<S> background_;
    Rgb<S> bound_{S(0)};
};

}  // namespace photon::dsl
