// SPDX-License-Identifier: MIT
// Lights as POV-Ray 3.7 computes them: a fill light without a fade (POV-Ray's default: it does not
// fall off with distance), two soft spotlights (POV-Ray's radius / falloff / tightness profile)
// with fades 2 / (1 + (d / D)^P) of power 1 and 2, and a `shadowless` red light from the right
// whose light passes through the objects. White spheres and a box on a white floor before a
// white wall; the spots' soft rims, the fill light's even brightness across the floor and the
// missing red shadows are the things to look at.
// Colours are POV-Ray's brightness (docs/scene-language.md, light units); a valid POV-Ray 3.7 file:
//   photon render examples/scenes/lights.pov -o lights.png
//   povray -D +W640 +H480 +A0.3 +AM2 +R3 +HIexamples/scenes/povray/radphot.inc +FE +Olights.exr examples/scenes/lights.pov

#version 3.7;

global_settings {
  assumed_gamma 1.0
  ambient_light rgb 0
  max_trace_level 4
}

#ifdef (photon_version)
global_settings {
  width 640 height 480
  render_mode pm
  global_photons 300000
  global_estimate { count 100 radius 0.25 }
  max_photon_depth 10
  final_gather 256
  samples_per_pixel 4
}
#end

camera {
  location <0, 1.6, -4.2>
  look_at <0, 0.6, 0>
  up y
  right x*4/3
  angle 55
}

#declare Matte = finish { ambient 0 diffuse 1 }
#declare White = texture { pigment { rgb 0.75 } finish { Matte } }

// Fill light, no fade: the same brightness on the floor under it and on the wall 6 m away.
light_source { <-1, 5, -5>, rgb 0.12 }

// Warm soft spotlight: full inside 8 degrees, a smooth rim out to 20, cos^8 across the beam;
// fades as 2 / (1 + d / 2).
light_source {
  <-1.6, 3.2, -1.8>, rgb <1.6, 1.3, 0.9>
  spotlight radius 8 falloff 20 tightness 8
  point_at <-0.9, 0, 0.4>
  fade_distance 2 fade_power 1
}

// Cool spotlight with POV-Ray's default tightness 0: flat inside 10 degrees, rim to 22; fades as
// 2 / (1 + (d / 3)^2).
light_source {
  <2.0, 3.4, -1.2>, rgb <0.55, 0.75, 1.3>
  spotlight radius 10 falloff 22
  point_at <1.0, 0, 0.5>
  fade_distance 3 fade_power 2
}

// Shadowless red light from the right, low: no shadows behind the objects.
light_source { <3.5, 0.6, -0.8>, rgb <0.2, 0.02, 0.02> shadowless }

// Floor and back wall.
box { <-4, -0.02, -3>, <4, 0, 2.02> texture { White } }
box { <-4, -0.02, 2>, <4, 3, 2.02> texture { White } }

sphere { <-0.9, 0.45, 0.4>, 0.45 texture { White } }
sphere { <0.1, 0.3, -0.6>, 0.3 texture { White } }
box { <0.7, 0, 0.2>, <1.4, 0.8, 0.9> rotate <0, 20, 0> texture { White } }
