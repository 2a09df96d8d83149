// SPDX-License-Identifier: MIT
#pragma once
// Deterministic inputs for the mesh benchmark: a displaced "asteroid" of about a million
// triangles and two ray sets over it.

#include <array>
#include <cmath>
#include <cstdint>
#include <vector>

#include "photon/geometry/ray.hpp"
#include "photon/math/rng.hpp"

namespace photon::bench {

struct MeshData {
    std::vector<Vec3<float>> positions;
    std::vector<std::array<std::uint32_t, 3>> triangles;
};

namespace detail {
// Value noise on the integer lattice, smoothly interpolated: the hash is mix64 of the cell.
inline float lattice(int x, int y, int z) {
    const std::uint64_t h = mix64((std::uint64_t(std::uint32_t(x)) << 42) ^ (std::uint64_t(std::uint32_t(y)) << 21) ^
                                  std::uint64_t(std::uint32_t(z)));
    return float(h >> 40) * 0x1p-24f * 2.0f - 1.0f;
}
inline float value_noise(const Vec3<float>& p) {
    const Vec3<float> f = glm::floor(p);
    const int x = int(f.x), y = int(f.y), z = int(f.z);
    Vec3<float> u = p - f;
    u = u * u * (3.0f - 2.0f * u);
    float c[2][2][2];
    for (int i = 0; i < 2; ++i)
        for (int j = 0; j < 2; ++j)
            for (int k = 0; k < 2; ++k) c[i][j][k] = lattice(x + i, y + j, z + k);
    auto lerp = [](float a, float b, float t) { return a + (b - a) * t; };
    const float x00 = lerp(c[0][0][0], c[1][0][0], u.x), x10 = lerp(c[0][1][0], c[1][1][0], u.x);
    const float x01 = lerp(c[0][0][1], c[1][0][1], u.x), x11 = lerp(c[0][1][1], c[1][1][1], u.x);
    return lerp(lerp(x00, x10, u.y), lerp(x01, x11, u.y), u.z);
}
/// Seven octaves: hills of a quarter of the radius down to bumps of a few triangles.
inline float fractal(const Vec3<float>& p) {
    float sum = 0, amplitude = 0.5f, frequency = 2.0f;
    for (int octave = 0; octave < 7; ++octave, amplitude *= 0.5f, frequency *= 2.07f)
        sum += amplitude * value_noise(p * frequency + float(octave) * 17.3f);
    return sum;
}
}  // namespace detail

/// A cube sphere (six n x n grids projected onto the unit sphere, 12 n^2 triangles) displaced
/// along the normal by fractal noise: large hills, fine bumps, overhang-free, closed. n = 289
/// gives 1,002,252 triangles with roughly uniform size, as from a scanner or a subdivision.
inline MeshData displaced_sphere(int n) {
    MeshData m;
    const int side = n + 1;
    m.positions.reserve(std::size_t(6 * side * side));
    m.triangles.reserve(std::size_t(12 * n * n));
    for (int face = 0; face < 6; ++face) {
        const int axis = face / 2;
        const float sign = face % 2 == 0 ? 1.0f : -1.0f;
        const auto base = static_cast<std::uint32_t>(m.positions.size());
        for (int j = 0; j <= n; ++j)
            for (int i = 0; i <= n; ++i) {
                // (2i - n) / n in integers first, so that the edge shared by two faces gets
                // bit-identical coordinates (negation commutes with rounding).
                const float a = float(2 * i - n) / float(n), b = float(2 * j - n) / float(n);
                Vec3<float> c;
                c[axis] = sign;
                c[(axis + 1) % 3] = a * sign;  // flipped on negative faces so all wind outward
                c[(axis + 2) % 3] = b;
                const Vec3<float> dir = glm::normalize(c);
                m.positions.push_back(dir * (1.0f + 0.3f * detail::fractal(dir)));
            }
        // Shared edges between faces are duplicated vertices at identical positions (the same
        // direction computed the same way), so the surface is watertight in value.
        for (int j = 0; j < n; ++j)
            for (int i = 0; i < n; ++i) {
                const std::uint32_t v00 = base + std::uint32_t(j * side + i), v10 = v00 + 1;
                const std::uint32_t v01 = v00 + std::uint32_t(side), v11 = v01 + 1;
                m.triangles.push_back({v00, v10, v11});
                m.triangles.push_back({v00, v11, v01});
            }
    }
    return m;
}

/// Primary rays of a pinhole camera at distance 3 looking at the origin, `res` x `res` pixels
/// visited in 8 x 8 tiles as a renderer does (coherent: neighbours follow each other).
inline std::vector<Ray<float>> primary_rays(int res) {
    std::vector<Ray<float>> rays;
    rays.reserve(std::size_t(res) * std::size_t(res));
    const Vec3<float> eye{0.4f, 0.9f, -3.0f};
    const Vec3<float> forward = glm::normalize(-eye);
    const Vec3<float> right = glm::normalize(glm::cross(Vec3<float>(0, 1, 0), forward));
    const Vec3<float> up = glm::cross(forward, right);
    const float half = std::tan(0.5f * 40.0f * pi<float> / 180.0f);
    for (int ty = 0; ty < res; ty += 8)
        for (int tx = 0; tx < res; tx += 8)
            for (int y = ty; y < std::min(ty + 8, res); ++y)
                for (int x = tx; x < std::min(tx + 8, res); ++x) {
                    const float sx = (2.0f * (float(x) + 0.5f) / float(res) - 1.0f) * half;
                    const float sy = (1.0f - 2.0f * (float(y) + 0.5f) / float(res)) * half;
                    rays.push_back({eye, glm::normalize(forward + sx * right + sy * up)});
                }
    return rays;
}

/// Incoherent rays: origins uniform in [-1.3, 1.3]^3 (inside and outside the surface),
/// directions uniform over the sphere, in random order, like photon and gather rays.
inline std::vector<Ray<float>> random_rays(std::size_t count, std::uint64_t seed) {
    std::vector<Ray<float>> rays;
    rays.reserve(count);
    Pcg32 rng(seed, 0);
    for (std::size_t i = 0; i < count; ++i) {
        const Vec3<float> o = (Vec3<float>(rng.uniform<float>(), rng.uniform<float>(), rng.uniform<float>()) * 2.0f - 1.0f) * 1.3f;
        const float z = 1.0f - 2.0f * rng.uniform<float>(), phi = 2.0f * pi<float> * rng.uniform<float>();
        const float s = std::sqrt(std::max(0.0f, 1.0f - z * z));
        rays.push_back({o, {s * std::cos(phi), s * std::sin(phi), z}});
    }
    return rays;
}

}  // namespace photon::bench
