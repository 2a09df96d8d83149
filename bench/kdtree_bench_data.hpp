// SPDX-License-Identifier: MIT
#pragma once
// Point sets for the kd-tree benchmark: photon-like points on the walls of a Cornell box, and
// points uniform in a cube. Fixed seeds, so every run sees the same points.

#include <cmath>
#include <cstdint>
#include <optional>
#include <vector>

#include "photon/math/rng.hpp"
#include "photon/photonmap/photon.hpp"

namespace photon::bench {

enum class Distribution { cornell, cube };

inline const char* name(Distribution d) { return d == Distribution::cornell ? "cornell" : "cube"; }

// The interior [-1.2,1.2]x[0,1.8]x[-1.2,1.2] without its front wall (z = +1.2).
inline constexpr float box_half = 1.2f, box_height = 1.8f;

// Where a ray from inside the box leaves it; nothing when it leaves through the open front.
inline std::optional<Vec3<float>> exit_point(const Vec3<float>& o, const Vec3<float>& d) {
    float t = INFINITY;
    int wall = -1;
    auto consider = [&](float tt, int w) {
        if (tt > 0.0f && tt < t) {
            t = tt;
            wall = w;
        }
    };
    if (d.x != 0.0f) consider(((d.x > 0.0f ? box_half : -box_half) - o.x) / d.x, 0);
    if (d.y != 0.0f) consider(((d.y > 0.0f ? box_height : 0.0f) - o.y) / d.y, 1);
    if (d.z != 0.0f) consider(((d.z > 0.0f ? box_half : -box_half) - o.z) / d.z, d.z > 0.0f ? 3 : 2);
    if (wall < 0 || wall == 3) return std::nullopt;
    Vec3<float> p = o + t * d;
    if (wall == 0) p.x = d.x > 0.0f ? box_half : -box_half;
    if (wall == 1) p.y = d.y > 0.0f ? box_height : 0.0f;
    if (wall == 2) p.z = -box_half;
    return p;
}

// A point uniform (by area) on the five walls.
inline Vec3<float> point_on_walls(Pcg32& rng) {
    constexpr float floor_area = 4 * box_half * box_half, side_area = 2 * box_half * box_height;
    constexpr float total = 2 * floor_area + 3 * side_area;
    const float pick = rng.uniform<float>() * total;
    const float u = rng.uniform<float>() * 2.0f - 1.0f, v = rng.uniform<float>();
    if (pick < floor_area) return {u * box_half, 0.0f, (2.0f * v - 1.0f) * box_half};
    if (pick < 2 * floor_area) return {u * box_half, box_height, (2.0f * v - 1.0f) * box_half};
    if (pick < 2 * floor_area + side_area) return {u * box_half, v * box_height, -box_half};
    if (pick < 2 * floor_area + 2 * side_area) return {-box_half, v * box_height, u * box_half};
    return {box_half, v * box_height, u * box_half};
}

// Half the photons come straight from a 0.5 x 0.5 light under the ceiling centre (cosine
// emission, so they crowd the floor under it); the other half stand for diffusely bounced
// photons, spread evenly over the walls.
inline std::vector<Photon> cornell_photons(std::size_t n, std::uint64_t seed) {
    Pcg32 rng(seed, 0);
    std::vector<Photon> out;
    out.reserve(n);
    while (out.size() < n) {
        Vec3<float> p;
        if (rng.uniform<float>() < 0.5f) {
            const Vec3<float> o{(rng.uniform<float>() - 0.5f) * 0.5f, box_height - 0.01f, (rng.uniform<float>() - 0.5f) * 0.5f};
            const float u1 = rng.uniform<float>(), phi = 2.0f * pi<float> * rng.uniform<float>();
            const float s = std::sqrt(u1);
            const auto hit = exit_point(o, {s * std::cos(phi), -std::sqrt(1.0f - u1), s * std::sin(phi)});
            if (!hit) continue;
            p = *hit;
        } else {
            p = point_on_walls(rng);
        }
        const Rgb<float> power{rng.uniform<float>(), rng.uniform<float>(), rng.uniform<float>()};
        out.push_back({p, PackedPhoton(power, glm::normalize(Vec3<float>(0.3f, -1.0f, 0.2f)), PathKind::direct)});
    }
    return out;
}

inline std::vector<Vec3<float>> cornell_queries(std::size_t n, std::uint64_t seed) {
    Pcg32 rng(seed, 1);
    std::vector<Vec3<float>> out(n);
    for (auto& q : out) q = point_on_walls(rng);
    return out;
}

inline Vec3<float> in_cube(Pcg32& rng) {
    return {rng.uniform<float>() * 2.0f - 1.0f, rng.uniform<float>() * 2.0f - 1.0f, rng.uniform<float>() * 2.0f - 1.0f};
}

inline std::vector<Photon> cube_points(std::size_t n, std::uint64_t seed) {
    Pcg32 rng(seed, 2);
    std::vector<Photon> out(n);
    for (auto& p : out) p = {in_cube(rng), PackedPhoton({1.0f, 1.0f, 1.0f}, {0.0f, -1.0f, 0.0f}, PathKind::indirect)};
    return out;
}

inline std::vector<Vec3<float>> cube_queries(std::size_t n, std::uint64_t seed) {
    Pcg32 rng(seed, 3);
    std::vector<Vec3<float>> out(n);
    for (auto& q : out) q = in_cube(rng);
    return out;
}

}  // namespace photon::bench
