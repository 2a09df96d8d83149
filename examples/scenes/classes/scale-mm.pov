// SPDX-License-Identifier: MIT
// Scene class "scale-mm": a scene 1 mm across (Scale = 0.001: the unit-sized scene scaled down). An open corner (floor, a white back wall, a
// red left wall), a white ball and a sphere light, written in units of a 1 m scene and scaled
// by Scale: every length and the light's radius times Scale, the light's intensity times Scale^2
// (so that irradiance, and hence every pixel's radiance, is the same). The photon search radii
// are not given: photon derives them from the photons' spacing, which scales with the scene.
// scale-km.pov and scale-mm.pov differ only in Scale, so their images must match each other and a
// 1 m version. Tests ray offsets, intersection tolerances and photon-map searches far from a
// 1 m scale, in float.
// Light paths: L D E, L D D+ E (the walls, floor and ball light each other). No specular surface.
// Part of the scene-class gallery (docs/scene-classes.md). Units: metres and watts.
//   photon render examples/scenes/classes/scale-mm.pov -o scale-mm.png

#version 3.7;

#declare Scale = 0.001;

global_settings { assumed_gamma 1.0 ambient_light rgb 0 max_trace_level 4 }

#ifdef (photon_version)
global_settings {
  width 320 height 240
  render_mode pm
  global_photons 200000
  caustic_photons 0
  global_estimate { count 100 }
  final_gather 256
  shadow_samples 16
  samples_per_pixel 4
}
#end

#declare Light_Intensity = 0.3*Scale*Scale;
#declare Light_Radius = 0.04*Scale;
#declare Fade_D = 0.001*Scale;

camera {
  location <0, 0.45, -1.1>*Scale
  look_at <0, 0.22, 0>*Scale
  up y
  right x*4/3
  angle 55
}

light_source {
  <0.05, 0.5, -0.1>*Scale, rgb Light_Intensity / (2*pi*Fade_D*Fade_D)
  area_light <2*Light_Radius, 0, 0>, <0, 0, 2*Light_Radius>, 5, 5 circular orient jitter
  fade_distance Fade_D fade_power 2
}

#declare White = texture { pigment { rgb 0.75 } finish { ambient 0 diffuse 1 } }

union {
  box { <-0.5, -0.01, -0.5>, <0.5, 0, 0.5> texture { White } }     // floor
  box { <-0.5, 0, 0.5>, <0.5, 0.6, 0.51> texture { White } }       // back wall
  box { <-0.51, 0, -0.5>, <-0.5, 0.6, 0.51> pigment { rgb <0.75, 0.25, 0.25> } finish { ambient 0 diffuse 1 } }
  sphere { <0.15, 0.15, 0.1>, 0.15 texture { White } }
  scale Scale
}
