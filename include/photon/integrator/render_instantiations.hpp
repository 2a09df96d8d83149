// SPDX-License-Identifier: MIT
#pragma once
// The render functions for the scene language's scene types, DefaultScene<float> and
// DefaultScene<double>, listed once, with the effects plan (`photon check` prints it without
// rendering) and the scene's commit(), its BVH build (a large part of what examples/cornell.cpp
// took to compile without it). Header-only use instantiates them in every translation unit that
// renders, each slow to compile at -O3 (bench/README.md). A program built with
// PHOTON_SEPARATE_COMPILATION (CMake target photon::compiled) sees them as `extern template` and
// links the one compiled unit that instantiates them (src/render_instantiations.cpp); other scene
// types are unaffected.

#include "../scene/scene.hpp"
#include "render.hpp"

/// PHOTON_RENDER_INSTANTIATIONS(EXTERN, S): the explicit instantiations for DefaultScene<S>:
/// declarations with EXTERN = extern, definitions with EXTERN empty.
#define PHOTON_RENDER_INSTANTIATIONS(EXTERN, S)                                                                      \
    EXTERN template void DefaultScene<S>::commit(BvhConfig);                                                        \
    EXTERN template RenderResult render<DefaultScene<S>>(const DefaultScene<S>&, const Camera<S>&,            \
                                                         const RenderSettings&);                                     \
    EXTERN template PhotonMaps build_photon_maps<DefaultScene<S>>(const DefaultScene<S>&, const EffectsPlan&,      \
                                                                  const RenderSettings&, RenderStats&);              \
    EXTERN template PhotonMaps build_photon_maps<DefaultScene<S>>(const DefaultScene<S>&, const RenderSettings&,    \
                                                                  RenderStats&);                                     \
    EXTERN template Film render_image<DefaultScene<S>>(const DefaultScene<S>&, const Camera<S>&,              \
                                                       const PhotonMaps&, const RenderSettings&, RenderStats&,       \
                                                       const std::vector<bool>&, std::vector<std::uint32_t>*);       \
    EXTERN template IrradianceCache build_irradiance_cache<DefaultScene<S>>(                                         \
        const DefaultScene<S>&, const Camera<S>&, const PhotonMaps&, const RenderSettings&, RenderStats&,      \
        const std::vector<bool>&);                                                                                   \
    EXTERN template Film render_sppm<DefaultScene<S>>(const DefaultScene<S>&, const Camera<S>&,               \
                                                      const RenderSettings&, RenderStats&, const SppmPassCallback&,  \
                                                      Film*, std::array<Film, 2>*);                                  \
    EXTERN template Film render_reference<DefaultScene<S>>(const DefaultScene<S>&, const Camera<S>&,          \
                                                           const RenderSettings&, RenderStats&, Film*);              \
    EXTERN template EffectsPlan plan_effects<DefaultScene<S>>(const DefaultScene<S>&, const Camera<S>&,         \
                                                              const RenderSettings&);                                \
    EXTERN template EffectsPlan plan_effects<DefaultScene<S>>(const DefaultScene<S>&, const std::optional<Vec3<S>>&, \
                                                              const RenderSettings&, const std::vector<std::uint32_t>&);

#if defined(PHOTON_SEPARATE_COMPILATION) && PHOTON_SEPARATE_COMPILATION
namespace photon {
PHOTON_RENDER_INSTANTIATIONS(extern, float)
PHOTON_RENDER_INSTANTIATIONS(extern, double)
}  // namespace photon
#endif
