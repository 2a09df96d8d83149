// SPDX-License-Identifier: MIT
#pragma once
// POV-Ray 3.7's gamma mode of a scene, and so the working space of its render (film/tone_map.hpp).
// At the end of parsing (POV-Ray's parser.cpp, after the scene; renderfrontend.h, CreateView):
// - a scene whose last #version is below 3.7 (no #version at all reads as 3.62) and that writes no
//   assumed_gamma renders with gamma handling off: its numbers go to the file as they are, which
//   is the display's working space (sRGB on Debian: DEFAULT_DISPLAY_GAMMA_TYPE);
// - otherwise the numbers are of gamma `assumed_gamma` (1.0, linear, when a 3.7 scene writes none).
// The last #version is what counts: colors.inc and its kin set 3.5 and restore the version they
// found, which is 3.7 in a scene that wrote none before them, as POV-Ray's `version` reads.

#include <optional>

#include <photon/film/tone_map.hpp>

namespace photon::dsl {

/// Whether a scene renders with POV-Ray's gamma handling off (kPOVList_GammaMode_None).
[[nodiscard]] inline bool legacy_gamma(std::optional<double> assumed_gamma, std::optional<double> version) noexcept {
    return !assumed_gamma && version.value_or(3.62) < 3.7 - 1e-9;
}

/// The working space of a scene with `assumed_gamma` (if it writes one) and last `#version`.
[[nodiscard]] inline WorkingSpace scene_working_space(std::optional<double> assumed_gamma,
                                                      std::optional<double> version) noexcept {
    if (legacy_gamma(assumed_gamma, version)) return {.curve = WorkingSpace::Curve::srgb};
    return {.curve = WorkingSpace::Curve::power, .gamma = float(assumed_gamma.value_or(1.0))};
}

}  // namespace photon::dsl
