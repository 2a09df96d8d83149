// SPDX-License-Identifier: MIT
#pragma once
// POV-Ray 3.7's `normal { ... }`: a pattern that tilts the shading normal (Perturb_Normal in
// source/backend/texture/normal.cpp). bumps, dents, ripples, waves, wrinkles and quilted have their own
// formulas; any other pattern photon evaluates tilts the normal down its slope, found from the
// pattern's values at four points of a small tetrahedron (POV-Ray's Pyramid_Vect). A
// NormalField (normal_field.hpp), so a Material can take one.

#include <array>
#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <utility>

#include "../math/transform.hpp"
#include "noise.hpp"
#include "pattern.hpp"
#include "wave.hpp"

namespace photon {

/// The normal patterns with a formula of their own; `slope` uses a pigment Pattern's slope.
enum class NormalKind : std::uint8_t { bumps, dents, ripples, waves, wrinkles, quilted, slope };

/// One normal pattern with POV-Ray's modifiers and defaults.
struct NormalPattern {
    NormalKind kind = NormalKind::bumps;
    /// The modifiers (turbulence, octaves, omega, lambda, noise_generator, frequency, phase);
    /// for `slope`, also the pattern whose slope tilts the normal, with its wave.
    Pattern pattern{};
    double amount = 0.5;     ///< the number after the pattern, or `bump_size` (POV-Ray's default 0.5)
    double accuracy = 0.02;  ///< `accuracy`: the tetrahedron's size for `slope` (POV-Ray's Delta)
};

namespace normal_detail {

/// POV-Ray's Pyramid_Vect: a regular tetrahedron's vertex directions.
inline constexpr std::array<Vec3<double>, 4> pyramid{Vec3<double>{0.942809041, -0.333333333, 0.0},
                                                     Vec3<double>{-0.471404521, -0.333333333, 0.816496581},
                                                     Vec3<double>{-0.471404521, -0.333333333, -0.816496581},
                                                     Vec3<double>{0.0, 1.0, 0.0}};

/// The tilt POV-Ray adds to the pattern-space normal at pattern-space point q (already warped by
/// turbulence where POV-Ray warps it).
inline Vec3<double> tilt(const NormalPattern& np, const Vec3<double>& q) noexcept {
    const double amount = np.amount;
    switch (np.kind) {
    case NormalKind::bumps: return amount * pov_dnoise(q);
    case NormalKind::dents: {
        const double n = pov_noise(q, np.pattern.noise_generator);
        return (n * n * n * amount) * pov_dnoise(q);
    }
    case NormalKind::ripples:
    case NormalKind::waves: {
        const auto& w = pattern_detail::wave_sources();
        const double count = double(w.source.size());
        Vec3<double> sum(0.0);
        for (std::size_t i = 0; i < w.source.size(); ++i) {
            const Vec3<double> d = q - w.source[i];
            double length = glm::length(d);
            if (length == 0.0) length = 1.0;
            const double f = np.kind == NormalKind::waves ? w.frequency[i] : 1.0;
            const double index = length * np.pattern.wave.frequency * f + np.pattern.wave.phase;
            sum += (pov_cycloidal(index) * amount / f / (length * count)) * d;
        }
        return sum;
    }
    case NormalKind::wrinkles: {
        Vec3<double> sum(0.0);
        double scale = 1.0;
        for (int i = 0; i < 10; ++i, scale *= 2.0) sum += glm::abs(pov_dnoise(q * scale) / scale);
        return amount * sum;
    }
    case NormalKind::quilted: return amount * quilt_offset(q, np.pattern.quilt_control0, np.pattern.quilt_control1);
    case NormalKind::slope: {
        // POV-Ray's fudge factor -5, made independent of the tetrahedron's size.
        const double a = amount * -5.0 * 0.02 / np.accuracy;
        Vec3<double> sum(0.0);
        for (const Vec3<double>& v : pyramid) sum += (a * evaluate(np.pattern, q + np.accuracy * v)) * v;
        return sum;
    }
    }
    return Vec3<double>(0.0);
}

}  // namespace normal_detail

/// A normal pattern placed in the world. Computed in double whatever S is, as POV-Ray does.
template <Scalar S> class NormalPerturbation {
public:
    /// `placement` maps the pattern's own space to the world (the normal's transformations, then
    /// those of its texture and object); it must be invertible. Throws std::invalid_argument on a
    /// non-finite amount or a non-positive accuracy.
    explicit NormalPerturbation(NormalPattern pattern, const Affine<double>& placement = {})
        : pattern_(std::move(pattern)), to_pattern_(placement.inverse()) {
        if (!std::isfinite(pattern_.amount)) throw std::invalid_argument("normal: the bump size must be finite");
        if (!(pattern_.accuracy > 0.0) || !std::isfinite(pattern_.accuracy))
            throw std::invalid_argument("normal: accuracy must be positive and finite");
        // POV-Ray warps the point by turbulence once, before the pattern; the slope's pattern
        // must not warp each of its four points again (marble and wood keep it: it is part of
        // their formula).
        const PatternKind k = pattern_.pattern.kind;
        warp_ = pattern_.pattern.has_turbulence() &&
                (pattern_.kind != NormalKind::slope || (k != PatternKind::marble && k != PatternKind::wood));
        if (warp_) {
            turbulence_ = pattern_.pattern.turbulence;
            if (pattern_.kind == NormalKind::slope) pattern_.pattern.turbulence = Vec3<double>(0.0);
        }
        // World normals go to pattern space by the placement's transpose, and back by its
        // inverse transpose (POV-Ray's Warp_Normal and UnWarp_Normal).
        to_pattern_normal_ = glm::transpose(glm::inverse(to_pattern_.linear));
        to_world_normal_ = glm::transpose(to_pattern_.linear);
    }

    /// The tilted unit normal at world point p whose unit geometric normal is n (outward, not
    /// turned to any side; the tilt follows the outward side, as POV-Ray's does). Returns n where
    /// the tilted normal would not be finite.
    [[nodiscard]] Vec3<S> operator()(const Vec3<S>& p, const Vec3<S>& n) const noexcept {
        Vec3<double> q = to_pattern_.point(Vec3<double>(p));
        if (warp_) q += pov_dturbulence(q, pattern_.pattern.octaves) * turbulence_;
        const Vec3<double> np = glm::normalize(to_pattern_normal_ * Vec3<double>(n));
        const Vec3<double> world = to_world_normal_ * (np + normal_detail::tilt(pattern_, q));
        const double length = glm::length(world);
        if (!(length > 0.0) || !std::isfinite(length)) return n;
        const Vec3<S> out(world / length);
        return is_finite(out) ? out : n;
    }

    [[nodiscard]] const NormalPattern& pattern() const noexcept { return pattern_; }

private:
    NormalPattern pattern_;
    Affine<double> to_pattern_;  ///< world -> pattern space
    glm::dmat3 to_pattern_normal_{1.0}, to_world_normal_{1.0};
    Vec3<double> turbulence_{0.0};
    bool warp_ = false;
};

}  // namespace photon
