// SPDX-License-Identifier: MIT
#pragma once
// The mean red radiance of a small render in one mode, for the tests where pm, sppm and the path
// tracer must agree on a scene's light (area lights, falloffs, parallel lights).

#include <catch2/catch.hpp>

#include <photon/photon.hpp>

#include <cmath>
#include <cstdint>

namespace photon_test {

struct ModeMeanSettings {
    unsigned size = 20;         ///< square image, pixels per side
    unsigned sppm_passes = 12;  ///< of 100,000 photons each
    std::uint64_t seed = 4;
};

/// Renders `scene` through `camera` in `mode` (200,000 global photons) and returns the mean of
/// the pixels' red channel, requiring every pixel finite.
template <class SceneT, class CameraT>
[[nodiscard]] double mode_mean(const SceneT& scene, const CameraT& camera, photon::RenderMode mode, unsigned spp,
                               const ModeMeanSettings& m = {}) {
    photon::RenderSettings s;
    s.mode = mode;
    s.width = s.height = m.size;
    s.samples_per_pixel = spp;
    s.global_photons = 200'000;
    s.sppm_passes = m.sppm_passes;
    s.sppm_photons_per_pass = 100'000;
    s.threads = 2;
    s.seed = m.seed;
    const photon::RenderResult r = photon::render(scene, camera, s);
    double sum = 0;
    for (const auto& p : r.film.pixels()) {
        REQUIRE(std::isfinite(double(p.x)));
        sum += p.x;
    }
    return sum / double(r.film.pixels().size());
}

}  // namespace photon_test
