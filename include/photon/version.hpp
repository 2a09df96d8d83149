// SPDX-License-Identifier: MIT
#pragma once

/// Library version; CMake parses these three lines.
#define PHOTON_VERSION_MAJOR 0
#define PHOTON_VERSION_MINOR 1
#define PHOTON_VERSION_PATCH 0

namespace photon {
inline constexpr int version_major = PHOTON_VERSION_MAJOR;
inline constexpr int version_minor = PHOTON_VERSION_MINOR;
inline constexpr int version_patch = PHOTON_VERSION_PATCH;
}  // namespace photon
