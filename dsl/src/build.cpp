// SPDX-License-Identifier: MIT
// build() for float and double compiled once, for photon::dsl_compiled (see photon/dsl/build.hpp).

#include <photon/dsl/build.hpp>

namespace photon::dsl {
template BuiltScene<float> build<float>(const SceneDescription&, const BuildOptions&);
template BuiltScene<double> build<double>(const SceneDescription&, const BuildOptions&);
}  // namespace photon::dsl
