// SPDX-License-Identifier: MIT
#pragma once
// Ray marching through participating media (material/medium.hpp), as POV-Ray 3.7 integrates them
// (MediaFunction::ComputeMedia): the segment is cut into intervals, more of them where lights
// reach it (a spotlight's cone), and each interval into `samples` equal steps, each sampled once
// (at its centre, moved by the jitter); within a step the medium is taken as constant, so what
// the step adds is exact for it:
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
#include <vector>

#include "../math/rng.hpp"
#include "../material/medium.hpp"

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

/// Where along a segment a light can reach (POV-Ray's LightSourceEntry): [start, end]; empty
/// (start > end) where it reaches no point of it, as a spotlight whose cone the ray misses.
template <Scalar S> struct LitSpan {
    S start = S(1), end = S(0);
    [[nodiscard]] bool empty() const noexcept { return start > end; }
    [[nodiscard]] bool contains(S t) const noexcept { return t >= start && t <= end; }
};

/// One interval of the segment that is sampled on its own (POV-Ray's MediaInterval).
template <Scalar S> struct MediaInterval {
    S start, length;
    bool lit;
};

/// POV-Ray's intervals (ComputeMediaLightInterval, ComputeMediaSampleInterval): the lit spans
/// merged into lit and unlit stretches of [0, length]; then `intervals` (at least one per stretch)
/// shared among them by `ratio` for lit ones and 1 - ratio for unlit ones, each stretch cut into
/// equal intervals. Nothing lit and homogeneous media (`constant`): one interval.
template <Scalar S>
[[nodiscard]] std::vector<MediaInterval<S>> media_intervals(std::span<const LitSpan<S>> spans, S length,
                                                             const MediumSampling& sampling, bool constant) {
    struct Stretch {
        S s0, s1;
        bool lit;
    };
    std::vector<S> s0, s1;
    for (const LitSpan<S>& span : spans)
        if (!span.empty()) s0.push_back(std::max(span.start, S(0))), s1.push_back(std::min(span.end, length));
    std::vector<Stretch> stretches;
    if (s0.empty()) {
        stretches.push_back({S(0), length, false});
    } else {
        std::sort(s0.begin(), s0.end());
        std::sort(s1.begin(), s1.end());
        if (s0[0] > S(0)) stretches.push_back({S(0), s0[0], false});
        stretches.push_back({s0[0], s1[0], true});
        for (std::size_t i = 1; i < s0.size(); ++i) {
            if (s0[i] > stretches.back().s1) {
                stretches.push_back({stretches.back().s1, s0[i], false});
                stretches.push_back({s0[i], s1[i], true});
            } else if (s1[i] > stretches.back().s1) {
                stretches.back().s1 = s1[i];
            }
        }
        if (stretches.back().s1 < length) stretches.push_back({stretches.back().s1, length, false});
    }
    std::vector<MediaInterval<S>> out;
    const std::size_t count = std::max<std::size_t>(sampling.intervals, stretches.size());
    if (stretches.size() == 1) {
        const Stretch& only = stretches[0];
        const std::size_t n = !only.lit && constant ? 1 : count;
        const S delta = (only.s1 - only.s0) / S(n);
        for (std::size_t i = 0; i < n; ++i) out.push_back({only.s0 + delta * S(i), delta, only.lit});
        return out;
    }
    double sum = 0;
    for (const Stretch& st : stretches) sum += st.lit ? sampling.ratio : 1.0 - sampling.ratio;
    std::size_t remaining = count;
    for (std::size_t i = 0; i < stretches.size(); ++i) {
        const Stretch& st = stretches[i];
        const double weight = st.lit ? sampling.ratio : 1.0 - sampling.ratio;
        std::size_t n = sum > 0 ? std::size_t(weight / sum * double(count)) + 1 : 1;
        n = std::min(n, remaining - stretches.size() + i + 1);
        const S delta = (st.s1 - st.s0) / S(n);
        for (std::size_t j = 0; j < n; ++j) out.push_back({st.s0 + delta * S(j), delta, st.lit});
        remaining -= n;
    }
    return out;
}

/// The media along the segment from `origin` along unit `direction` of length `length`. `spans`
/// holds where each light (by index) reaches the segment; in the stretches no light reaches,
/// nothing is scattered in. For each sample point x at distance t in a lit one,
/// `lights(x, t, visit)` calls visit(to_light, irradiance) once per sample of each light whose
/// span holds t (to_light unit, irradiance on a surface facing the light, shadows applied).
/// `rng` draws the jitter.
template <Scalar S, class LightsAt>
[[nodiscard]] MediaEffect<S> march_media(std::span<const Medium<S>> media, const Vec3<S>& origin,
                                         const Vec3<S>& direction, S length, std::span<const LitSpan<S>> spans,
                                         Pcg32& rng, LightsAt&& lights) {
    MediaEffect<S> effect;
    if (media.empty() || !(length > S(0))) return effect;
    const bool scatters = std::any_of(media.begin(), media.end(), [](const Medium<S>& m) { return m.scatters(); });
    const MediumSampling sampling = media_detail::combined_sampling(media);
    const bool homogeneous = media_detail::all_homogeneous(media);
    const auto intervals = media_intervals<S>(scatters ? spans : std::span<const LitSpan<S>>{}, length, sampling, homogeneous);
    for (const MediaInterval<S>& interval : intervals) {
        // A homogeneous interval that nothing lights: one step is exact.
        const unsigned steps = !interval.lit && homogeneous ? 1u : sampling.samples;
        const S dt = interval.length / S(steps);
        for (unsigned k = 0; k < steps; ++k) {
            const S shift = sampling.jitter > 0.0 ? S(sampling.jitter) * (rng.uniform<S>() - S(0.5)) : S(0);
            const S t = interval.start + (S(k) + S(0.5) + shift) * dt;
            const Vec3<S> x = origin + direction * t;
            Rgb<S> sigma_t(S(0)), source(S(0)), sigma_s(S(0));
            for (const Medium<S>& m : media) {
                const Rgb<S> d = m.density_at(x);
                sigma_t += d * m.extinction_coefficient();
                source += d * m.emission;
                sigma_s += d * m.scattering;
            }
            if (interval.lit && !is_black(sigma_s)) {
                Rgb<S> in(S(0));
                lights(x, t, [&](const Vec3<S>& to_light, const Rgb<S>& irradiance) {
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
    }
    return effect;
}

}  // namespace photon
