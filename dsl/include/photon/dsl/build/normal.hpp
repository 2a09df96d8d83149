// SPDX-License-Identifier: MIT
#pragma once
// A `normal` as the library's NormalPerturbation: a normal pattern's own formula, or the slope of
// an evaluated pigment pattern, with its modifiers, bump size, accuracy and placement.

#include <string>

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
                                                             {"wrinkles", NormalKind::wrinkles}};
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

}  // namespace photon::dsl
