// SPDX-License-Identifier: MIT
#pragma once
// Ray marching through participating media (scene/medium.hpp), as POV-Ray 3.7 integrates them
// (MediaFunction::ComputeMedia): the segment is cut into intervals x samples equal steps, each
// sampled once (at its centre, moved by the jitter); within a step the medium is taken as
// constant, so what the step adds is exact for it:
//   added += T J (1 - exp(-sigma_t dt)) / sigma_t,   T *= exp(-sigma_t dt)
// with J = emission + scattering * mean phase * the light arriving at the sample (POV-Ray's
// k averaged over the media there). A homogeneous medium is integrated exactly whatever the step
// count, and without light (no scattering) its effect is the closed form. Several media on one
// segment add their coefficients and are sampled as the one with the most intervals (then
// samples) asks. The random numbers (only for jitter) come from the caller's stream, so a pixel
// renders the same whatever thread runs it.

#include <algorithm>
#include <cmath>
#include <span>

#include "../math/rng.hpp"
#include "../scene/medium.hpp"

namespace photon {

/// What media do to one ray segment: seen = added + transmittance * behind, per channel.
template <Scalar S> struct MediaEffect {
    Rgb<S> transmittance{S(1)};
    Rgb<S> added{S(0)};
    [[nodiscard]] Rgb<S> apply(const Rgb<S>& behind) const noexcept { return added + transmittance * behind; }
};


namespace media_detail {

/// (1 - exp(-x dt)) / x per channel, dt where x dt is tiny: a step's emitted share.
template <Scalar S> [[nodiscard]] Rgb<S> step_weight(const Rgb<S>& sigma_t, S dt) noexcept {
    Rgb<S> w;
    for (int c = 0; c < 3; ++c) {
        const S od = sigma_t[c] * dt;
        w[c] = od > S(1e-6) ? -std::expm1(-od) / sigma_t[c] : dt * (S(1) - S(0.5) * od);
    }
    return w;
}

}  // namespace media_detail

/// The media along the segment from `origin` along unit `direction` of length `length`. For each
/// sample point x, `lights(x, visit)` calls visit(to_light, irradiance) once per light sample
/// that reaches x (to_light unit, irradiance on a surface facing the light, shadows applied);
/// it is called only where some medium scatters. `rng` draws the jitter.
template <Scalar S, class LightsAt>
[[nodiscard]] MediaEffect<S> march_media(std::span<const Medium<S>> media, const Vec3<S>& origin,
                                         const Vec3<S>& direction, S length, Pcg32& rng, LightsAt&& lights) {
    MediaEffect<S> effect;
    if (media.empty() || !(length > S(0))) return effect;
    const bool scatters = std::any_of(media.begin(), media.end(), [](const Medium<S>& m) { return m.scatters(); });
    const MediumSampling sampling = media_detail::combined_sampling(media);
    // Homogeneous media that nothing lights: one step is exact.
    const unsigned steps = !scatters && media_detail::all_homogeneous(media) ? 1u : sampling.intervals * sampling.samples;
    const S dt = length / S(steps);
    for (unsigned k = 0; k < steps; ++k) {
        const S shift = sampling.jitter > 0.0 ? S(sampling.jitter) * (rng.uniform<S>() - S(0.5)) : S(0);
        const Vec3<S> x = origin + direction * ((S(k) + S(0.5) + shift) * dt);
        Rgb<S> sigma_t(S(0)), source(S(0)), sigma_s(S(0));
        for (const Medium<S>& m : media) {
            const Rgb<S> d = m.density_at(x);
            sigma_t += d * m.extinction_coefficient();
            source += d * m.emission;
            sigma_s += d * m.scattering;
        }
        if (scatters && !is_black(sigma_s)) {
            Rgb<S> in(S(0));
            lights(x, [&](const Vec3<S>& to_light, const Rgb<S>& irradiance) {
                const S alpha = glm::dot(to_light, direction);
                S phase = S(0);
                for (const Medium<S>& m : media) phase += phase_value(m.phase, m.eccentricity, alpha);
                in += irradiance * (phase / S(media.size()));
            });
            source += sigma_s * in;
        }
        effect.added += effect.transmittance * source * media_detail::step_weight(sigma_t, dt);
        effect.transmittance *= media_detail::exp_neg(sigma_t * dt);
    }
    return effect;
}

}  // namespace photon
