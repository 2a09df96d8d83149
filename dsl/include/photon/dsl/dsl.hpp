// SPDX-License-Identifier: MIT
#pragma once
// photon's scene language: POV-Ray 3.7 scene files read into the library's objects, in three
// stages (pbrt-v4 and Mitsuba style): lexer.hpp splits the text into located tokens; parser.hpp
// evaluates it into a SceneDescription (description.hpp), which holds no library type; build.hpp
// makes DefaultScene, Camera and RenderSettings from it. export_pov.hpp writes a
// description back as a POV-Ray file. Bad input throws dsl::Error (diagnostics.hpp).
//
//   auto desc = photon::dsl::parse_file("cornell.pov");
//   auto built = photon::dsl::build<float>(desc);
//   auto result = photon::render(built.scene, built.camera, built.settings);

#include "animation.hpp"
#include "build.hpp"
#include "description.hpp"
#include "diagnostics.hpp"
#include "export_pov.hpp"
#include "lexer.hpp"
#include "object_geometry.hpp"
#include "parser.hpp"
#include "value.hpp"

namespace photon::dsl {

/// parse_file then build, with one diagnostics sink for both.
template <Scalar S>
[[nodiscard]] BuiltScene<S> load_scene(const std::filesystem::path& path, ParseOptions parse_options = {},
                                       BuildOptions build_options = {}) {
    if (!build_options.diagnostics) build_options.diagnostics = parse_options.diagnostics;
    return build<S>(parse_file(path, parse_options), build_options);
}

}  // namespace photon::dsl
