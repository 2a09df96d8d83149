// SPDX-License-Identifier: MIT
#pragma once
// POV-Ray 3.7's pigment patterns: a pattern maps a point of its own space to a value in [0, 1]
// (checker to 0 or 1, hexagon to 0, 1/2 or 1) that then picks a colour from a color_map. Each pattern is POV-Ray's formula
// (source/backend/pattern/pattern.cpp, 3.7.0.10), with its turbulence and wave.

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>

#include "../math/vec.hpp"
#include "crackle.hpp"
#include "noise.hpp"
#include "wave.hpp"

namespace photon {

enum class PatternKind : std::uint8_t {
    checker, gradient, bozo, spotted, granite, marble, wood, agate, onion, leopard, radial, ripples, waves,
    spherical, planar, boxed, cylindrical, hexagon, cells, crackle, bumps, dents, wrinkles, mandel, spiral1, spiral2,
    quilted
};

/// `mandel`'s iteration count and its colouring of the points inside and outside the set: POV-Ray's
/// `interior TYPE, FACTOR` and `exterior TYPE, FACTOR` (FractalPattern's InteriorColour and
/// ExteriorColour; exterior 1, the escape iteration over the count, is the default).
struct FractalParams {
    int iterations = 1;
    int interior_type = 0, exterior_type = 1;
    double interior_factor = 1, exterior_factor = 1;
};

/// One pattern with its modifiers, in POV-Ray's meaning and with its defaults.
struct Pattern {
    PatternKind kind = PatternKind::checker;
    Vec3<double> gradient{1, 0, 0};  ///< `gradient` direction (its length does not matter: normalized, as POV-Ray does)
    double agate_turb = 1.0;         ///< `agate_turb`
    CrackleParams crackle{};         ///< `form`, `metric`, `offset`, `solid` of crackle
    FractalParams fractal{};         ///< mandel's iterations, `interior` and `exterior`
    int spiral_arms = 1;             ///< the number after spiral1 and spiral2
    double quilt_control0 = 1, quilt_control1 = 1;  ///< quilted's `control0` and `control1`
    /// `turbulence`: displaces the point by dturbulence * amount before the pattern (marble and
    /// wood instead use it in their own formula, as POV-Ray does). Zero: no turbulence.
    Vec3<double> turbulence{0.0};
    TurbulenceParams octaves{};
    NoiseGenerator noise_generator = NoiseGenerator::range_corrected;
    Wave wave{};

    /// A pattern with POV-Ray's defaults for its kind (marble, wood and the spirals: triangle_wave;
    /// quilted: frequency 0, its value not wrapped).
    [[nodiscard]] static Pattern of(PatternKind kind) noexcept {
        Pattern p;
        p.kind = kind;
        if (kind == PatternKind::marble || kind == PatternKind::wood || kind == PatternKind::spiral1 ||
            kind == PatternKind::spiral2)
            p.wave.type = WaveType::triangle;
        if (kind == PatternKind::quilted) p.wave.frequency = 0.0;
        return p;
    }
    [[nodiscard]] bool has_turbulence() const noexcept { return turbulence != Vec3<double>(0.0); }
    /// Patterns whose value is one of a few discrete ones (checker: 0 or 1; hexagon: 0, 1/2 or 1,
    /// its three colours); they take no wave.
    [[nodiscard]] bool is_discrete() const noexcept {
        return kind == PatternKind::checker || kind == PatternKind::hexagon;
    }
};

/// POV-Ray's Mandelbrot set of exponent 2 over the x-y plane (Mandel2Pattern): z <- z^2 + c from
/// z = c = x + iy; a point escaping (|z|^2 > 4) at iteration n is coloured by the exterior type,
/// one that does not within the count by the interior type (mindist2: the least |z|^2 on its way).
/// Every case is POV-Ray's, its interior type 6 (a^2 + b^2 * factor, as written there) included.
inline double mandel_value(double x, double y, const FractalParams& f) noexcept {
    double a = x, b = y, a2 = a * a, b2 = b * b, mindist2 = a2 + b2;
    for (int n = 0; n < f.iterations; ++n) {
        b = 2.0 * a * b + y;
        a = a2 - b2 + x;
        a2 = a * a;
        b2 = b * b;
        const double dist2 = a2 + b2;
        mindist2 = std::min(mindist2, dist2);
        if (dist2 > 4.0) {
            const double k = f.exterior_factor;
            switch (f.exterior_type) {
            case 0: return k;
            case 1: return double(n) / double(f.iterations);
            case 2: return a * k;
            case 3: return b * k;
            case 4: return a2 * k;
            case 5: return b2 * k;
            case 6: return std::sqrt(dist2) * k;
            // POV-Ray's n % unsigned(k), in doubles: no conversion to overflow for a huge factor,
            // and 0 where POV-Ray would divide by zero (k below 1).
            case 7: return k >= 1.0 ? std::fmod(double(n), std::floor(k)) / k : 0.0;
            case 8: return k > 0.0 ? std::fmod(double(n), std::floor(1.0 + k)) / k : 0.0;
            default: return 0.0;
            }
        }
    }
    const double k = f.interior_factor;
    switch (f.interior_type) {
    case 0: return k;
    case 1: return std::sqrt(mindist2) * k;
    case 2: return a * k;
    case 3: return b * k;
    case 4: return a2 * k;
    case 5: return b2 * k;
    case 6: return a2 + b2 * k;
    default: return 0.0;
    }
}

/// POV-Ray's spirals about the z axis (Spiral1Pattern, Spiral2Pattern): the height along z plus
/// the distance from the axis plus `arms` turns per revolution of the angle; spiral2 folds that
/// and the distance by a triangle wave each and adds them, two spirals crossing.
inline double spiral_value(const Vec3<double>& p, int arms, bool crossed) noexcept {
    constexpr double pi = 3.14159265358979323846;
    const double rad = std::sqrt(p.x * p.x + p.y * p.y);
    const double phi = rad == 0.0 ? 0.0 : p.x < 0.0 ? 1.5 * pi - std::asin(p.y / rad) : 0.5 * pi + std::asin(p.y / rad);
    const double value = p.z + rad + double(arms) * phi / (2.0 * pi);
    return crossed ? pov_triangle_wave(rad) + pov_triangle_wave(value) : value;
}

/// POV-Ray's quilted offset: the point's offset from its unit cell's centre, scaled by a cubic
/// Bezier of its length through the two controls (quilt_cubic); what `normal { quilted }` adds.
inline Vec3<double> quilt_offset(const Vec3<double>& p, double control0, double control1) noexcept {
    const Vec3<double> v(p.x - std::floor(p.x) - 0.5, p.y - std::floor(p.y) - 0.5, p.z - std::floor(p.z) - 0.5);
    const double t = glm::length(v), it = 1.0 - t;
    return v * ((t * t * t + 3.0 * t * it * it * control0 + 3.0 * t * t * it * control1) * 1.154700538);
}

/// POV-Ray's quilted pattern: the quilt offset's components averaged.
inline double quilted_value(const Vec3<double>& p, double control0, double control1) noexcept {
    const Vec3<double> v = quilt_offset(p, control0, control1);
    return (std::fabs(v.x) + std::fabs(v.y) + std::fabs(v.z)) / 3.0;
}

namespace pattern_detail {

/// POV-Ray's 10 wave sources for ripples and waves (Initialize_Waves), and their frequencies.
struct WaveSources {
    std::array<Vec3<double>, 10> source{};
    std::array<double, 10> frequency{};
    WaveSources() noexcept {
        int state = -560851967;
        for (int i = 0; i < 10; ++i) {
            source[std::size_t(i)] = glm::normalize(pov_dnoise(Vec3<double>(double(i), 0.0, 0.0)));
            frequency[std::size_t(i)] = double(noise_detail::pov_next(state)) * 0.000030518509476 + 0.01;
        }
    }
};
inline const WaveSources& wave_sources() noexcept {
    static const WaveSources sources;
    return sources;
}

/// POV-Ray's hexagon: a tiling of the x-z plane by regular hexagons of unit edge-to-edge width
/// along x, in three colours so that no two neighbours share one; 0, 1 or 2 (HexagonPattern::
/// Evaluate). The plane is cut into half-triangle blocks of 0.5 by sqrt(3)/2, repeating every 6
/// blocks each way; 4 of each 6 columns of blocks lie inside one hexagon, the other 2 are split
/// by a hexagon's slanted edge. POV-Ray mirrors x (|x|) and shifts negative z by one period
/// (5.196152424) so the tiling does not mirror across the x axis; kept for the same picture.
inline int hexagon_colour(double x, double z) noexcept {
    x = std::fabs(x);
    z = z < 0.0 ? 5.196152424 - std::fabs(z) : z;
    double xs = x / 0.5, zs = z / 0.866025404;
    xs -= std::floor(xs / 6.0) * 6.0;
    zs -= std::floor(zs / 6.0) * 6.0;
    const int xm = int(std::floor(xs)) % 6, zm = int(std::floor(zs)) % 6;
    switch (xm) {
    case 0:
    case 5: return zm == 0 || zm == 5 ? 0 : zm <= 2 ? 1 : 2;
    case 2:
    case 3: return zm <= 1 ? 2 : zm <= 3 ? 0 : 1;
    default: {  // 1, 4: the block is split by a diagonal edge
        double xl = xs - xm;
        const double zl = zs - zm;
        if ((xm + zm) % 2 == 1) xl = 1.0 - xl;  // a negative slope, flipped
        if (xl == 0.0) xl = 0.0001;              // POV-Ray's guard against the division
        const bool below = zl / xl < 1.0;
        const int row = zm % 3;                  // zm 0/3, 1/4, 2/5 behave alike
        if (below) return row == 0 ? 0 : row == 2 ? 1 : 2;
        return row == 0 ? 2 : row == 2 ? 0 : 1;
    }
    }
}

/// The pattern's formula before its wave, at a point already turbulence-warped.
inline double raw_value(const Pattern& pat, const Vec3<double>& p, double cell_epsilon) noexcept {
    switch (pat.kind) {
    case PatternKind::checker: {
        const double e = cell_epsilon;
        const auto v = static_cast<long long>(std::floor(p.x + e) + std::floor(p.y + e) + std::floor(p.z + e));
        return (v & 1) ? 1.0 : 0.0;
    }
    case PatternKind::gradient: {
        const double length = glm::length(pat.gradient);
        const double r = length > 0 ? glm::dot(p, pat.gradient) / length : 0.0;
        return r > 1.0 ? std::fmod(r, 1.0) : r;
    }
    case PatternKind::bozo:
    case PatternKind::spotted:
    case PatternKind::bumps: return pov_noise(p, pat.noise_generator);
    case PatternKind::dents: {
        const double n = pov_noise(p, pat.noise_generator);
        return n * n * n;
    }
    case PatternKind::wrinkles: {
        // Ten octaves of noise, each twice as fine and half as strong; generators 2 and 3 stretch
        // each octave's noise to [-0.5, 1.5] and clamp it (WrinklesPattern, POV-Ray 3.7).
        const auto octave = [&](const Vec3<double>& q) {
            const double n = pov_noise(q, pat.noise_generator);
            return pat.noise_generator == NoiseGenerator::original ? n : std::clamp(n * 2.0 - 0.5, 0.0, 1.0);
        };
        double value = octave(p), lambda = 2.0, omega = 0.5;
        for (int i = 1; i < 10; ++i, lambda *= 2.0, omega *= 0.5) value += omega * octave(p * lambda);
        return value / 2.0;
    }
    case PatternKind::granite: {
        double value = 0, freq = 1;
        for (int i = 0; i < 6; ++i, freq *= 2.0) {
            const double n = pov_noise(p * 4.0 * freq, pat.noise_generator);
            const double t = pat.noise_generator == NoiseGenerator::original ? std::fabs(0.5 - n)
                                                                             : std::min(0.5, std::fabs(1.0 - 2.0 * n));
            value += t / freq;
        }
        return value;
    }
    case PatternKind::marble:
        return p.x + (pat.has_turbulence() ? pat.turbulence.x * pov_turbulence(p, pat.octaves, pat.noise_generator) : 0.0);
    case PatternKind::wood: {
        Vec3<double> q(p.x, p.y, 0.0);
        if (pat.has_turbulence()) {
            const Vec3<double> t = pov_dturbulence(p, pat.octaves);
            q.x += pov_cycloidal((p.x + t.x) * pat.turbulence.x);
            q.y += pov_cycloidal((p.y + t.y) * pat.turbulence.y);
        }
        return glm::length(q);
    }
    case PatternKind::agate: {
        const double turb = pat.agate_turb * pov_turbulence(p, pat.octaves, pat.noise_generator);
        const double n = 0.5 * (pov_cycloidal(1.3 * turb + 1.1 * p.z) + 1.0);
        return n < 0.0 ? 0.0 : std::pow(std::min(1.0, n), 0.77);
    }
    case PatternKind::onion: return std::fmod(glm::length(p), 1.0);
    case PatternKind::leopard: {
        const double s = (std::sin(p.x) + std::sin(p.y) + std::sin(p.z)) / 3.0;
        return s * s;
    }
    case PatternKind::radial:
        if (std::fabs(p.x) < 0.001 && std::fabs(p.z) < 0.001) return 0.25;
        return 0.25 + (std::atan2(p.x, p.z) + 3.14159265358979323846) / 6.28318530717958647692;
    case PatternKind::ripples:
    case PatternKind::waves: {
        const WaveSources& w = wave_sources();
        double sum = 0;
        for (std::size_t i = 0; i < w.source.size(); ++i) {
            double length = glm::length(p - w.source[i]);
            if (length == 0.0) length = 1.0;
            if (pat.kind == PatternKind::ripples)
                sum += pov_cycloidal(length * pat.wave.frequency + pat.wave.phase);
            else
                sum += pov_cycloidal(length * pat.wave.frequency * w.frequency[i] + pat.wave.phase) / w.frequency[i];
        }
        const double mean = sum / double(w.source.size());
        return pat.kind == PatternKind::ripples ? 0.5 * (1.0 + mean) : 0.2 * (2.5 + mean);
    }
    case PatternKind::spherical: return std::clamp(1.0 - glm::length(p), 0.0, 1.0);
    case PatternKind::planar: return std::clamp(1.0 - std::fabs(p.y), 0.0, 1.0);
    case PatternKind::boxed:
        return std::clamp(1.0 - std::max({std::fabs(p.x), std::fabs(p.y), std::fabs(p.z)}), 0.0, 1.0);
    case PatternKind::cylindrical: return std::clamp(1.0 - std::sqrt(p.x * p.x + p.z * p.z), 0.0, 1.0);
    case PatternKind::hexagon: return 0.5 * hexagon_colour(p.x, p.z);
    case PatternKind::cells: return cells_value(p);
    case PatternKind::crackle: return crackle_value(p, pat.crackle, pat.noise_generator);
    case PatternKind::mandel: return mandel_value(p.x, p.y, pat.fractal);
    case PatternKind::spiral1:
    case PatternKind::spiral2: return spiral_value(p, pat.spiral_arms, pat.kind == PatternKind::spiral2);
    case PatternKind::quilted: return quilted_value(p, pat.quilt_control0, pat.quilt_control1);
    }
    return 0.0;
}

}  // namespace pattern_detail

/// The pattern's value at `p` (in the pattern's own space): POV-Ray's turbulence warp, its
/// formula, then frequency, phase and wave (not for checker and hexagon, whose values pick list
/// entries).
/// `cell_epsilon`: a point this close below a cell boundary of checker counts as inside the cell
/// above (POV-Ray's 1e-10), so that a floor at y = 0 does not flicker between two cells with the
/// rounding error of its hit points; single-precision hit points need a larger one (Pigment).
[[nodiscard]] inline double evaluate(const Pattern& pat, Vec3<double> p, double cell_epsilon = 1.0e-10) noexcept {
    if (pat.has_turbulence() && pat.kind != PatternKind::marble && pat.kind != PatternKind::wood)
        p += pov_dturbulence(p, pat.octaves) * pat.turbulence;
    const double raw = pattern_detail::raw_value(pat, p, cell_epsilon);
    return pat.is_discrete() ? raw : pat.wave(raw);
}

}  // namespace photon
