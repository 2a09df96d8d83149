// SPDX-License-Identifier: MIT
#pragma once
// A `normal` as the library's NormalPerturbation: a normal pattern's own formula, or the slope of
// an evaluated pigment pattern, with its modifiers, bump size, accuracy and placement.

#include <string>

#include <photon/texture/bump_map.hpp>
#include <photon/texture/normal_field.hpp>
#include <photon/texture/normal_pattern.hpp>

#include "../description.hpp"
#include "pigment.hpp"

namespace photon::dsl {

/// The normal (its pattern set) as a library NormalPerturbation; `placement` maps the pattern's
/// space to the world.
template <Scalar S>
[[nodiscard]] NormalPerturbation<S> library_normal(const Normal& n, const Transform& placement) {
    static const std::pair<const char*, NormalKind> own[] = {{"bumps", NormalKind::bumps},
                                                             {"dents", NormalKind::dents},
                                                             {"ripples", NormalKind::ripples},
                                                             {"waves", NormalKind::waves},
                                                             {"wrinkles", NormalKind::wrinkles},
                                                             {"quilted", NormalKind::quilted}};
    NormalPattern np;
    np.kind = NormalKind::slope;
    for (const auto& [name, kind] : own)
        if (n.pattern->name == name) np.kind = kind;
    np.pattern = np.kind == NormalKind::slope ? library_pattern(*n.pattern) : with_modifiers(Pattern{}, *n.pattern);
    np.amount = n.amount;
    np.accuracy = n.accuracy;
    Affine<double> a;
    a.linear = placement.linear;
    a.translation = placement.translation;
    return NormalPerturbation<S>(std::move(np), a);
}

/// The normal as the library's normal field: a bump map (its image read through `images`, a
/// located error without them) or library_normal's perturbation.
template <Scalar S>
[[nodiscard]] AnyNormalField<S> library_normal_field(const Normal& n, const Transform& placement, ImageFiles* images) {
    if (!n.pattern->image) return AnyNormalField<S>(library_normal<S>(n, placement));
    const ImageMapDesc& m = *n.pattern->image;
    if (!images) throw Error(m.file.at, "bump maps are not read here (no image files were given to this build)");
    Affine<double> a;
    a.linear = placement.linear;
    a.translation = placement.translation;
    const ImageMapOptions mapping{.map_type = ImageMapType(m.map_type), .interpolate = ImageInterpolation(m.interpolate),
                                  .once = m.once};
    return AnyNormalField<S>(ImageBumpMap<S>(images->grid(m.file, false), mapping, n.amount, m.use_index, a));
}

}  // namespace photon::dsl
