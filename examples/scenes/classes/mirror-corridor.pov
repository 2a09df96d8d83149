// SPDX-License-Identifier: MIT
// Scene class "mirror-corridor": two parallel mirrors (reflectance 0.9, 1.2 m apart, 4 m long) on
// a white floor, a red ball between them and a small sphere light (radius 0.08 m, 1.5 W/sr) above
// it. The camera looks into the right mirror at a slant and sees the corridor repeat; light and
// photons bounce between the mirrors many times. Tests long specular chains on both sides of the
// diffuse vertex, the ray depth (max_trace_level 16) and the photon depth (max_photon_depth 30).
// Light paths: L D E, L S+ D E (the light's mirror images lighting the floor and the ball),
// L D S+ E (the corridor seen in the mirrors), L S+ D S+ E, L D D+ E and L S+ D (S+ D)+ S* E.
// Part of the scene-class gallery (docs/scene-classes.md). Metres and watts, as in cornell.pov.
//   photon render examples/scenes/classes/mirror-corridor.pov -o mirror-corridor.png

#version 3.7;

global_settings { assumed_gamma 1.0 ambient_light rgb 0 max_trace_level 16 }

#ifdef (photon_version)
global_settings {
  width 320 height 240
  render_mode pm
  global_photons 200000
  caustic_photons 200000
  global_estimate { count 100 }
  caustic_estimate { count 60 }
  max_photon_depth 30
  final_gather 256
  shadow_samples 16
  samples_per_pixel 4
}
#end

#declare Light_Intensity = 1.5;
#declare Light_Radius = 0.08;
#declare Fade_D = 0.001;

camera {
  location <-0.3, 0.7, -1.8>
  look_at <0.6, 0.35, 0.6>
  up y
  right x*4/3
  angle 60
}

light_source {
  <0, 1.0, 0>, rgb Light_Intensity / (2*pi*Fade_D*Fade_D)
  area_light <2*Light_Radius, 0, 0>, <0, 0, 2*Light_Radius>, 5, 5 circular orient jitter
  fade_distance Fade_D fade_power 2
  photons { refraction on reflection on }
}

#declare Mirror = texture { pigment { rgb 0 } finish { ambient 0 diffuse 0 reflection { 0.9 } } }

box { <-0.6, -0.02, -2>, <0.6, 0, 2> pigment { rgb 0.75 } finish { ambient 0 diffuse 1 } }  // floor
box { <-0.62, -0.02, -2>, <-0.6, 1.2, 2> texture { Mirror } photons { target reflection on } }  // left
box { <0.6, -0.02, -2>, <0.62, 1.2, 2> texture { Mirror } photons { target reflection on } }    // right
sphere { <0.15, 0.2, 0.4>, 0.2 pigment { rgb <0.75, 0.25, 0.25> } finish { ambient 0 diffuse 1 } }
