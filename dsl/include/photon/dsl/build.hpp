// SPDX-License-Identifier: MIT
#pragma once
// From a SceneDescription to the library's objects: DefaultScene<S>, Camera<S> and
// RenderSettings, reading the mesh files the scene names (mesh_files.hpp). This is where
// POV-Ray's meaning becomes physics: the light-unit rule (a light's colour and fade give its
// radiant intensity), the finish-to-reflectance rule, the camera in POV-Ray's order of
// application. Library constructors that reject a value (std::invalid_argument) are reported as
// dsl::Error at the place the value was written.

#include <algorithm>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>

#include <photon/photon.hpp>

#include "build/camera.hpp"
#include "build/lights.hpp"
#include "build/material.hpp"
#include "build/scene_builder.hpp"
#include "build/settings.hpp"
#include "build/fog.hpp"
#include "build/sky.hpp"
#include "build/warnings.hpp"
#include "build/working_space.hpp"
#include "description.hpp"
#include "diagnostics.hpp"
#include "image_files.hpp"

namespace photon::dsl {

struct BuildOptions {
    SettingsOverrides overrides;
    /// Settings neither the file nor `overrides` writes take `photon render`'s defaults (the
    /// settings table's program_default: POV-Ray's anti-aliasing, the mode the file asks for...);
    /// false: the library's (RenderSettings' initializers).
    bool program_defaults = true;
    DiagnosticSink diagnostics;
    /// Objects and mesh triangles in the scene, the mesh files' triangles counted for every use
    /// (the parser bounds the rest with ParseOptions::max_primitives, the same default).
    std::size_t max_primitives = 10'000'000;
    /// Reads the image files of image maps, bump maps and height fields; unset, a scene naming
    /// one is an error at its name. Programs linking OpenImageIO pass photon::read_pixel_grid
    /// (photon/io/image_file.hpp); the photon program reads through its image module.
    ImageReader read_image;
};

template <Scalar S>
struct BuiltScene {
    DefaultScene<S> scene;
    Camera<S> camera;
    RenderSettings settings;
    /// The film holds numbers of this working space (POV-Ray's gamma rules: build/working_space.hpp),
    /// and an image written from it is first converted to linear by decode_working_space.
    WorkingSpace working_space{};
};

/// The library's scene, camera and render settings for `desc`. Throws dsl::Error with the
/// location of the offending value.
template <Scalar S>
[[nodiscard]] BuiltScene<S> build(const SceneDescription& desc, const BuildOptions& options = {}) {
    Warnings warn(options.diagnostics);
    ImageFiles images(options.read_image, ImageDecoding{desc.settings.assumed_gamma, desc.version});
    detail::Builder<S> builder(desc, warn, options.max_primitives, images);
    builder.read_files();
    RenderSettings settings = render_settings(desc, options.overrides, warn, options.program_defaults);
    CameraDescription cam;
    if (desc.camera)
        cam = *desc.camera;
    else
        warn(desc.at, "no camera: using POV-Ray's default camera at the origin looking along +z");
    const ResolvedCamera rc = resolve_camera(cam, double(settings.width) / double(settings.height), &warn);
    std::optional<Camera<S>> camera;
    try {
        camera.emplace(camera_projection(rc.type),
                       CameraFrame<S>{Vec3<S>(rc.location), Vec3<S>(rc.direction), Vec3<S>(rc.right), Vec3<S>(rc.up),
                                      S(rc.angle), S(rc.vertical_angle)},
                       FocalBlur<S>{S(rc.aperture), S(rc.focal_distance)});
    } catch (const std::invalid_argument& e) {
        throw Error(cam.at.known() ? cam.at : desc.at, e.what());
    }
    DefaultScene<S> scene;
    if (auto sky = build_environment<S>(desc, warn, &images)) scene.set_environment(std::move(*sky));
    for (const Fog<S>& fog : build_fogs<S>(desc)) scene.add_fog(fog);
    for (const Medium<S>& medium : build_media<S>(desc.media, Transform{}, warn)) scene.add_medium(medium);
    builder.set_build_threads(settings.threads);
    builder.add_all(scene);
    // The effects plan names objects and lights by where the file writes them.
    for (std::uint32_t id = 0; id < builder.object_locations().size(); ++id)
        scene.set_object_label(id, builder.object_locations()[id].str());
    for (std::size_t i = 0; i < builder.light_locations().size(); ++i)
        scene.set_light_label(i, builder.light_locations()[i].str());
    BvhConfig bvh = DefaultScene<S>::default_bvh_config;
    bvh.threads = settings.threads;
    scene.commit(bvh);
    // Said here, where the object's place in the file is known, for `check` and `render` alike
    // (render() lists the same objects in RenderStats::warnings for programs using the library).
    if (settings.mode != RenderMode::rt && settings.mode != RenderMode::reference && scene_has_caustics(scene))
        for (std::uint32_t id : unaimed_specular_objects(scene)) warn(builder.object_locations()[id], unaimed_caustics_warning);
    return BuiltScene<S>{std::move(scene), *camera, std::move(settings),
                         scene_working_space(desc.settings.assumed_gamma, desc.version)};
}

}  // namespace photon::dsl

// With PHOTON_DSL_SEPARATE_COMPILATION (photon::dsl_compiled), build() for the two scalar types is
// compiled once, in dsl/src/build.cpp.
#if defined(PHOTON_DSL_SEPARATE_COMPILATION) && PHOTON_DSL_SEPARATE_COMPILATION
namespace photon::dsl {
extern template BuiltScene<float> build<float>(const SceneDescription&, const BuildOptions&);
extern template BuiltScene<double> build<double>(const SceneDescription&, const BuildOptions&);
}  // namespace photon::dsl
#endif

