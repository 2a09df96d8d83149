// SPDX-License-Identifier: MIT
#pragma once
// POV-Ray's wave types: how a pattern's raw value becomes the value that picks a colour, after
// `frequency` and `phase` (POV-Ray 3.7, Evaluate_TPat in source/backend/pattern/pattern.cpp).

#include <cmath>
#include <cstdint>

namespace photon {

enum class WaveType : std::uint8_t { ramp, sine, triangle, scallop, cubic, poly };

/// POV-Ray's cycloidal(): sin(2 pi x), periodic in x.
inline double pov_cycloidal(double x) noexcept {
    constexpr double two_pi = 6.28318530717958647692;
    if (x >= 0.0) return std::sin((x - std::floor(x)) * 50000.0 / 50000.0 * two_pi);
    return -std::sin((-(x + std::floor(-x))) * 50000.0 / 50000.0 * two_pi);
}

/// POV-Ray's Triangle_Wave(): 0 -> 1 -> 0 over each unit interval.
inline double pov_triangle_wave(double x) noexcept {
    const double offset = x >= 0.0 ? x - std::floor(x) : x + 1.0 + std::floor(std::fabs(x));
    return offset >= 0.5 ? 2.0 * (1.0 - offset) : 2.0 * offset;
}

/// The wave's shape and repetition: value * frequency + phase, wrapped into [0, 1] (by POV-Ray's
/// fmod with 1.00001, so that a value of exactly 1 stays 1), then shaped.
struct Wave {
    WaveType type = WaveType::ramp;
    double frequency = 1.0, phase = 0.0;
    double exponent = 1.0;  ///< poly_wave's exponent

    [[nodiscard]] double operator()(double value) const noexcept {
        if (frequency != 0.0) value = std::fmod(value * frequency + phase, 1.00001);
        if (value < 0.0) value -= std::floor(value);
        switch (type) {
        case WaveType::ramp: return value;
        case WaveType::sine: return (1.0 + pov_cycloidal(value)) * 0.5;
        case WaveType::triangle: return pov_triangle_wave(value);
        case WaveType::scallop: return std::fabs(pov_cycloidal(value * 0.5));
        case WaveType::cubic: return value * value * (-2.0 * value + 3.0);
        case WaveType::poly: return std::pow(value, exponent);
        }
        return value;
    }
};

}  // namespace photon
