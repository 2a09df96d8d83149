// SPDX-License-Identifier: MIT
#pragma once
// What `photon check` reports of a built scene, and the lines of it that `photon render` prints
// too (check_command.cpp): compiled once for both commands.

#include <photon/dsl/build.hpp>

#include <string>
#include <vector>

namespace photon::cli {

/// The render settings in one line.
std::string settings_line(const RenderSettings& s);

/// What a render of `built` with `settings` will do (plan/effects_plan.hpp), one line per effect.
std::vector<std::string> plan_of(const dsl::BuiltScene<float>& built, const RenderSettings& settings);

}  // namespace photon::cli
