// SPDX-License-Identifier: MIT
#pragma once
// A participating medium (POV-Ray 3.7's `media`, material/media.cpp): per unit length it absorbs
// (sigma_a), scatters (sigma_s) and emits (radiance per length), each coefficient times a density
// field that may vary in space (the product of its densities, each a colour per channel). Along a
// ray segment, light behind is attenuated by exp(-integral of sigma_t) with
//   sigma_t = density (absorption + extinction * scattering)
// and the segment adds the emission and the light each light source scatters into the ray
// (single scattering): density * scattering * phase(cos) * E, E the light's irradiance at the
// point on a surface facing it. POV-Ray's `extinction` decouples how much scattering dims from
// how much it adds (1, physical, by default). The integration is integrator/media_march.hpp.

#include <algorithm>
#include <cmath>
#include <span>
#include <stdexcept>
#include <vector>

#include "../math/rng.hpp"
#include "../math/vec.hpp"
#include "../texture/reflectance_field.hpp"

namespace photon {

/// POV-Ray's scattering types 1 to 5, with its own phase functions (ComputeMediaScatteringAttenuation)
/// divided by 4 pi: isotropic 1 / (4 pi); Henyey-Greenstein with eccentricity g (normalised);
/// Rayleigh and the Mie approximations as POV-Ray writes them (their means over the sphere are
/// within 7% of 1 / (4 pi), and POV-Ray does not renormalise them, so neither does photon).
enum class PhaseFunction : unsigned char { isotropic = 1, mie_hazy, mie_murky, rayleigh, henyey_greenstein };

/// The phase function's value for light arriving from unit direction `to_light` (the direction
/// towards the light) and leaving along the ray's forward direction `forward`: alpha =
/// dot(to_light, forward), 1 where the light is straight ahead (forward scattering towards the eye
/// is the light shining through the medium into it, hence POV-Ray's sign).
template <Scalar S> [[nodiscard]] S phase_value(PhaseFunction phase, S eccentricity, S alpha) noexcept {
    constexpr S inv_4pi = S(1) / (S(4) * pi<S>);
    switch (phase) {
    case PhaseFunction::rayleigh: return inv_4pi * S(0.799372013) * (S(1) + alpha * alpha);
    case PhaseFunction::mie_hazy: return inv_4pi * S(0.576655375) * (S(1) + S(9) * std::pow(S(0.5) * (S(1) + alpha), S(8)));
    case PhaseFunction::mie_murky:
        return inv_4pi * S(0.495714547) * (S(1) + S(50) * std::pow(S(0.5) * (S(1) + alpha), S(32)));
    case PhaseFunction::henyey_greenstein: {
        const S g = eccentricity, g2 = g * g;
        const S base = std::max(S(1) + g2 - S(2) * g * alpha, S(1e-12));
        return inv_4pi * (S(1) - g2) / (base * std::sqrt(base));
    }
    case PhaseFunction::isotropic: break;
    }
    return inv_4pi;
}

/// How a medium is sampled along a segment: `intervals` intervals (more where lights reach it:
/// integrator/media_march.hpp), each `samples` equal steps, each sampled once at its centre moved
/// by up to +-jitter/2 of the step (POV-Ray's `intervals`, minimum `samples`, `jitter` and
/// `ratio`; its defaults for method 3 are 1, 10, 0 and 0.9).
struct MediumSampling {
    unsigned intervals = 1;
    unsigned samples = 10;
    double jitter = 0.0;
    double ratio = 0.9;  ///< POV-Ray's `ratio`: the share of the intervals that go where lights reach
};

template <Scalar S> struct Medium {
    Rgb<S> absorption{S(0)};  ///< sigma_a per unit length
    Rgb<S> emission{S(0)};    ///< radiance added per unit length
    Rgb<S> scattering{S(0)};  ///< sigma_s: what light sources scatter into the ray, per unit length
    S extinction = S(1);      ///< sigma_t = absorption + extinction * scattering (POV-Ray's `extinction`)
    PhaseFunction phase = PhaseFunction::isotropic;
    S eccentricity = S(0);  ///< Henyey-Greenstein's g, in (-1, 1)
    /// Densities that multiply (empty: 1 everywhere); each a colour per channel at a world point.
    std::vector<AnyReflectanceField<S>> density{};
    MediumSampling sampling{};

    /// Throws std::invalid_argument for values no medium can have.
    void validate() const {
        const auto nonnegative = [](const Rgb<S>& c) { return is_finite(c) && min_component(c) >= S(0); };
        if (!nonnegative(absorption) || !nonnegative(scattering))
            throw std::invalid_argument("media: absorption and scattering must be finite and >= 0");
        if (!is_finite(emission)) throw std::invalid_argument("media: emission must be finite");
        if (!(extinction >= S(0)) || !std::isfinite(extinction))
            throw std::invalid_argument("media: extinction must be finite and >= 0");
        if (phase == PhaseFunction::henyey_greenstein && !(std::abs(eccentricity) < S(1)))
            throw std::invalid_argument("media: Henyey-Greenstein eccentricity must be in (-1, 1)");
        if (sampling.intervals < 1 || sampling.samples < 1)
            throw std::invalid_argument("media: at least one interval and one sample per interval");
        if (!(sampling.jitter >= 0.0 && sampling.jitter <= 1.0))
            throw std::invalid_argument("media: jitter must be in [0, 1]");
        if (!(sampling.ratio >= 0.0 && sampling.ratio <= 1.0))
            throw std::invalid_argument("media: ratio must be in [0, 1]");
        for (const auto& d : density)
            if (!d) throw std::invalid_argument("media: an empty density field");
    }

    /// sigma_t without the density.
    [[nodiscard]] Rgb<S> extinction_coefficient() const noexcept { return absorption + extinction * scattering; }
    [[nodiscard]] bool scatters() const noexcept { return !is_black(scattering); }
    /// The product of the densities at world point `p` (1 without any).
    [[nodiscard]] Rgb<S> density_at(const Vec3<S>& p) const {
        Rgb<S> d(S(1));
        for (const auto& field : density) d *= field(p);
        return d;
    }
};

namespace media_detail {

/// The sampling of several media: the one with the most intervals, then samples (POV-Ray's IMedia).
template <Scalar S> [[nodiscard]] MediumSampling combined_sampling(std::span<const Medium<S>> media) noexcept {
    MediumSampling best = media.front().sampling;
    for (const Medium<S>& m : media)
        if (m.sampling.intervals > best.intervals ||
            (m.sampling.intervals == best.intervals && m.sampling.samples > best.samples))
            best = m.sampling;
    return best;
}

template <Scalar S> [[nodiscard]] Rgb<S> exp_neg(const Rgb<S>& od) noexcept {
    return {std::exp(-od.x), std::exp(-od.y), std::exp(-od.z)};
}

[[nodiscard]] inline bool all_homogeneous(auto media) noexcept {
    return std::all_of(media.begin(), media.end(), [](const auto& m) { return m.density.empty(); });
}

}  // namespace media_detail

/// The fraction of light that crosses the segment (no emission, no scattering in): for photons
/// and shadow rays. Exact for homogeneous media; `rng` jitters the samples of varying ones.
template <Scalar S>
[[nodiscard]] Rgb<S> media_transmittance(std::span<const Medium<S>> media, const Vec3<S>& origin,
                                         const Vec3<S>& direction, S length, Pcg32& rng) {
    if (media.empty() || !(length > S(0))) return Rgb<S>(S(1));
    Rgb<S> od(S(0));
    if (media_detail::all_homogeneous(media)) {
        for (const Medium<S>& m : media) od += m.extinction_coefficient();
        return media_detail::exp_neg(od * length);
    }
    const MediumSampling sampling = media_detail::combined_sampling(media);
    const unsigned steps = sampling.intervals * sampling.samples;
    const S dt = length / S(steps);
    for (unsigned k = 0; k < steps; ++k) {
        const S shift = sampling.jitter > 0.0 ? S(sampling.jitter) * (rng.uniform<S>() - S(0.5)) : S(0);
        const Vec3<S> x = origin + direction * ((S(k) + S(0.5) + shift) * dt);
        for (const Medium<S>& m : media) od += m.density_at(x) * m.extinction_coefficient();
    }
    return media_detail::exp_neg(od * dt);
}

}  // namespace photon
