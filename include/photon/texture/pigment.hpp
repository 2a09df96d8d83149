// SPDX-License-Identifier: MIT
#pragma once
// POV-Ray's pigment: a pattern, the colour map its value picks from, and the pigment's own
// transformation. A ReflectanceField (reflectance_field.hpp), so a Material can take one as its
// spatially varying diffuse reflectance.

#include <algorithm>
#include <type_traits>
#include <utility>

#include "../math/transform.hpp"
#include "color_map.hpp"
#include "pattern.hpp"

namespace photon {

template <Scalar S> class Pigment {
public:
    /// `placement` maps the pattern's own space to the world (POV-Ray's pigment transformations,
    /// composed with those of the object after the pigment); it must be invertible.
    Pigment(Pattern pattern, ColorMap<S> colors, const Affine<double>& placement = {})
        : pattern_(std::move(pattern)), colors_(std::move(colors)), to_pattern_(placement.inverse()),
          bound_(colors_.upper_bound()) {
        // A float hit point on a surface at a cell boundary (a floor at y = 0) is off by a few ulps
        // of the coordinates around it: 1e-4 world units covers scenes up to about 1000 units
        // across, in the pattern's space as its transformation scales it.
        if constexpr (std::is_same_v<S, float>) {
            const double shrink = std::max({glm::length(to_pattern_.linear[0]), glm::length(to_pattern_.linear[1]),
                                            glm::length(to_pattern_.linear[2])});
            cell_epsilon_ = 1.0e-4 * shrink;
        }
    }

    /// POV-Ray's `checker a b`: value 0 picks a, 1 picks b.
    [[nodiscard]] static Pigment checker(const Rgb<S>& a, const Rgb<S>& b, const Affine<double>& placement = {}) {
        return Pigment(Pattern::of(PatternKind::checker), ColorMap<S>({{0.0, a}, {1.0, b}}), placement);
    }

    /// The colour at world point `p`.
    [[nodiscard]] Rgb<S> operator()(const Vec3<S>& p) const noexcept { return colors_(value(p)); }
    /// The pattern's value at world point `p`, the one the colour map picks from.
    [[nodiscard]] double value(const Vec3<S>& p) const noexcept {
        return evaluate(pattern_, to_pattern_.point(Vec3<double>(p)), cell_epsilon_);
    }
    /// Per channel, no point is brighter than this.
    [[nodiscard]] Rgb<S> upper_bound() const noexcept { return bound_; }

    [[nodiscard]] const Pattern& pattern() const noexcept { return pattern_; }
    [[nodiscard]] const ColorMap<S>& colors() const noexcept { return colors_; }

private:
    Pattern pattern_;
    ColorMap<S> colors_;
    Affine<double> to_pattern_;  ///< world -> pattern space
    Rgb<S> bound_;
    double cell_epsilon_ = 1.0e-10;  ///< POV-Ray's, for double hit points
};

}  // namespace photon
