// SPDX-License-Identifier: MIT
// POV-Ray's rectangular area lights (docs/scene-language.md, light_source): a warm jittered
// light 2 m wide and 0.3 m deep, whose shadows are soft along x and nearly sharp along z, and a
// cool 4 x 1 grid without `jitter`, whose every emitter casts its own hard shadow (four copies
// side by side). A post, a ball and a slab on two legs on a white floor before a white wall;
// the penumbra widths (wider the further the shadow falls from its object) and the cool light's
// four separate shadows are the things to look at.
// Colours are POV-Ray's brightness (docs/scene-language.md, light units); a valid POV-Ray 3.7 file:
//   photon render examples/scenes/area_lights.pov -o area_lights.png
//   povray -D +W640 +H480 +A0.3 +AM2 +R3 +HIexamples/scenes/povray/radphot.inc +FE +Oarea_lights.exr examples/scenes/area_lights.pov

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
  location <0, 2.2, -4.4>
  look_at <0, 0.5, 0.3>
  up y
  right x*4/3
  angle 52
}

#declare Matte = finish { ambient 0 diffuse 1 }
#declare White = texture { pigment { rgb 0.75 } finish { Matte } }

// Warm light 2 m wide (x) and 0.3 m deep (z), 3 m up, slightly to the left; 8 x 2 jittered cells
// (POV-Ray's adaptive subdivision is a sampling detail: photon traces every cell).
// `area_illumination`: POV-Ray lights by each emitter's own cosine and distance, as photon does.
light_source {
  <-0.6, 3.0, -0.6>, rgb <0.38, 0.32, 0.24>
  area_light <2, 0, 0>, <0, 0, 0.3>, 8, 2
  jitter adaptive 1 area_illumination
}

// Cool grid of 4 point lights 0.6 m apart along x, no jitter: four hard shadows per object.
light_source {
  <1.4, 2.4, -1.6>, rgb <0.1, 0.16, 0.3>
  area_light <1.8, 0, 0>, <0, 0, 0>, 4, 1
  area_illumination
}

// Floor and back wall.
box { <-4, -0.02, -3>, <4, 0, 2.02> texture { White } }
box { <-4, -0.02, 2>, <4, 3, 2.02> texture { White } }

// A thin post, a ball, and a slab on two legs (its shadow falls from 0.7 m up).
box { <-1.75, 0, 0.45>, <-1.6, 1.4, 0.6> texture { White } }
sphere { <-0.4, 0.35, 0.1>, 0.35 texture { White } }
union {
  box { <0.4, 0.68, -0.2>, <1.6, 0.72, 0.6> }
  box { <0.45, 0, 0.5>, <0.55, 0.68, 0.55> }
  box { <1.45, 0, 0.5>, <1.55, 0.68, 0.55> }
  texture { White }
}
