// SPDX-License-Identifier: MIT
#pragma once
// Memory a render will need, estimated from its settings before anything is allocated, and
// checked against the memory the system has available: an oversized request (a 65536 x 65536
// film, 10^11 photons) ends with a message naming the sizes instead of std::bad_alloc or the
// kernel's OOM killer halfway through pass 1.

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <fstream>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <unistd.h>

#include "../film/film.hpp"
#include "../photonmap/photon.hpp"
#include "../settings/render_settings.hpp"

namespace photon {

/// A render's largest simultaneous use of memory, in bytes, by part.
struct MemoryEstimate {
    double film = 0;         ///< the film and the image writer's buffer
    double photon_maps = 0;  ///< traced photons, the balanced maps and precomputed irradiance
    [[nodiscard]] double total() const noexcept { return film + photon_maps; }
};

/// Bytes held per stored photon at the peak of pass 1: the traced array, its copy in trace order
/// (for the irradiance precomputation), the kd-tree's positions and payloads, the build's index
/// permutation and the normal (render.hpp, build_photon_maps).
inline constexpr double bytes_per_stored_photon = 3.0 * sizeof(Photon) + 8.0 + 2.0;

/// Upper bound on the expected number of times one emitted photon is stored: a photon is stored
/// only at hits on surfaces with a diffuse part, and leaves each by Russian roulette with
/// probability rho_d,avg + rho_s,avg + rho_t,avg <= `max_albedo` (of those surfaces), so it reaches
/// its j-th store with probability at most max_albedo^(j-1); at most `max_depth` hits.
[[nodiscard]] inline double stores_per_photon(double max_albedo, unsigned max_depth) noexcept {
    const double rho = std::clamp(max_albedo, 0.0, 1.0);
    if (rho >= 1.0) return double(max_depth);
    return (1.0 - std::pow(rho, double(max_depth))) / (1.0 - rho);
}

/// The photon passes a render runs: the settings' counts, or fewer where the light-path plan
/// drops a pass (EffectsPlan: global_photons, caustic_photons, precomputed_irradiance).
struct PhotonPasses {
    std::size_t global_photons = 0, caustic_photons = 0;
    bool precomputed_irradiance = false;
};

/// The passes `s` asks for, before any plan.
[[nodiscard]] inline PhotonPasses requested_passes(const RenderSettings& s) noexcept {
    return {s.global_photons, s.caustic_photons, s.irradiance_stride > 0};
}

/// The estimate for `settings` running `passes` in a scene whose materials reflect at most
/// `max_albedo`.
[[nodiscard]] inline MemoryEstimate estimate_memory(const RenderSettings& s, double max_albedo, const PhotonPasses& passes) {
    MemoryEstimate m;
    const double pixels = double(s.width) * double(s.height);
    m.film = pixels * (sizeof(Rgb<float>) + 3.0 * sizeof(float));
    if (s.mode == RenderMode::pm || s.mode == RenderMode::pm_direct) {
        const double per_photon = stores_per_photon(max_albedo, s.max_photon_depth) * bytes_per_stored_photon;
        const double irradiance =
            passes.precomputed_irradiance && s.irradiance_stride > 0 ? 64.0 / double(s.irradiance_stride) : 0.0;
        m.photon_maps = (double(passes.global_photons) + double(passes.caustic_photons)) * per_photon +
                        double(passes.global_photons) * irradiance;
    }
    if (s.mode == RenderMode::sppm) {
        // Per pixel: its statistics (SppmPixel, 64 bytes). Per photon hit of one pass: the traced
        // record, the kd-tree's position and payload, and the build's two item arrays and index.
        m.film += pixels * 64.0;
        const double per_hit = 36.0 + 12.0 + 24.0 + 2.0 * 16.0 + 4.0;
        m.photon_maps = double(s.sppm_photons_per_pass) * stores_per_photon(max_albedo, s.max_photon_depth) * per_hit;
    }
    return m;
}

/// The estimate for every pass `s` asks for.
[[nodiscard]] inline MemoryEstimate estimate_memory(const RenderSettings& s, double max_albedo = 1.0) {
    return estimate_memory(s, max_albedo, requested_passes(s));
}

/// Bytes the system can give without swapping: MemAvailable from /proc/meminfo (Linux), else the
/// free physical pages; nullopt when neither is known.
[[nodiscard]] inline std::optional<double> available_memory() {
    std::ifstream meminfo("/proc/meminfo");
    std::string key;
    double kib = 0;
    std::string unit;
    while (meminfo >> key >> kib >> unit)
        if (key == "MemAvailable:") return kib * 1024.0;
#ifdef _SC_AVPHYS_PAGES
    const long pages = ::sysconf(_SC_AVPHYS_PAGES), page = ::sysconf(_SC_PAGESIZE);
    if (pages > 0 && page > 0) return double(pages) * double(page);
#endif
    return std::nullopt;
}

/// Error thrown when a render would need more memory than it may use.
class MemoryLimitError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

namespace detail {
inline std::string gib(double bytes) {
    std::ostringstream s;
    s.setf(std::ios::fixed);
    s.precision(1);
    if (bytes < double(1u << 30))
        s << bytes / double(1u << 20) << " MiB";
    else
        s << bytes / double(1u << 30) << " GiB";
    return s.str();
}
}  // namespace detail

/// Throws MemoryLimitError when `estimate` exceeds `limit` bytes (0: the memory available now).
inline void check_memory(const MemoryEstimate& estimate, double limit = 0) {
    if (limit <= 0) {
        const auto available = available_memory();
        if (!available) return;
        limit = *available;
    }
    if (estimate.total() <= limit) return;
    throw MemoryLimitError("not enough memory: the render needs up to " + detail::gib(estimate.total()) + " (film " +
                           detail::gib(estimate.film) + ", photon maps " + detail::gib(estimate.photon_maps) +
                           ") and " + detail::gib(limit) +
                           " is available: lower the resolution or the photon counts");
}

/// Highest survival probability of a photon at any material of `scene` that stores photons (one
/// with a diffuse part; 1 when unknown).
template <class SceneT>
[[nodiscard]] double max_albedo(const SceneT& scene) {
    if constexpr (requires { scene.materials(); }) {
        double rho = 0;
        for (const auto& material : scene.materials()) {
            if (!material.has_diffuse()) continue;  // never stores a photon (stores_per_photon)
            const auto& p = material.params();
            auto avg = [](const auto& c) { return (double(c.x) + double(c.y) + double(c.z)) / 3.0; };
            rho = std::max(rho, avg(material.max_diffuse()) + avg(p.specular) + avg(p.transmission));
        }
        return rho;
    } else {
        return 1.0;
    }
}

}  // namespace photon
