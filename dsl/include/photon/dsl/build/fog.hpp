// SPDX-License-Identifier: MIT
#pragma once
// POV-Ray's fogs as the library's (scene/fog.hpp), every one, in the order written: POV-Ray
// composes them all. A fog of distance 0 is skipped, as POV-Ray skips it.

#include <stdexcept>
#include <vector>

#include <photon/scene/fog.hpp>

#include "../description.hpp"
#include "../diagnostics.hpp"
#include "../value.hpp"

namespace photon::dsl {

/// Throws dsl::Error at the fog for a negative distance or fog_alt, or values that are not finite.
template <Scalar S> [[nodiscard]] std::vector<Fog<S>> build_fogs(const SceneDescription& desc) {
    std::vector<Fog<S>> fogs;
    for (const FogDescription& d : desc.fogs) {
        if (d.distance == 0.0) continue;
        if (d.distance < 0.0) throw Error(d.at, "fog: distance must be positive, found " + format_number(d.distance));
        if (d.type == 2 && d.altitude < 0.0)
            throw Error(d.at, "fog: a ground fog's fog_alt must be >= 0, found " + format_number(d.altitude));
        if (d.type == 2 && !(glm::length(d.up) > 0.0)) throw Error(d.at, "fog: up must not be zero");
        Fog<S> fog;
        fog.kind = d.type == 2 ? Fog<S>::Kind::ground : Fog<S>::Kind::constant;
        fog.distance = S(d.distance);
        fog.colour = Rgb<S>(d.color.rgb);
        fog.filter = S(d.color.filter);
        fog.transmit = S(d.color.transmit);
        fog.up = Vec3<S>(glm::normalize(d.up));
        fog.offset = S(d.offset);
        fog.altitude = d.type == 2 ? S(d.altitude) : S(1);  // 0: POV-Ray's default, a flat-topped layer
        if (d.turbulence)
            fog.turbulence = FogTurbulence{*d.turbulence, TurbulenceParams{d.octaves, d.omega, d.lambda}, d.turb_depth};
        try {
            fog.validate();
        } catch (const std::invalid_argument& e) {
            throw Error(d.at, e.what());
        }
        fogs.push_back(fog);
    }
    return fogs;
}

}  // namespace photon::dsl
