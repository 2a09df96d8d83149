// SPDX-License-Identifier: MIT
#pragma once
// photon: global illumination by photon mapping. This umbrella header includes every public
// header but two, which bring in heavy third-party headers: io/obj_mesh.hpp (tinyobjloader; CMake
// target photon::obj) and film/image_io.hpp (OpenImageIO, half of this header's compile time):
// include that one where images are written or read. Each header can also be included on its own.

#include "config.hpp"
#include "version.hpp"

#include "math/frame.hpp"
#include "math/octahedral.hpp"
#include "math/rng.hpp"
#include "math/sampling.hpp"
#include "math/transform.hpp"
#include "math/vec.hpp"

#include "geometry/bbox.hpp"
#include "geometry/box.hpp"
#include "geometry/bvh.hpp"
#include "geometry/cone.hpp"
#include "geometry/cylinder.hpp"
#include "geometry/disc.hpp"
#include "geometry/hit.hpp"
#include "geometry/offset.hpp"
#include "geometry/plane.hpp"
#include "geometry/polygon.hpp"
#include "geometry/polynomial_surface.hpp"
#include "geometry/primitive.hpp"
#include "geometry/quadric.hpp"
#include "geometry/ray.hpp"
#include "geometry/sphere.hpp"
#include "geometry/torus.hpp"
#include "geometry/transformed.hpp"
#include "geometry/triangle.hpp"
#include "geometry/triangle_mesh.hpp"

#include "material/fresnel.hpp"
#include "material/highlight.hpp"
#include "material/material.hpp"
#include "material/medium.hpp"
#include "material/scatter.hpp"

#include "texture/bump_map.hpp"
#include "texture/color_map.hpp"
#include "texture/image_map.hpp"
#include "texture/layer_color.hpp"
#include "texture/noise.hpp"
#include "texture/normal_field.hpp"
#include "texture/normal_pattern.hpp"
#include "texture/pattern.hpp"
#include "texture/pigment.hpp"
#include "texture/reflectance_field.hpp"
#include "texture/wave.hpp"

#include "light/cone.hpp"
#include "light/environment.hpp"
#include "light/light.hpp"
#include "light/point_light.hpp"
#include "light/sphere_light.hpp"

#include "scene/camera.hpp"
#include "scene/fog.hpp"
#include "scene/media_segment.hpp"
#include "scene/scene.hpp"

#include "photonmap/kdtree.hpp"
#include "photonmap/neighbors.hpp"
#include "photonmap/photon.hpp"
#include "photonmap/point_traits.hpp"

#include "tracing/caustic_targets.hpp"
#include "tracing/light_allocation.hpp"
#include "tracing/photon_tracer.hpp"

#include "estimator/density_estimate.hpp"
#include "estimator/filters.hpp"
#include "estimator/visible_disc.hpp"

#include "settings/effect_switches.hpp"
#include "settings/render_settings.hpp"

#include "integrator/boundary_probe.hpp"
#include "integrator/direct_lighting.hpp"
#include "integrator/environment_lighting.hpp"
#include "integrator/fog_seen.hpp"
#include "integrator/media_march.hpp"
#include "integrator/media_seen.hpp"
#include "integrator/radiance.hpp"
#include "integrator/reference_render.hpp"
#include "integrator/render.hpp"
#include "integrator/render_stats.hpp"
#include "integrator/shading_context.hpp"
#include "plan/effects_plan.hpp"
#include "plan/plan_report.hpp"
#include "plan/shape_facts.hpp"

#include "film/error_estimate.hpp"
#include "film/film.hpp"
#include "film/tone_map.hpp"

#include "memory/huge_page_allocator.hpp"

#include "parallel/parallel_for.hpp"
