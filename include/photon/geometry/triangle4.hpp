// SPDX-License-Identifier: MIT
#pragma once
// Four triangles side by side (structure of arrays) and the watertight test of a ray against all
// four at once: SSE for float, the scalar test lane by lane for double. Both give bit for bit the
// results of detail::intersect_watertight on each triangle (same operations, same order, no FMA).

#include <array>
#include <cmath>
#include <cstdint>
#include <limits>

#include "../config.hpp"
#include "triangle.hpp"

#if defined(__SSE2__) || defined(_M_X64)
#include <emmintrin.h>
#define PHOTON_TRIANGLE4_SSE 1
#else
#define PHOTON_TRIANGLE4_SSE 0
#endif

namespace photon::detail {

template <Scalar S> struct alignas(16) Triangle4 {
    /// v[vertex][axis][lane]. Unused lanes and triangles that can never be hit hold NaN, which
    /// fails every comparison of the test.
    std::array<std::array<std::array<S, 4>, 3>, 3> v;

    Triangle4() noexcept {
        for (auto& vertex : v)
            for (auto& axis : vertex) axis.fill(std::numeric_limits<S>::quiet_NaN());
    }
    void set(int lane, const Vec3<S>& v0, const Vec3<S>& v1, const Vec3<S>& v2) noexcept {
        for (int a = 0; a < 3; ++a) v[0][a][lane] = v0[a], v[1][a][lane] = v1[a], v[2][a][lane] = v2[a];
    }
    [[nodiscard]] Vec3<S> vertex(int lane, int k) const noexcept { return {v[k][0][lane], v[k][1][lane], v[k][2][lane]}; }
};

/// Tests the first `count` lanes of `tris` (count <= 4) for a ray whose shear axis is Kz: a bit
/// mask of the lanes hit in (0, t_max), with their distances in `t`.
template <int Kz, Scalar S>
[[nodiscard]] PHOTON_FORCEINLINE unsigned intersect_watertight4(const WatertightRay<S>& ray, S t_max,
                                                               const Triangle4<S>& tris, unsigned count,
                                                               std::array<S, 4>& t) noexcept {
    const unsigned lanes = (1u << count) - 1u;
#if PHOTON_TRIANGLE4_SSE
    if constexpr (std::is_same_v<S, float>) {
        constexpr int kx = (Kz + 1) % 3, ky = (Kz + 2) % 3;
        const __m128 sx = _mm_set1_ps(ray.sx), sy = _mm_set1_ps(ray.sy);
        __m128 px[3], py[3], pz[3];  // NOLINT: std::array would drop __m128's alignment attribute
        for (int k = 0; k < 3; ++k) {
            const __m128 x = _mm_sub_ps(_mm_load_ps(tris.v[k][kx].data()), _mm_set1_ps(ray.origin[kx]));
            const __m128 y = _mm_sub_ps(_mm_load_ps(tris.v[k][ky].data()), _mm_set1_ps(ray.origin[ky]));
            pz[k] = _mm_sub_ps(_mm_load_ps(tris.v[k][Kz].data()), _mm_set1_ps(ray.origin[Kz]));
            px[k] = _mm_sub_ps(x, _mm_mul_ps(sx, pz[k]));
            py[k] = _mm_sub_ps(y, _mm_mul_ps(sy, pz[k]));
        }
        // Vertices a, b, c = 0, 1, 2; edge functions as in intersect_watertight.
        const __m128 u = _mm_sub_ps(_mm_mul_ps(px[2], py[1]), _mm_mul_ps(py[2], px[1]));
        const __m128 v = _mm_sub_ps(_mm_mul_ps(px[0], py[2]), _mm_mul_ps(py[0], px[2]));
        const __m128 w = _mm_sub_ps(_mm_mul_ps(px[1], py[0]), _mm_mul_ps(py[1], px[0]));
        const __m128 zero = _mm_setzero_ps();
        const int zeros = _mm_movemask_ps(
            _mm_or_ps(_mm_or_ps(_mm_cmpeq_ps(u, zero), _mm_cmpeq_ps(v, zero)), _mm_cmpeq_ps(w, zero)));
        if ((static_cast<unsigned>(zeros) & lanes) == 0) {
            const __m128 negative = _mm_or_ps(_mm_or_ps(_mm_cmplt_ps(u, zero), _mm_cmplt_ps(v, zero)), _mm_cmplt_ps(w, zero));
            const __m128 positive = _mm_or_ps(_mm_or_ps(_mm_cmpgt_ps(u, zero), _mm_cmpgt_ps(v, zero)), _mm_cmpgt_ps(w, zero));
            const __m128 det = _mm_add_ps(_mm_add_ps(u, v), w);
            const __m128 abs_det = _mm_andnot_ps(_mm_set1_ps(-0.0f), det);
            // det != 0 and finite (NaN fails the comparison).
            const __m128 det_ok = _mm_and_ps(_mm_cmpneq_ps(det, zero),
                                             _mm_cmplt_ps(abs_det, _mm_set1_ps(std::numeric_limits<float>::infinity())));
            const __m128 sum = _mm_add_ps(_mm_add_ps(_mm_mul_ps(u, pz[0]), _mm_mul_ps(v, pz[1])), _mm_mul_ps(w, pz[2]));
            const __m128 tv = _mm_div_ps(_mm_mul_ps(_mm_set1_ps(ray.sz), sum), det);
            const __m128 t_ok = _mm_and_ps(_mm_cmpgt_ps(tv, zero), _mm_cmplt_ps(tv, _mm_set1_ps(t_max)));
            const __m128 hit = _mm_andnot_ps(_mm_and_ps(negative, positive), _mm_and_ps(det_ok, t_ok));
            _mm_storeu_ps(t.data(), tv);
            return static_cast<unsigned>(_mm_movemask_ps(hit)) & lanes;
        }
        // An edge function of exactly zero: the scalar test decides it in double.
    }
#endif
    unsigned mask = 0;
    for (unsigned lane = 0; lane < count; ++lane) {
        const auto hit = intersect_watertight<Kz>(ray, t_max, tris.vertex(int(lane), 0), tris.vertex(int(lane), 1),
                                                  tris.vertex(int(lane), 2));
        if (hit) mask |= 1u << lane, t[lane] = *hit;
    }
    return mask;
}

}  // namespace photon::detail
