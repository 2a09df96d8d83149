// SPDX-License-Identifier: MIT
// Absorption: four glass balls that absorb the light travelling inside them (POV-Ray's interior
// `fade_distance`, `fade_power` and `fade_color`), on a pale floor before a wall, under one
// round light. Light crossing a ball loses exp(-(1 - fade_color) d / fade_distance) per colour
// over the distance d it runs inside, so thick paths are deeper in colour than thin ones, and the
// caustics on the floor are tinted. Left to right: a red ball that absorbs strongly (fade_distance
// 0.15), a green one, a pale blue one that absorbs weakly (0.6), and an amber one with POV-Ray's
// older fade law (fade_power 2: 1 / (1 + (d / fade_distance)^2) of what fade_color does not keep).
// Units and light as in cornell.pov (metres, watts, radiance); a valid POV-Ray 3.7 file:
//   photon render examples/scenes/absorption.pov -o absorption.png
//   povray -D +W400 +H300 +A0.3 +AM2 +R3 +HIexamples/scenes/povray/radphot.inc +FE +Oabsorption.exr examples/scenes/absorption.pov

#version 3.7;

global_settings {
  assumed_gamma 1.0
  ambient_light rgb 0
  max_trace_level 10
}

#ifdef (photon_version)
global_settings {
  width 400 height 300
  render_mode pm
  global_photons 100000
  caustic_photons 400000
  global_estimate { count 100 radius 0.25 }
  caustic_estimate { count 80 radius 0.05 }
  max_photon_depth 10
  final_gather 192
  shadow_samples 16
  samples_per_pixel 4
}
#end

#declare Light_Intensity = 4;
#declare Light_Radius = 0.08;
#declare Fade_D = 0.001;

camera {
  location <0, 1.25, -2.3>
  look_at <0, 0.2, 0.15>
  up y
  right x*4/3
  angle 50
}

light_source {
  <-0.3, 1.9, 0.9>, rgb Light_Intensity / (2*pi*Fade_D*Fade_D)
  area_light <2*Light_Radius, 0, 0>, <0, 0, 2*Light_Radius>, 9, 9 circular orient jitter
  fade_distance Fade_D fade_power 2
  photons { refraction on reflection on }
}

#declare Matte = finish { ambient 0 diffuse 1 }
#declare Glass = texture {
  pigment { rgbf <1, 1, 1, 1> }
  finish { ambient 0 diffuse 0 reflection { 0, 1 fresnel on } conserve_energy }
}

// Floor and back wall: pale grey, so the caustics show their colour.
box { <-3, -0.02, -3>, <3, 0, 3> texture { pigment { rgb 0.75 } finish { Matte } } }
box { <-3, 0, 1.5>, <3, 3, 1.52> texture { pigment { rgb 0.7 } finish { Matte } } }

sphere {  // red, strongly absorbing
  <-0.9, 0.25, 0>, 0.25
  texture { Glass }
  interior { ior 1.5 fade_distance 0.15 fade_power 1001 fade_color rgb <0.9, 0.15, 0.1> }
  photons { target reflection on refraction on collect off }
}
sphere {  // green
  <-0.3, 0.25, -0.2>, 0.25
  texture { Glass }
  interior { ior 1.5 fade_distance 0.3 fade_power 1001 fade_color rgb <0.2, 0.85, 0.3> }
  photons { target reflection on refraction on collect off }
}
sphere {  // pale blue, weakly absorbing
  <0.3, 0.25, 0>, 0.25
  texture { Glass }
  interior { ior 1.5 fade_distance 0.6 fade_power 1001 fade_color rgb <0.3, 0.6, 1> }
  photons { target reflection on refraction on collect off }
}
sphere {  // amber, POV-Ray's older fade law
  <0.9, 0.25, -0.2>, 0.25
  texture { Glass }
  interior { ior 1.5 fade_distance 0.4 fade_power 2 fade_color rgb <0.95, 0.6, 0.1> }
  photons { target reflection on refraction on collect off }
}
