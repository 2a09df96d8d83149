// SPDX-License-Identifier: MIT
#pragma once
// Aiming caustic photons only at the mirrors and glass whose caustics the camera sees. A pilot of
// a few hundred caustic photons per target, aimed as the caustic pass aims them, measures how much
// of the caustic power each target sends lands on a point the camera sees, directly or in a mirror
// or through glass (mirror_view.hpp samples where it sees those images). A target
// whose caustics the pilot never saw land in view (a glass ball behind the camera), or that brings
// under 1% of the caustic light the pilot saw, is not aimed at: its caustic photons go to the
// others. Nothing is lost by a wrong guess: the global pass hands the caustic map every L S+ D
// photon the caustic pass does not aim at (caustic_targets.hpp), so such a target's caustics are
// still rendered, from the sparser global photons. The walls of effects_plan.hpp prove a caustic
// unseen; this pilot only estimates, and so it moves the caustics to another map instead of
// dropping them.

#include <cstdint>
#include <vector>

#include "../tracing/caustic_targets.hpp"
#include "mirror_view.hpp"
#include "../tracing/photon_tracer.hpp"
#include "visible_power.hpp"

namespace photon {

/// How the caustic pilot measures and decides.
struct VisibleCausticsPilot {
    unsigned photons_per_target = 256;
    std::size_t max_photons = 65'536;  ///< in all: with many targets, fewer per target (at least 32)
    /// A target bringing less than this fraction of the caustic power the pilot saw land in view
    /// is not aimed at.
    double min_share = 0.01;
    std::uint64_t seed = 1;
};

/// What the pilot measured for one target.
struct TargetCausticsSeen {
    std::uint32_t object = 0;
    unsigned photons = 0;  ///< pilot photons aimed at it
    double landed = 0.0;   ///< caustic power (W, channel mean) that landed on a diffuse surface
    double seen = 0.0;     ///< of which on a point the camera sees: directly, from the side it landed on, or in a mirror
    double seen_in_mirrors = 0.0;  ///< of `seen`, on points seen only by way of mirrors or glass
};

/// The pilot for every object in `targets` (aimable caustic targets), with the lights `emits`
/// allows (empty: all). Deterministic for a seed; independent of the thread count.
template <class SceneT>
[[nodiscard]] std::vector<TargetCausticsSeen> visible_caustics(const SceneT& scene,
                                                               const Camera<typename SceneT::scalar_type>& camera,
                                                               const std::vector<std::uint32_t>& targets,
                                                               const std::vector<bool>& emits,
                                                               const VisibleCausticsPilot& pilot = {}) {
    using S = typename SceneT::scalar_type;
    std::vector<TargetCausticsSeen> result;
    if (targets.empty()) return result;
    const MirrorView<S> mirrors(scene, camera);
    const unsigned per_target = unsigned(std::max<std::size_t>(
        32, std::min<std::size_t>(pilot.photons_per_target, pilot.max_photons / targets.size())));
    for (std::size_t k = 0; k < targets.size(); ++k) {
        const std::uint32_t t = targets[k];
        std::vector<bool> others(scene.objects().size(), true);
        others[t] = false;
        TargetCausticsSeen measured{.object = t, .photons = per_target};
        const auto aim = caustic_aim(scene, others);
        const TracedPhotons traced = trace_caustic_photons(
            scene, {.photons = per_target, .max_depth = 16, .light_emits = emits, .seed = pilot.seed ^ (0x636175ULL + k), .threads = 1},
            aim);
        std::vector<Photon> landed = traced.photons;  // with a mirror plane's, which come back apart
        landed.insert(landed.end(), traced.unaimed_caustics.begin(), traced.unaimed_caustics.end());
        for (const Photon& p : landed) {
            const double power = double(average(p.packed.power()));
            measured.landed += power;
            const Vec3<S> at(p.position);
            // The direction slot points into the surface from the side the photon arrived on.
            const bool camera_side = on_camera_side(camera, at, Vec3<S>(p.packed.incident_direction()));
            if (camera_side && camera_sees(scene, camera, at)) {
                measured.seen += power;
            } else if (mirrors.sees(at)) {
                measured.seen += power;
                measured.seen_in_mirrors += power;
            }
        }
        result.push_back(measured);
    }
    return result;
}

/// The targets the pilot says not to aim at: none of their caustic power seen, or less than
/// `min_share` of all the targets' seen power together.
[[nodiscard]] inline std::vector<std::uint32_t> unseen_caustic_targets(const std::vector<TargetCausticsSeen>& measured,
                                                                       double min_share) {
    double total = 0.0;
    for (const auto& m : measured) total += m.seen;
    std::vector<std::uint32_t> unseen;
    for (const auto& m : measured)
        if (!(m.seen > 0.0) || m.seen < min_share * total) unseen.push_back(m.object);
    return unseen;
}

}  // namespace photon
