// SPDX-License-Identifier: MIT
// The compiled unit of photon::compiled: the render functions for DefaultScene<float> and
// DefaultScene<double>, instantiated once (integrator/render_instantiations.hpp lists them).

#include <photon/integrator/render_instantiations.hpp>

namespace photon {
PHOTON_RENDER_INSTANTIATIONS(, float)
PHOTON_RENDER_INSTANTIATIONS(, double)
}  // namespace photon
