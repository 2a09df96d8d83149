// SPDX-License-Identifier: MIT
#pragma once
// What the builder (shape_placement.hpp) and the parser's inside() (parser/object_queries.hpp)
// both make of a description: the library's affine map of a transformation, and the library's
// Blob of a blob.

#include <photon/geometry/blob.hpp>

#include "../description.hpp"

namespace photon::dsl::detail {

template <Scalar S>
Affine<S> to_affine(const Transform& t) {
    Affine<S> a;
    a.linear = glm::mat<3, 3, S, glm::defaultp>(t.linear);
    a.translation = Vec3<S>(t.translation);
    return a;
}

/// The blob in its own space (the object's transformation is the caller's). POV-Ray squares a
/// component's radius, so a negative one acts as its absolute value.
template <Scalar S> Blob<S> blob_of(const BlobShape& g) {
    using Component = typename Blob<S>::Component;
    std::vector<Component> components;
    for (const BlobShape::Component& c : *g.components) {
        const S radius = S(std::abs(c.radius)), strength = S(c.strength);
        Component k = c.cylinder ? Component::cylinder(Vec3<S>(c.a), Vec3<S>(c.b), radius, strength)
                                 : Component::sphere(Vec3<S>(c.a), radius, strength);
        k.placement = to_affine<S>(c.transform);
        components.push_back(k);
    }
    return Blob<S>(std::move(components), S(g.threshold));
}

}  // namespace photon::dsl::detail
