// SPDX-License-Identifier: MIT
#pragma once
// Irradiance gradients (Ward and Heckbert 1992, "Irradiance Gradients"), estimated from the
// samples of one cosine-weighted final gather stratified in (theta, phi): M rows with sin^2 theta
// in [j/M, (j+1)/M) and N columns with phi in [2 pi k/N, 2 pi (k+1)/N). E = pi/(MN) sum L.
//  - Rotation: turning the normal by a small angle about axis a changes E by a . grad_r with
//    grad_r = integral of L (n x w) dw = pi/(MN) sum L (n x w) / cos theta.
//  - Translation: moving x shifts each cell boundary by (move / distance to the nearer of the two
//    hits across it), handing the projected solid angle of the strip it sweeps from one cell's
//    radiance to its neighbour's. Across the theta boundary j (j = 1..M-1), along u_k (phi at the
//    column's centre): sin theta cos^2 theta (2 pi/N) / min(r) (L_jk - L_j-1,k); across the phi
//    boundary k, along v_k (phi_k + pi/2): (sin theta_j+ - sin theta_j-) / min(r) (L_jk - L_j,k-1).
// A gather that met nothing (every distance infinite) and a zero radiance field give zero
// gradients; distances are floored so that a hit at the gather's own point cannot divide by 0.

#include <algorithm>
#include <array>
#include <cmath>
#include <span>

#include "../math/frame.hpp"
#include "../math/vec.hpp"

namespace photon {

/// The rows M (in theta) and columns N (in phi) of a gather of at least `rays` rays, with
/// N close to pi M so that the cells are about square in projected solid angle.
struct GatherStrata {
    unsigned rows = 1, columns = 1;
    [[nodiscard]] unsigned count() const noexcept { return rows * columns; }
    [[nodiscard]] static GatherStrata for_rays(unsigned rays) noexcept {
        const double r = std::max(1u, rays);
        const unsigned m = std::max(1u, unsigned(std::lround(std::sqrt(r / 3.14159265358979))));
        return {m, std::max(1u, unsigned(std::ceil(r / m - 1e-9)))};
    }
    /// Cosine-distributed local direction (z = normal) of cell (row j, column k) at jitter u.
    template <Scalar S> [[nodiscard]] Vec3<S> direction(unsigned j, unsigned k, Vec2<S> u) const noexcept {
        const S below_one = std::nextafter(S(1), S(0));
        const S sin2 = std::min((S(j) + u.x) / S(rows), below_one);
        const S phi = S(2) * pi<S> * (S(k) + u.y) / S(columns);
        const S sin_t = std::sqrt(sin2);
        return {sin_t * std::cos(phi), sin_t * std::sin(phi), std::sqrt(S(1) - sin2)};
    }
};

/// Per channel gradients of irradiance, in world space and in the record's tangent plane.
struct IrradianceGradients {
    std::array<Vec3<float>, 3> rotation{Vec3<float>(0.0f), Vec3<float>(0.0f), Vec3<float>(0.0f)};
    std::array<Vec3<float>, 3> translation{Vec3<float>(0.0f), Vec3<float>(0.0f), Vec3<float>(0.0f)};
};

/// One gather sample: the local direction (z = normal) it took, the radiance it brought and the
/// distance to what it hit (infinite: nothing).
template <Scalar S> struct GatherSample {
    Vec3<S> local;
    Rgb<S> radiance;
    S distance;
};

/// Ward and Heckbert's gradients from the samples of one gather, stored row by row (index
/// j * columns + k) in the frame `frame` (its normal is the gather's).
template <Scalar S>
[[nodiscard]] IrradianceGradients irradiance_gradients(std::span<const GatherSample<S>> samples, GatherStrata strata,
                                                       const Frame<S>& frame) {
    IrradianceGradients g;
    const unsigned m = strata.rows, n = strata.columns;
    if (samples.size() != std::size_t(m) * n) return g;
    const S floor_distance = S(1e-6);
    const auto at = [&](unsigned j, unsigned k) -> const GatherSample<S>& { return samples[std::size_t(j) * n + k]; };
    const auto nearer = [&](const GatherSample<S>& a, const GatherSample<S>& b) {
        return std::max(std::min(a.distance, b.distance), floor_distance);
    };
    std::array<Vec3<S>, 3> rot{Vec3<S>(S(0)), Vec3<S>(S(0)), Vec3<S>(S(0))};
    std::array<Vec3<S>, 3> trans = rot;
    const S dphi = S(2) * pi<S> / S(n);
    for (unsigned k = 0; k < n; ++k) {
        const S phi_mid = (S(k) + S(0.5)) * dphi, phi_edge = S(k) * dphi;
        const Vec3<S> u_k{std::cos(phi_mid), std::sin(phi_mid), S(0)};
        const Vec3<S> v_k{-std::sin(phi_edge), std::cos(phi_edge), S(0)};
        Rgb<S> along_u(S(0)), along_v(S(0));
        for (unsigned j = 0; j < m; ++j) {
            const GatherSample<S>& s = at(j, k);
            // Rotation: L (n x w) / cos theta, n x w = (-w.y, w.x, 0); cos theta > 0 by construction.
            const S cos_t = std::max(s.local.z, S(1e-6));
            const Vec3<S> turn{-s.local.y / cos_t, s.local.x / cos_t, S(0)};
            for (int c = 0; c < 3; ++c) rot[c] += s.radiance[c] * turn;
            if (j > 0) {
                const S sin2 = S(j) / S(m);  // at the boundary between rows j-1 and j
                const S weight = std::sqrt(sin2) * (S(1) - sin2) / nearer(s, at(j - 1, k));
                along_u += weight * (s.radiance - at(j - 1, k).radiance);
            }
            const GatherSample<S>& before = at(j, (k + n - 1) % n);
            const S band = std::sqrt(S(j + 1) / S(m)) - std::sqrt(S(j) / S(m));  // sin theta+ - sin theta-
            along_v += (band / nearer(s, before)) * (s.radiance - before.radiance);
        }
        for (int c = 0; c < 3; ++c) trans[c] += dphi * along_u[c] * u_k + along_v[c] * v_k;
    }
    const S scale = pi<S> / S(m * n);
    for (int c = 0; c < 3; ++c) {
        g.rotation[c] = Vec3<float>(frame.to_world(scale * rot[c]));
        g.translation[c] = Vec3<float>(frame.to_world(trans[c]));
        // Anything not finite (a radiance that was) is no usable slope: drop it.
        if (!std::isfinite(glm::dot(g.rotation[c], g.rotation[c]))) g.rotation[c] = Vec3<float>(0.0f);
        if (!std::isfinite(glm::dot(g.translation[c], g.translation[c]))) g.translation[c] = Vec3<float>(0.0f);
    }
    return g;
}

}  // namespace photon
