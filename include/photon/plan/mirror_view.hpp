// SPDX-License-Identifier: MIT
#pragma once
// Where the camera sees diffuse surfaces by way of mirrors and glass, for the caustic pilot
// (visible_caustics.hpp): a coarse grid of camera rays is followed through every specular bounce
// (both branches at glass) and each diffuse point reached after at least one of them marks its
// cell of a hash grid and the cells around it. Only images at least a quarter as bright as the
// surface count: a mirror's or the light through glass, not the faint Fresnel reflection on
// glass, which shows the whole room at a few percent and would make every caustic "seen".
// A caustic landing in a marked cell counts as seen,
// though the camera does not see it directly: a caustic on the floor behind the camera, seen in
// a mirror, is then aimed at like one seen directly. An estimate like the pilot it serves: it
// samples the mirror images at a few thousand rays, so a sliver of one can be missed (the
// caustic then comes from the global photons, as before).

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <unordered_set>

#include "../geometry/offset.hpp"
#include "../material/scatter.hpp"
#include "../scene/camera.hpp"

namespace photon {

/// How finely the camera's mirror images are sampled.
struct MirrorViewSettings {
    unsigned columns = 96, rows = 72;  ///< camera rays
    unsigned max_depth = 6;            ///< specular bounces followed
    unsigned cells_across = 64;        ///< grid cells along the scene's largest extent
    double min_throughput = 0.25;      ///< fainter images (channel mean of the chain's reflectances) do not count
};

template <Scalar S> class MirrorView {
public:
    MirrorView() = default;

    /// The mirror images of `scene` seen by `camera`; empty when the scene has no mirror or glass.
    template <class SceneT>
    MirrorView(const SceneT& scene, const Camera<S>& camera, const MirrorViewSettings& settings = {}) {
        bool specular = false;
        for (std::uint32_t i = 0; i < scene.objects().size() && !specular; ++i)
            specular = scene.any_material_of(i, [](const auto& m) { return m.is_specular(); });
        if (!specular) return;
        const BBox<S> bounds = scene.bounds();
        const S largest = bounds.is_finite() ? std::max({bounds.extent().x, bounds.extent().y, bounds.extent().z}) : S(0);
        // Only infinite planes: a cell of 1/64 of the camera's distance to the origin, or 1.
        const S scale = largest > S(0) ? largest : std::max(glm::length(camera.location()), S(1));
        cell_ = scale / S(std::max(1u, settings.cells_across));
        for (unsigned j = 0; j < settings.rows; ++j)
            for (unsigned i = 0; i < settings.columns; ++i) {
                const S u = (S(i) + S(0.5)) / S(settings.columns), v = (S(j) + S(0.5)) / S(settings.rows);
                if (const auto ray = camera.ray(u, v)) follow(scene, *ray, 0, S(1), settings);
            }
    }

    [[nodiscard]] bool empty() const noexcept { return cells_.empty(); }
    /// Whether `p` lies in or next to a cell where the camera sees a diffuse surface in a mirror.
    [[nodiscard]] bool sees(const Vec3<S>& p) const {
        return !cells_.empty() && cells_.count(key(cell_of(p))) > 0;
    }

private:
    using Cell = glm::vec<3, std::int64_t>;

    template <class SceneT>
    void follow(const SceneT& scene, Ray<S> ray, unsigned bounces, S throughput, const MirrorViewSettings& settings) {
        const auto surface = scene.intersect(ray);
        if (!surface) return;
        const Material<S>& material = *surface->material;
        const Vec3<S>& x = surface->hit.point;
        if (bounces > 0 && material.has_diffuse()) mark(x);
        if (bounces >= settings.max_depth || !material.is_specular()) return;
        const Facing<S> f = facing(material, x, surface->hit.normal, ray.direction);
        const S error = intersection_error(x, ray.origin);
        const Scattering<S> sc = material.scattering(x, f.shading_cos, f.entering);
        const auto branch = [&](const Ray<S>& next, S reflectance) {
            if (double(throughput * reflectance) >= settings.min_throughput)
                follow(scene, next, bounces + 1, throughput * reflectance, settings);
        };
        const Ray<S> reflected{offset_origin(x, f.normal, error), mirror_direction(ray.direction, f)};
        const S t = average(sc.transmission);
        if (t > S(0)) {
            if (const auto refracted = refraction_direction(ray.direction, f, relative_eta(material, f.entering)))
                branch(Ray<S>{offset_origin(x, -f.normal, error), *refracted}, t);
            else  // total internal reflection: the transmitted share is reflected too
                return branch(reflected, t + average(sc.specular));
        }
        branch(reflected, average(sc.specular));
    }

    [[nodiscard]] Cell cell_of(const Vec3<S>& p) const noexcept {
        const auto index = [&](S c) {
            const double k = std::floor(double(c) / double(cell_));
            return std::int64_t(std::clamp(k, -1e15, 1e15));
        };
        return Cell(index(p.x), index(p.y), index(p.z));
    }
    [[nodiscard]] static std::uint64_t key(const Cell& c) noexcept {
        const auto mix = [](std::uint64_t h, std::int64_t v) {
            return (h ^ std::uint64_t(v)) * 0x100000001b3ULL + 0x9e3779b97f4a7c15ULL;
        };
        return mix(mix(mix(0xcbf29ce484222325ULL, c.x), c.y), c.z);
    }
    /// The point's cell and its 26 neighbours: the sampled images are sparse, a landing point
    /// next to a sampled one counts.
    void mark(const Vec3<S>& p) {
        if (!is_finite(p)) return;
        const Cell c = cell_of(p);
        for (std::int64_t dz = -1; dz <= 1; ++dz)
            for (std::int64_t dy = -1; dy <= 1; ++dy)
                for (std::int64_t dx = -1; dx <= 1; ++dx) cells_.insert(key(c + Cell(dx, dy, dz)));
    }

    S cell_ = S(1);
    std::unordered_set<std::uint64_t> cells_;
};

}  // namespace photon
