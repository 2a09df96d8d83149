// SPDX-License-Identifier: MIT
#pragma once
// Reads a POV-Ray 3.7 scene file (the subset documented in docs/scene-language.md) into a
// SceneDescription, evaluating it as POV-Ray does: directives (#declare, #local, #undef,
// #include, #if/#ifdef/#ifndef/#else/#elseif/#end, #while, #for, #switch/#case/#range/#break,
// #macro, #default, #version, #warning, #error) and macro calls are handled in the token stream,
// so they may appear anywhere; expressions are evaluated as they are read. Errors throw
// dsl::Error with the location; warnings go to ParseOptions::diagnostics. Input is bounded (file
// size, include depth, nesting, loop iterations, tokens, primitives), so no file can crash or
// hang the parser.
//
// The reader is split by concern under parser/ (see parser/parser_class.hpp for the index).
// Header-only by default. With PHOTON_DSL_SEPARATE_COMPILATION (CMake target
// photon::dsl_compiled) this header only declares parse_file and parse_string, and the reader is
// compiled once, in dsl/src/parser.cpp: about 20 CPU-seconds less for every file that parses.

#include <filesystem>
#include <string>

#include "description.hpp"
#include "parser/parse_options.hpp"

#if defined(PHOTON_DSL_SEPARATE_COMPILATION) && PHOTON_DSL_SEPARATE_COMPILATION
#define PHOTON_DSL_PARSER_INLINE
#else
#define PHOTON_DSL_PARSER_INLINE inline
#endif

namespace photon::dsl {

/// Reads the scene file at `path`. Throws dsl::Error on bad input.
[[nodiscard]] PHOTON_DSL_PARSER_INLINE SceneDescription parse_file(const std::filesystem::path& path,
                                                                   const ParseOptions& options = {});

/// Reads a scene from `text`; `name` is the file name in messages, and includes are looked up
/// relative to the current directory.
[[nodiscard]] PHOTON_DSL_PARSER_INLINE SceneDescription parse_string(std::string text, std::string name = "<string>",
                                                                     const ParseOptions& options = {});

}  // namespace photon::dsl

// The reader itself: in every including file when header-only, else only in dsl/src/parser.cpp.
#if !(defined(PHOTON_DSL_SEPARATE_COMPILATION) && PHOTON_DSL_SEPARATE_COMPILATION) || defined(PHOTON_DSL_COMPILING_PARSER)
#include "parser/token_stream.hpp"
#include "parser/scene_files.hpp"
#include "parser/symbol_table.hpp"
#include "parser/directives.hpp"
#include "parser/macros.hpp"
#include "parser/control_flow.hpp"
#include "parser/arrays.hpp"
#include "parser/file_io.hpp"
#include "parser/expressions.hpp"
#include "parser/builtins.hpp"
#include "parser/strings.hpp"
#include "parser/user_functions.hpp"
#include "parser/object_queries.hpp"
#include "parser/splines.hpp"
#include "parser/typed_values.hpp"
#include "parser/transforms.hpp"
#include "parser/degradation.hpp"
#include "parser/patterns.hpp"
#include "parser/images.hpp"
#include "parser/materials.hpp"
#include "parser/normals.hpp"
#include "parser/objects.hpp"
#include "parser/mesh2.hpp"
#include "parser/quadrics.hpp"
#include "parser/quadric_polygon.hpp"
#include "parser/prism.hpp"
#include "parser/polynomials.hpp"
#include "parser/revolved.hpp"
#include "parser/blob.hpp"
#include "parser/lights_camera.hpp"
#include "parser/settings.hpp"
#include "parser/sky.hpp"
#include "parser/fog.hpp"
#include "parser/media.hpp"
#include "parser/statements.hpp"

namespace photon::dsl {

PHOTON_DSL_PARSER_INLINE SceneDescription parse_file(const std::filesystem::path& path, const ParseOptions& options) {
    detail::Parser parser(options);
    return parser.parse_file(path);
}

PHOTON_DSL_PARSER_INLINE SceneDescription parse_string(std::string text, std::string name, const ParseOptions& options) {
    detail::Parser parser(options);
    return parser.parse_text(std::move(text), std::move(name));
}

}  // namespace photon::dsl
#endif
