// SPDX-License-Identifier: MIT
// Scene class "cone-light": two spotlights with sharp-edged cones on a white floor, nothing else:
// a sphere light (radius 0.1 m) emitting 3 W/sr into a cone of half-angle 20 degrees, tilted, and a
// point light emitting 2 W/sr into a cone of 15 degrees. Tests the light cones as the language
// writes them (`spotlight radius A falloff A tightness 0`: exactly the paper's light field of
// view): the power photons carry is the cone's, and the elliptical pools of light end sharply.
// Light paths: L D E only (a flat floor does not light itself), so ray tracing (rt) must match the
// judge too.
// Part of the scene-class gallery (docs/scene-classes.md). Metres and watts, as in cornell.pov.
//   photon render examples/scenes/classes/cone-light.pov -o cone-light.png

#version 3.7;

global_settings { assumed_gamma 1.0 ambient_light rgb 0 max_trace_level 4 }

#ifdef (photon_version)
global_settings {
  width 320 height 240
  render_mode pm
  global_photons 100000
  caustic_photons 0
  global_estimate { count 100 }
  final_gather 256
  shadow_samples 16
  samples_per_pixel 4
}
#end

#declare Fade_D = 0.001;

camera {
  location <0, 2.2, -1.8>
  look_at <0, 0, 0.2>
  up y
  right x*4/3
  angle 60
}

light_source {  // a sphere light with a cone, pointing down and to the left
  <-0.3, 1.5, -0.1>, rgb 3 / (2*pi*Fade_D*Fade_D)
  spotlight radius 20 falloff 20 tightness 0 point_at <-0.8, 0, 0.3>
  area_light <0.2, 0, 0>, <0, 0, 0.2>, 5, 5 circular orient jitter
  fade_distance Fade_D fade_power 2
}

light_source {  // a point light with a cone, pointing down and to the right
  <0.5, 1.2, 0.2>, rgb 2 / (2*pi*Fade_D*Fade_D)
  spotlight radius 15 falloff 15 tightness 0 point_at <0.7, 0, 0.5>
  fade_distance Fade_D fade_power 2
}

box { <-3, -0.02, -3>, <3, 0, 3> pigment { rgb 0.75 } finish { ambient 0 diffuse 1 } }   // floor
