// SPDX-License-Identifier: MIT
// build() for float and double compiled once, for photon::dsl_compiled (see photon/dsl/build.hpp),
// and library_object_geometry() (photon/dsl/object_geometry.hpp) beside it: it builds each queried
// object with Builder<double>, which build<double> instantiates here anyway.

#define PHOTON_DSL_COMPILING_OBJECT_GEOMETRY 1
#include <photon/dsl/build.hpp>
#include <photon/dsl/object_geometry.hpp>

namespace photon::dsl {
template BuiltScene<float> build<float>(const SceneDescription&, const BuildOptions&);
template BuiltScene<double> build<double>(const SceneDescription&, const BuildOptions&);
}  // namespace photon::dsl
