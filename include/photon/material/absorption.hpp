// SPDX-License-Identifier: MIT
#pragma once
// What light loses travelling inside an object (coloured glass): a transmittance that depends on
// the length of each straight segment a ray or photon runs inside. Beer-Lambert absorption,
// T(d) = exp(-sigma d) per channel, and POV-Ray 3.7's older fade,
// T(d) = C + (1 - C) / (1 + (d / D)^P), which it keeps for `fade_power` below 1000 (trace.cpp,
// ComputeLightedTexture: "NK attenuate"). Every pass applies it per segment, where the segment
// ends on the inside of the surface (segment_transmittance in scatter.hpp).

#include <cmath>
#include <sstream>
#include <stdexcept>

#include "../math/vec.hpp"

namespace photon {

/// Absorption inside a surface. Default: clear (T = 1 at every distance).
template <Scalar S> class Absorption {
public:
    enum class Law : unsigned char {
        clear,        ///< nothing is absorbed
        beer_lambert, ///< T(d) = exp(-sigma d) per channel
        pov_fade,     ///< T(d) = C + (1 - C) / (1 + (d / D)^P) per channel (POV-Ray's fade_power < 1000)
    };

    Absorption() = default;

    /// Beer-Lambert absorption with coefficient `sigma` (per unit length, finite, >= 0, per channel).
    [[nodiscard]] static Absorption beer_lambert(const Rgb<S>& sigma) {
        if (!is_finite(sigma) || min_component(sigma) < S(0)) fail("sigma must be finite and >= 0", sigma);
        Absorption a;
        a.law_ = is_black(sigma) ? Law::clear : Law::beer_lambert;
        a.sigma_ = sigma;
        return a;
    }

    /// POV-Ray 3.7's interior fade: `distance` D > 0 (fade_distance), `power` P >= 0 (fade_power),
    /// `color` C in [0, 1] (fade_color, black by default). P >= 1000 is Beer-Lambert with
    /// sigma = (1 - C) / D; below, the rational form above, which is not multiplicative over
    /// distance (POV-Ray applies it to each segment, as photon does). D = 0 is clear, as in POV-Ray.
    [[nodiscard]] static Absorption pov_fade(S distance, S power, const Rgb<S>& color = Rgb<S>(S(0))) {
        if (!(distance >= S(0)) || !std::isfinite(distance)) fail("fade distance must be finite and >= 0", Rgb<S>(distance));
        if (!(power >= S(0)) || !std::isfinite(power)) fail("fade power must be finite and >= 0", Rgb<S>(power));
        if (!is_finite(color) || min_component(color) < S(0) || max_component(color) > S(1))
            fail("fade colour must be in [0, 1]", color);
        if (distance == S(0)) return {};
        if (power >= S(1000)) return beer_lambert((Rgb<S>(S(1)) - color) / distance);
        Absorption a;
        a.law_ = Law::pov_fade;
        a.distance_ = distance;
        a.power_ = power;
        a.color_ = color;
        return a;
    }

    [[nodiscard]] Law law() const noexcept { return law_; }
    [[nodiscard]] bool absorbs() const noexcept { return law_ != Law::clear; }
    [[nodiscard]] const Rgb<S>& sigma() const noexcept { return sigma_; }
    [[nodiscard]] S fade_distance() const noexcept { return distance_; }
    [[nodiscard]] S fade_power() const noexcept { return power_; }
    [[nodiscard]] const Rgb<S>& fade_color() const noexcept { return color_; }

    friend bool operator==(const Absorption&, const Absorption&) = default;

    /// The fraction of light per channel that survives one straight segment of length d >= 0.
    [[nodiscard]] Rgb<S> transmittance(S d) const {
        switch (law_) {
        case Law::clear: break;
        case Law::beer_lambert:
            return {std::exp(-sigma_.x * d), std::exp(-sigma_.y * d), std::exp(-sigma_.z * d)};
        case Law::pov_fade:
            return color_ + (Rgb<S>(S(1)) - color_) / (S(1) + std::pow(d / distance_, power_));
        }
        return Rgb<S>(S(1));
    }

private:
    [[noreturn]] static void fail(const char* what, const Rgb<S>& got) {
        std::ostringstream os;
        os << "absorption: " << what << ", got <" << got.x << ", " << got.y << ", " << got.z << ">";
        throw std::invalid_argument(os.str());
    }

    Law law_ = Law::clear;
    Rgb<S> sigma_{S(0)};
    S distance_ = S(0), power_ = S(0);
    Rgb<S> color_{S(0)};
};

}  // namespace photon
