// SPDX-License-Identifier: MIT
// The scene-language reader compiled once, for photon::dsl_compiled (see photon/dsl/parser.hpp).

#define PHOTON_DSL_COMPILING_PARSER 1
#include <photon/dsl/parser.hpp>
