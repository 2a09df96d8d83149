// SPDX-License-Identifier: MIT
#pragma once
// POV-Ray's background and sky_sphere as the library's sky (light/environment.hpp). POV-Ray 3.7
// (Trace::ComputeSky) composes the sky_sphere's pigments from the last written down, each
// times `emission`, the layers below showing through its filter and transmit, and the
// background colour under them all as one more, opaque layer: a layered pigment
// (texture/layered.hpp), evaluated at the ray's direction moved back by the sky_sphere's
// transformations; a scene older than 3.7 composes them as POV-Ray 3.6 did (legacy_sky.hpp).
// POV-Ray sees its sky with camera and reflected rays and, under radiosity,
// with its gathers; photon lights the scene with it where it renders global illumination
// (docs/scene-language.md).

#include <optional>
#include <stdexcept>
#include <vector>

#include <photon/light/environment.hpp>
#include <photon/texture/layered.hpp>

#include "../description.hpp"
#include "../diagnostics.hpp"
#include "layers.hpp"
#include "legacy_sky.hpp"
#include "warnings.hpp"

namespace photon::dsl {

/// The sky of `desc`: none without a background colour or sky_sphere (POV-Ray's background is
/// black). Throws dsl::Error at the sky_sphere for an emission that is negative or not finite.
template <Scalar S>
[[nodiscard]] std::optional<Environment<S>> build_environment(const SceneDescription& desc, Warnings& warn,
                                                             ImageFiles* images = nullptr) {
    Color background;  // POV-Ray ignores the background's filter and transmit (no alpha channel)
    if (desc.background) background.rgb = glm::max(desc.background->rgb, Vector3(0.0));
    if (!desc.sky_sphere || desc.sky_sphere->pigments.empty()) {
        if (background.rgb == Vector3(0.0)) return std::nullopt;
        return Environment<S>(Rgb<S>(background.rgb));
    }
    const SkySphere& sky = *desc.sky_sphere;
    try {
        std::vector<PigmentLayer<S>> layers;
        for (const Pigment& p : sky.pigments) {
            Texture t;
            t.pigment = p;
            layers.push_back(layers_detail::library_layer<S>(t, sky.transform, sky.emission, warn, p.at.known() ? p.at : sky.at, images));
        }
        if (desc.version.value_or(3.62) < 3.7 - 1e-9)  // POV-Ray 3.6's composition (legacy_sky.hpp)
            return Environment<S>(AnyReflectanceField<S>(LegacySky<S>(std::move(layers), Rgb<S>(background.rgb))));
        layers.insert(layers.begin(), PigmentLayer<S>(LayerColor<S>{Rgb<S>(background.rgb)}, Rgb<S>(S(1))));
        return Environment<S>(AnyReflectanceField<S>(LayeredPigment<S>(std::move(layers))));
    } catch (const std::invalid_argument& e) {
        throw Error(sky.at, std::string("sky_sphere: ") + e.what());
    }
}

}  // namespace photon::dsl
