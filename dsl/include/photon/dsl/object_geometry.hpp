// SPDX-License-Identifier: MIT
#pragma once
// The library's answers to POV-Ray's trace(), min_extent() and max_extent(), which a scene asks
// while it is read (to place objects on a surface, to fit one object to another). Each question
// builds the object alone into a DefaultScene<double>, exactly as the render would build it, so
// the answer agrees with what is rendered.
//
// Header-only by default. With PHOTON_DSL_SEPARATE_COMPILATION (photon::dsl_compiled) this header
// only declares library_object_geometry(), which dsl/src/build.cpp compiles beside build<double>,
// whose Builder<double> it reuses: a program that sets it up no longer instantiates the builder.

#include <memory>

#include "parser/parse_options.hpp"

#if defined(PHOTON_DSL_SEPARATE_COMPILATION) && PHOTON_DSL_SEPARATE_COMPILATION && \
    !defined(PHOTON_DSL_COMPILING_OBJECT_GEOMETRY)
namespace photon::dsl {
/// trace(), min_extent() and max_extent() answered by photon's own geometry.
[[nodiscard]] std::shared_ptr<const ObjectGeometry> library_object_geometry();
}  // namespace photon::dsl
#else
#include <algorithm>
#include <limits>
#include <optional>

#include "build.hpp"

#if defined(PHOTON_DSL_COMPILING_OBJECT_GEOMETRY)
#define PHOTON_DSL_OBJECT_GEOMETRY_INLINE
#else
#define PHOTON_DSL_OBJECT_GEOMETRY_INLINE inline
#endif

namespace photon::dsl {

namespace detail {

/// `obj` alone, built as the render builds it (warnings are the render's business, not the query's).
inline DefaultScene<double> scene_of(const Object& obj) {
    SceneDescription desc;
    desc.objects.push_back(obj);
    desc.at = obj.at;
    Warnings quiet(nullptr);
    DefaultScene<double> scene;
    // Colours do not change the geometry: image maps are read as one grey pixel here.
    ImageFiles images(nullptr, {}, ImageFiles::colours_as_grey);
    Builder<double> builder(desc, quiet, BuildOptions{}.max_primitives, images);
    builder.read_files();
    builder.add_all(scene);
    scene.commit();
    return scene;
}

}  // namespace detail

/// trace(), min_extent() and max_extent() answered by photon's own geometry.
[[nodiscard]] PHOTON_DSL_OBJECT_GEOMETRY_INLINE std::shared_ptr<const ObjectGeometry> library_object_geometry() {
    auto g = std::make_shared<ObjectGeometry>();
    g->bounds = [](const Object& obj) {
        const DefaultScene<double> scene = detail::scene_of(obj);
        BBox<double> box;
        for (std::uint32_t i = 0; i < scene.objects().size(); ++i) box.extend(scene.object_bounds(i));
        // An unbounded part (a plane) reaches POV-Ray's BOUND_HUGE, 2e10, as in POV-Ray.
        static constexpr double huge = 2e10;
        auto clamp = [](const Vec3<double>& v) {
            return Vector3(std::clamp(v.x, -huge, huge), std::clamp(v.y, -huge, huge), std::clamp(v.z, -huge, huge));
        };
        if (box.min.x > box.max.x) return ObjectGeometry::Bounds{Vector3(0.0), Vector3(0.0)};  // nothing solid
        return ObjectGeometry::Bounds{clamp(box.min), clamp(box.max)};
    };
    g->trace = [](const Object& obj, const Vector3& origin, const Vector3& direction)
        -> std::optional<ObjectGeometry::Hit> {
        const DefaultScene<double> scene = detail::scene_of(obj);
        Ray<double> ray;
        ray.origin = origin;
        ray.direction = direction;
        const auto hit = scene.intersect(ray);
        if (!hit) return std::nullopt;
        // POV-Ray's normal faces the ray's origin.
        Vec3<double> n = hit->hit.normal;
        if (glm::dot(n, direction) > 0) n = -n;
        return ObjectGeometry::Hit{hit->hit.point, n};
    };
    return g;
}

}  // namespace photon::dsl
#endif
