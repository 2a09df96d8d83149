// SPDX-License-Identifier: MIT
#pragma once
// POV-Ray's media as the library's (material/medium.hpp), computing what POV-Ray 3.7 computes.
// Absorption and emission carry over as written. POV-Ray scatters k * scattering * C towards
// the eye, k its phase function (1 when isotropic), C the light's colour at the point; photon's
// lights give irradiance E = pi C (build/lights.hpp) and its phase functions are POV-Ray's over
// 4 pi, so the library's scattering is 4 times POV-Ray's and its extinction factor a quarter of
// POV-Ray's: the same light scattered, the same dimming. A density without a pattern is a
// constant that multiplies the coefficients (as POV-Ray's does); a patterned one is a library
// Pigment whose colours are densities (filter and transmit unused, as POV-Ray's lc.colour()),
// nesting as pigment_maps nest where its map's entries are densities.

#include <algorithm>
#include <memory>
#include <stdexcept>
#include <vector>

#include <photon/material/medium.hpp>

#include "../description.hpp"
#include "../diagnostics.hpp"
#include "../value.hpp"
#include "layers.hpp"
#include "pigment.hpp"
#include "warnings.hpp"

namespace photon::dsl {

/// A density whose map entries are densities themselves: the colour of the nested layers
/// (their filter and transmit unused, as POV-Ray's density ignores them).
template <Scalar S> struct NestedDensity {
    std::shared_ptr<const PigmentLayer<S>> layer;
    [[nodiscard]] Rgb<S> operator()(const Vec3<S>& p) const { return (*layer)(p).color; }
    [[nodiscard]] Rgb<S> upper_bound() const noexcept { return layer->envelope().color; }
};

namespace media_build_detail {

/// `c` with its negative channels at 0, warning once at `at` that they are.
[[nodiscard]] inline Vector3 nonnegative(const Vector3& c, const char* what, const SourceLocation& at, Warnings& warn) {
    if (c.x >= 0 && c.y >= 0 && c.z >= 0) return c;
    warn(at, std::string("negative media ") + what + " is used as 0: photon's media cannot add light by absorbing",
         "approximated media", what);
    return glm::max(c, Vector3(0.0));
}

[[nodiscard]] inline SourceLocation written_at(const MediaDescription& d, const char* key) {
    const auto it = d.written.find(key);
    return it != d.written.end() ? it->second : d.at;
}

}  // namespace media_build_detail

/// One media, its densities placed by `to_world` after their own transformations. Throws
/// dsl::Error at the media for values the library rejects.
template <Scalar S>
[[nodiscard]] Medium<S> build_medium(const MediaDescription& d, const Transform& to_world, Warnings& warn) {
    using namespace media_build_detail;
    Vector3 absorption = nonnegative(d.absorption, "absorption", written_at(d, "absorption"), warn);
    Vector3 emission = d.emission;
    Vector3 scattering = nonnegative(d.scattering, "scattering", written_at(d, "scattering"), warn);
    Medium<S> m;
    for (const Pigment& density : d.density) {
        if (!density.pattern) {  // a constant: it scales every coefficient
            const Vector3 c = nonnegative(density.color.rgb, "density", density.at, warn);
            absorption *= c, emission *= c, scattering *= c;
            continue;
        }
        const PigmentPattern& pattern = *density.pattern;
        const Transform placement = density.transform.then(to_world);
        if (std::any_of(pattern.nested.begin(), pattern.nested.end(), [](const auto& n) { return n != nullptr; })) {
            // Patterned entries (a density_map of densities): the nesting pigment_maps use.
            m.density.push_back(AnyReflectanceField<S>(NestedDensity<S>{std::make_shared<const PigmentLayer<S>>(
                layers_detail::pattern_layer<S>(pattern, placement, Vector3(1.0), warn, density.at))}));
            continue;
        }
        std::vector<typename ColorMap<S>::Entry> entries;
        for (const auto& [v, c] : pattern.colors) entries.push_back({v, Rgb<S>(glm::max(c.rgb, Vector3(0.0)))});
        Affine<double> a;
        a.linear = placement.linear;
        a.translation = placement.translation;
        m.density.push_back(
            AnyReflectanceField<S>(photon::Pigment<S>(library_pattern(pattern), ColorMap<S>(std::move(entries)), a)));
    }
    m.absorption = Rgb<S>(absorption);
    m.emission = Rgb<S>(emission);
    m.scattering = Rgb<S>(scattering * 4.0);
    m.extinction = S(std::max(0.0, d.extinction) / 4.0);
    m.phase = PhaseFunction(d.scattering_type);
    m.eccentricity = S(d.eccentricity);
    if (m.phase == PhaseFunction::henyey_greenstein && !(std::abs(d.eccentricity) < 0.999)) {
        warn(written_at(d, "scattering"), "a Henyey-Greenstein eccentricity of magnitude 1 or more is used as +-0.999",
             "approximated media", "eccentricity");
        m.eccentricity = S(std::clamp(d.eccentricity, -0.999, 0.999));
    }
    m.sampling.intervals = unsigned(std::max(1, d.intervals));
    m.sampling.samples = unsigned(std::max(1, d.samples_min));
    m.sampling.jitter = std::clamp(d.jitter, 0.0, 1.0);
    m.sampling.ratio = std::clamp(d.ratio, 0.0, 1.0);
    if (d.jitter > 1.0)
        warn(written_at(d, "jitter"), "media jitter above 1 is used as 1: photon keeps each sample within its step",
             "approximated media", "jitter");
    try {
        m.validate();
    } catch (const std::invalid_argument& e) {
        throw Error(d.at, e.what());
    }
    return m;
}

template <Scalar S>
[[nodiscard]] std::vector<Medium<S>> build_media(const std::vector<MediaDescription>& media, const Transform& to_world,
                                                 Warnings& warn) {
    std::vector<Medium<S>> out;
    for (const MediaDescription& d : media) out.push_back(build_medium<S>(d, to_world, warn));
    return out;
}

}  // namespace photon::dsl
