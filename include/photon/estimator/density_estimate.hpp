// SPDX-License-Identifier: MIT
#pragma once
// Irradiance from a photon map by density estimation (paper, section 3.3; Jensen 2001, ch. 7):
// E(x) = sum of photon powers over the area they were gathered from. Photons that belong to
// another surface are rejected, the paper's "light through thin walls" weakness:
//  - photons that arrived from behind the surface (incident direction against the normal),
//  - photons off the tangent plane: distances are measured in a metric flattened along the
//    normal (an ellipsoid instead of a sphere), so a wall's photons near a floor count as far,
//  - optionally, photons the shading point cannot see across the surface (a wall standing on the
//    floor): a VisibleDisc from probe rays clips the gather disc and its area (see visible_disc.hpp).

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include "../photonmap/kdtree.hpp"
#include "../photonmap/photon.hpp"
#include "filters.hpp"
#include "visible_disc.hpp"

namespace photon {

using PhotonMap = KdTree<Photon>;

struct EstimateSettings {
    unsigned k = 100;          ///< photons per estimate
    float max_radius = 0.1f;   ///< search radius cap, scene units
    FilterKernel kernel{};
    float flatten = 4.0f;      ///< distance along the normal counts this many times (1: sphere)
    bool reject_backfacing = true;
    unsigned boundary_probes = 0;  ///< rays that clip the disc at walls (0: off; 8 or 16 typical)
};

/// A photon found by the estimate and its squared (flattened) distance.
struct GatheredPhoton {
    float distance2;
    std::uint32_t index;
};

/// Per-thread scratch space, reused across estimates without allocating.
struct EstimateScratch {
    std::vector<GatheredPhoton> found;
};

namespace detail {

/// k nearest photons within max_radius in the flattened metric, as a kd-tree visitor. The tree
/// prunes with Euclidean distances, which never exceed flattened ones, so pruning stays exact.
/// Candidates are appended unsorted; when 1.5k have piled up, a selection keeps the k nearest and
/// the search radius shrinks to the k-th. That costs O(1) amortised per candidate instead of a
/// heap's O(log k), which matters for the large k (hundreds to thousands) of smooth estimates.
class DiscGather {
public:
    DiscGather(const PhotonMap& map, const Vec3<float>& x, const Vec3<float>& n, const EstimateSettings& s,
               const VisibleDisc* disc, std::vector<GatheredPhoton>& found) noexcept
        : map_(map), x_(x), n_(n), k_(std::max(1u, s.k)), bound2_(s.max_radius * s.max_radius),
          flatten2_(s.flatten * s.flatten - 1.0f), backfacing_(s.reject_backfacing), disc_(disc), found_(found) {
        found_.clear();
    }

    [[nodiscard]] float max_distance2() const noexcept { return bound2_; }

    void visit(std::uint32_t i, float d2) noexcept {
        const Vec3<float> offset = map_.position(i) - x_;
        const float h = glm::dot(offset, n_);
        const float flat2 = d2 + flatten2_ * h * h;
        if (!(flat2 < bound2_)) return;
        if (backfacing_ && !map_.payload(i).arrived_against(n_)) return;
        if (disc_ && !disc_->contains(offset - h * n_)) return;
        found_.push_back({flat2, i});
        if (found_.size() == k_ + k_ / 2 + 1) keep_nearest();
    }

    /// Leaves the k nearest (or all, if fewer were found) with the farthest last; returns whether
    /// k were found.
    bool finish() noexcept {
        if (found_.size() > k_) keep_nearest();
        if (found_.size() < k_) return false;
        std::swap(*std::max_element(found_.begin(), found_.end(), by_distance), found_.back());
        return true;
    }

private:
    static bool by_distance(const GatheredPhoton& a, const GatheredPhoton& b) noexcept {
        return a.distance2 < b.distance2;
    }
    void keep_nearest() noexcept {
        std::nth_element(found_.begin(), found_.begin() + std::ptrdiff_t(k_ - 1), found_.end(), by_distance);
        bound2_ = found_[k_ - 1].distance2;
        found_.resize(k_);
    }

    const PhotonMap& map_;
    Vec3<float> x_, n_;
    std::size_t k_;
    float bound2_, flatten2_;
    bool backfacing_;
    const VisibleDisc* disc_;
    std::vector<GatheredPhoton>& found_;
};

}  // namespace detail

/// Irradiance (W/m^2 per channel) at `x` on a surface with unit normal `n` facing the side being
/// shaded. When k photons are found, the k-th nearest is left out, which makes the estimate
/// unbiased for a uniform density ((k-1) / (pi r^2) is the unbiased k-nearest-neighbour density);
/// otherwise every photon found counts over the disc of radius max_radius. `disc`, if given,
/// clips the disc to what x can see.
///
/// The area divided by is pi r^2 with r the largest Euclidean (not flattened) distance among the
/// photons found. Photons are selected in the flattened metric, but on a curved surface the part
/// inside the flattened ellipsoid is a cap whose chord is shorter than the flattened radius, and a
/// cap of chord c on a sphere has area exactly pi c^2 (Archimedes), convex or concave. On a plane
/// both radii are the same. Dividing by the flattened radius reads a ball dark, more so the more
/// photons an estimate takes (docs/design.md, 'Radiance estimation').
template <Scalar S>
[[nodiscard]] Rgb<S> estimate_irradiance(const PhotonMap& map, const Vec3<S>& x, const Vec3<S>& n,
                                         const EstimateSettings& settings, EstimateScratch& scratch,
                                         const VisibleDisc* disc = nullptr) {
    if (map.empty() || settings.k == 0 || !(settings.max_radius > 0.0f)) return Rgb<S>(S(0));
    const Vec3<float> xf(x);
    detail::DiscGather gather(map, xf, Vec3<float>(n), settings, disc, scratch.found);
    map.search(xf, gather);
    bool k_found = gather.finish();
    const auto& found = scratch.found;
    if (found.empty()) return Rgb<S>(S(0));
    // k photons all at distance 0 (piled up at x, as behind a perfect lens) leave no radius: count
    // them over the largest disc instead, a finite lower bound rather than a black pixel.
    if (k_found && !(found.back().distance2 > 0.0f)) k_found = false;
    float r2 = settings.max_radius * settings.max_radius;  // the kernel's radius, flattened metric
    float area_r2 = r2;
    std::size_t used = found.size();
    if (k_found) {
        r2 = found.back().distance2;  // the k-th nearest, left out
        used = found.size() - 1;
        area_r2 = 0.0f;
        for (const GatheredPhoton& p : found) {
            const Vec3<float> offset = map.position(p.index) - xf;
            area_r2 = std::max(area_r2, glm::dot(offset, offset));
        }
        if (!(area_r2 > 0.0f)) area_r2 = r2;  // (all photons within rounding of x)
    }
    Rgb<float> sum(0.0f);
    const float inv_r2 = 1.0f / r2;
    for (std::size_t j = 0; j < used; ++j) {
        const GatheredPhoton& p = found[j];
        sum += settings.kernel.weight(std::min(1.0f, p.distance2 * inv_r2)) * map.payload(p.index).power();
    }
    const float area = disc ? disc->area(std::sqrt(area_r2)) : pi<float> * area_r2;
    if (!(area > 0.0f)) return Rgb<S>(S(0));
    return Rgb<S>(sum / (area * settings.kernel.mean_weight()));
}

}  // namespace photon
