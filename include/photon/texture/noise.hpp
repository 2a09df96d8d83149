// SPDX-License-Identifier: MIT
#pragma once
// POV-Ray 3.7's solid noise, value for value (source/backend/texture/texture.cpp and
// core/material/noise.cpp, portablenoise.cpp of POV-Ray): the lattice noise of generators 1
// (original) and 2 (range corrected, POV-Ray's default), Perlin's gradient noise (generator 3),
// the vector noise DNoise, and fractal turbulence with octaves, omega and lambda. The tables are
// built once by POV-Ray's own pseudo-random sequence, so a pattern looks as it does in POV-Ray.
// Everything is computed in double, as POV-Ray does, whatever the caller's scalar type.

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>

#include "../math/vec.hpp"

namespace photon {

/// POV-Ray's `noise_generator`: 1 original, 2 range corrected (the default), 3 Perlin.
enum class NoiseGenerator : std::uint8_t { original = 1, range_corrected = 2, perlin = 3 };

/// POV-Ray's turbulence parameters: `octaves` noise layers, each `lambda` times finer and `omega`
/// times weaker than the one before.
struct TurbulenceParams {
    int octaves = 6;
    double omega = 0.5, lambda = 2.0;
};

namespace noise_detail {

/// POV-Ray's linear congruential step (int arithmetic wrapping at 32 bits) and its 15-bit draw.
inline int pov_next(int& state) noexcept {
    state = static_cast<int>(static_cast<std::uint32_t>(static_cast<std::int64_t>(state) * 1812433253LL + 12345LL));
    return (state >> 16) & 0x7FFF;
}

struct NoiseTables {
    static constexpr int entries = 2048;  // Perlin noise lattice (a power of two)
    std::array<double, 267 * 2> rtable{};
    std::array<unsigned short, 8192> hash{};
    std::array<int, 2 * (entries + 1)> permutation{};
    std::array<Vec3<double>, 2 * (entries + 1)> gradients{};

    NoiseTables() noexcept {
        static constexpr double random_table[267] = {
    -1, 0.604974, -0.937102, 0.414115, 0.576226, -0.0161593, 0.432334, 0.103685,
    0.590539, 0.0286412, 0.46981, -0.84622, -0.0734112, -0.304097, -0.40206, -0.210132,
    -0.919127, 0.652033, -0.83151, -0.183948, -0.671107, 0.852476, 0.043595, -0.404532,
    0.75494, -0.335653, 0.618433, 0.605707, 0.708583, -0.477195, 0.899474, 0.490623,
    0.221729, -0.400381, -0.853727, -0.932586, 0.659113, 0.961303, 0.325948, -0.750851,
    0.842466, 0.734401, -0.649866, 0.394491, -0.466056, -0.434073, 0.109026, 0.0847028,
    -0.738857, 0.241505, 0.16228, -0.71426, -0.883665, -0.150408, -0.90396, -0.686549,
    -0.785214, 0.488548, 0.0246433, 0.142473, -0.602136, 0.375845, -0.00779736, 0.498955,
    -0.268147, 0.856382, -0.386007, -0.596094, -0.867735, -0.570977, -0.914366, 0.28896,
    0.672206, -0.233783, 0.94815, 0.895262, 0.343252, -0.173388, -0.767971, -0.314748,
    0.824308, -0.342092, 0.721431, -0.24004, -0.63653, 0.553277, 0.376272, 0.158984,
    -0.452659, 0.396323, -0.420676, -0.454154, 0.122179, 0.295857, 0.0664225, -0.202075,
    -0.724788, 0.453513, 0.224567, -0.908812, 0.176349, -0.320516, -0.697139, 0.742702,
    -0.900786, 0.471489, -0.133532, 0.119127, -0.889769, -0.23183, -0.669673, -0.046891,
    -0.803433, -0.966735, 0.475578, -0.652644, 0.0112459, -0.730007, 0.128283, 0.145647,
    -0.619318, 0.272023, 0.392966, 0.646418, -0.0207675, -0.315908, 0.480797, 0.535668,
    -0.250172, -0.83093, -0.653773, -0.443809, 0.119982, -0.897642, 0.89453, 0.165789,
    0.633875, -0.886839, 0.930877, -0.537194, 0.587732, 0.722011, -0.209461, -0.0424659,
    -0.814267, -0.919432, 0.280262, -0.66302, -0.558099, -0.537469, -0.598779, 0.929656,
    -0.170794, -0.537163, 0.312581, 0.959442, 0.722652, 0.499931, 0.175616, -0.534874,
    -0.685115, 0.444999, 0.17171, 0.108202, -0.768704, -0.463828, 0.254231, 0.546014,
    0.869474, 0.875212, -0.944427, 0.130724, -0.110185, 0.312184, -0.33138, -0.629206,
    0.0606546, 0.722866, -0.0979477, 0.821561, 0.0931258, -0.972808, 0.0318151, -0.867033,
    -0.387228, 0.280995, -0.218189, -0.539178, -0.427359, -0.602075, 0.311971, 0.277974,
    0.773159, 0.592493, -0.0331884, -0.630854, -0.269947, 0.339132, 0.581079, 0.209461,
    -0.317433, -0.284993, 0.181323, 0.341634, 0.804959, -0.229572, -0.758907, -0.336721,
    0.605463, -0.991272, -0.0188754, -0.300191, 0.368307, -0.176135, -0.3832, -0.749569,
    0.62356, -0.573938, 0.278309, -0.971313, 0.839994, -0.830686, 0.439078, 0.66128,
    0.694514, 0.0565042, 0.54342, -0.438804, -0.0228428, -0.687068, 0.857267, 0.301991,
    -0.494255, -0.941039, 0.775509, 0.410575, -0.362081, -0.671534, -0.348379, 0.932433,
    0.886442, 0.868681, -0.225666, -0.062211, -0.0976425, -0.641444, -0.848112, 0.724697,
    0.473503, 0.998749, 0.174701, 0.559625, -0.029099, -0.337392, -0.958129, -0.659785,
    0.236042, -0.246937, 0.659449, -0.027512, 0.821897, -0.226215, 0.0181735, 0.500481,
    -0.420127, -0.427878, 0.566186,
        };
        for (int i = 0; i < 267; ++i) {
            rtable[std::size_t(2 * i)] = random_table[i];
            rtable[std::size_t(2 * i + 1)] = random_table[i] * 0.5;
        }
        // InitTextureTable: a shuffled 0..4095, twice.
        for (int i = 0; i < 4096; ++i) hash[std::size_t(i)] = static_cast<unsigned short>(i);
        int state = 0;
        for (int i = 4095; i >= 0; --i) {
            const int j = pov_next(state) % 4096;
            std::swap(hash[std::size_t(i)], hash[std::size_t(j)]);
        }
        for (int i = 0; i < 4096; ++i) hash[std::size_t(4096 + i)] = hash[std::size_t(i)];
        // InitSolidNoise: unit gradients by rejection, then a permutation.
        state = 1;
        for (int i = 0; i < entries; ++i) {
            Vec3<double> v;
            double s;
            do {
                for (int k = 0; k < 3; ++k)
                    v[k] = double((pov_next(state) % (entries << 1)) - entries) / double(entries);
                s = glm::dot(v, v);
            } while (s > 1.0 || s < 1.0e-5);
            gradients[std::size_t(i)] = v / std::sqrt(s);
        }
        for (int i = 0; i < entries; ++i) permutation[std::size_t(i)] = i;
        for (int i = entries; i > 0; i -= 2) {
            const int k = permutation[std::size_t(i)];
            const int j = pov_next(state) % entries;
            permutation[std::size_t(i)] = permutation[std::size_t(j)];
            permutation[std::size_t(j)] = k;
        }
        for (int i = 0; i < entries + 2; ++i) {
            permutation[std::size_t(entries + i)] = permutation[std::size_t(i)];
            gradients[std::size_t(entries + i)] = gradients[std::size_t(i)];
        }
    }
};

inline const NoiseTables& noise_tables() noexcept {
    static const NoiseTables tables;
    return tables;
}

inline double scurve(double t) noexcept { return t * t * (3.0 - 2.0 * t); }

/// An integral double as an int, wrapped modulo 2^30 into (-2^30, 2^30): a lattice cell number
/// without undefined behaviour. Cells within 1e9 of the origin (every coordinate a double can
/// still texture: past 2^52 it has no fraction left) keep their number, so POV-Ray's patterns are
/// unchanged there; past it the low 12 bits the lattices use are kept, and a NaN or infinite
/// coordinate gives cell 0. The 2^30 bound leaves room for the +-1 neighbours the callers add.
inline int lattice_cell(double integral) noexcept {
    if (!(std::abs(integral) < 9.0e18)) return 0;
    return int(std::int64_t(integral) % (std::int64_t(1) << 30));
}

/// Lattice cell of one coordinate as POV-Ray finds it ("JB fix for the range problem").
struct LatticeAxis {
    int index;        ///< cell, offset by -NOISE_MIN and masked to 12 bits
    double fraction;  ///< position inside the cell
};
inline LatticeAxis lattice_axis(double x) noexcept {
    constexpr double epsilon = 1.0e-10;
    constexpr int noise_min = -10000;
    const double tmp = x >= 0 ? std::trunc(x) : std::trunc(x - (1 - epsilon));
    return {(lattice_cell(tmp) - noise_min) & 0xFFF, x - tmp};
}

/// Perlin's gradient noise, in about [-1, 1] (POV-Ray's SolidNoise).
inline double solid_noise(const Vec3<double>& p) noexcept {
    const NoiseTables& t = noise_tables();
    constexpr double rollover = 10000000.023157213;
    int b0[3], b1[3];
    double r0[3], r1[3];
    for (int k = 0; k < 3; ++k) {
        const double v = p[k] + rollover;
        const double it = std::floor(v);
        b0[k] = lattice_cell(it) & (NoiseTables::entries - 1);
        b1[k] = (b0[k] + 1) & (NoiseTables::entries - 1);
        r0[k] = v - it;
        r1[k] = r0[k] - 1.0;
    }
    const auto perm = [&](int i) { return t.permutation[std::size_t(i)]; };
    const int i = perm(b0[0]), j = perm(b1[0]);
    const int b00 = perm(i + b0[1]), b10 = perm(j + b0[1]), b01 = perm(i + b1[1]), b11 = perm(j + b1[1]);
    const double sx = scurve(r0[0]), sy = scurve(r0[1]), sz = scurve(r0[2]);
    const auto at = [&](int g, double x, double y, double z) {
        const Vec3<double>& q = t.gradients[std::size_t(g)];
        return x * q.x + y * q.y + z * q.z;
    };
    const auto lerp = [](double s, double a, double b) { return a + s * (b - a); };
    double a = lerp(sx, at(b00 + b0[2], r0[0], r0[1], r0[2]), at(b10 + b0[2], r1[0], r0[1], r0[2]));
    double b = lerp(sx, at(b01 + b0[2], r0[0], r1[1], r0[2]), at(b11 + b0[2], r1[0], r1[1], r0[2]));
    const double c = lerp(sy, a, b);
    a = lerp(sx, at(b00 + b1[2], r0[0], r0[1], r1[2]), at(b10 + b1[2], r1[0], r0[1], r1[2]));
    b = lerp(sx, at(b01 + b1[2], r0[0], r1[1], r1[2]), at(b11 + b1[2], r1[0], r1[1], r1[2]));
    const double d = lerp(sy, a, b);
    return lerp(sz, c, d);
}

/// The eight lattice corners' contributions, as POV-Ray's PortableNoise/PortableDNoise sum them:
/// calls add(rtable offset, weight, dx, dy, dz) once per corner.
template <class Add> void lattice_corners(const Vec3<double>& p, Add&& add) noexcept {
    const NoiseTables& t = noise_tables();
    const LatticeAxis ax = lattice_axis(p.x), ay = lattice_axis(p.y), az = lattice_axis(p.z);
    const int ix = ax.index, iy = ay.index, iz = az.index;
    const double x0 = ax.fraction, y0 = ay.fraction, z0 = az.fraction, x1 = x0 - 1, y1 = y0 - 1, z1 = z0 - 1;
    const double sx = scurve(x0), sy = scurve(y0), sz = scurve(z0), tx = 1 - sx, ty = 1 - sy, tz = 1 - sz;
    const auto hash2 = [&](int a, int b) { return int(t.hash[std::size_t(int(t.hash[std::size_t(a)]) ^ b)]); };
    const auto index = [&](int h, int z) { return (t.hash[std::size_t(h ^ z)] & 0xFF) * 2; };
    const int h00 = hash2(ix, iy), h10 = hash2(ix + 1, iy), h01 = hash2(ix, iy + 1), h11 = hash2(ix + 1, iy + 1);
    add(index(h00, iz), tx * ty * tz, x0, y0, z0);
    add(index(h10, iz), sx * ty * tz, x1, y0, z0);
    add(index(h01, iz), tx * sy * tz, x0, y1, z0);
    add(index(h11, iz), sx * sy * tz, x1, y1, z0);
    add(index(h00, iz + 1), tx * ty * sz, x0, y0, z1);
    add(index(h10, iz + 1), sx * ty * sz, x1, y0, z1);
    add(index(h01, iz + 1), tx * sy * sz, x0, y1, z1);
    add(index(h11, iz + 1), sx * sy * sz, x1, y1, z1);
}

inline double corner_sum(const double* m, double s, double x, double y, double z) noexcept {
    return s * (m[1] + m[2] * x + m[4] * y + m[6] * z);
}

}  // namespace noise_detail

/// POV-Ray's Noise(): a smooth pseudo-random value in [0, 1] at p.
inline double pov_noise(const Vec3<double>& p, NoiseGenerator generator = NoiseGenerator::range_corrected) noexcept {
    if (generator == NoiseGenerator::perlin)
        return std::clamp(0.5 * (1.59 * noise_detail::solid_noise(p) + 0.985), 0.0, 1.0);
    const double* rt = noise_detail::noise_tables().rtable.data();
    double sum = 0;
    noise_detail::lattice_corners(p, [&](int m, double s, double x, double y, double z) {
        sum += noise_detail::corner_sum(rt + m, s, x, y, z);
    });
    if (generator == NoiseGenerator::range_corrected) return std::clamp((sum + 1.05242) * 0.48985582, 0.0, 1.0);
    return std::clamp(sum + 0.5, 0.0, 1.0);
}

/// POV-Ray's DNoise(): a smooth pseudo-random vector at p, each component in about [-1, 1].
inline Vec3<double> pov_dnoise(const Vec3<double>& p) noexcept {
    const double* rt = noise_detail::noise_tables().rtable.data();
    Vec3<double> r(0.0);
    noise_detail::lattice_corners(p, [&](int m, double s, double x, double y, double z) {
        r.x += noise_detail::corner_sum(rt + m, s, x, y, z);
        r.y += noise_detail::corner_sum(rt + m + 8, s, x, y, z);
        r.z += noise_detail::corner_sum(rt + m + 16, s, x, y, z);
    });
    return r;
}

/// POV-Ray's Turbulence(): fractal sum of noise over `octaves`.
inline double pov_turbulence(const Vec3<double>& p, const TurbulenceParams& t,
                         NoiseGenerator generator = NoiseGenerator::range_corrected) noexcept {
    const bool original = generator == NoiseGenerator::original;
    // Generators 2 and 3 stretch each layer to 2 n - 0.5 (only the first is clipped, as POV-Ray does).
    double value = original ? pov_noise(p, generator) : std::clamp(2.0 * pov_noise(p, generator) - 0.5, 0.0, 1.0);
    double l = t.lambda, o = t.omega;
    for (int i = 2; i <= t.octaves; ++i) {
        const double n = pov_noise(p * l, generator);
        value += o * (original ? n : 2.0 * n - 0.5);
        if (i < t.octaves) l *= t.lambda, o *= t.omega;
    }
    return value;
}

/// POV-Ray's DTurbulence(): fractal sum of dnoise over `octaves`.
inline Vec3<double> pov_dturbulence(const Vec3<double>& p, const TurbulenceParams& t) noexcept {
    Vec3<double> result = pov_dnoise(p);
    double l = t.lambda, o = t.omega;
    for (int i = 2; i <= t.octaves; ++i) {
        result += o * pov_dnoise(p * l);
        if (i < t.octaves) l *= t.lambda, o *= t.omega;
    }
    return result;
}

}  // namespace photon
