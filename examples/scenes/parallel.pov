// SPDX-License-Identifier: MIT
// A parallel light (POV-Ray's `parallel`, photon's ParallelLight): sunlight slanting in from the
// upper left, every ray along one direction, so the shadows of the spheres and the box are the
// same shape wherever they fall and the floor is equally bright near and far. A small lamp on the
// right, a point light with `looks_like`, shows its glowing bulb to the camera, casts no shadow
// and dims none of its own light. White spheres and a box on a white floor before a white wall.
// Colours are POV-Ray's brightness (docs/scene-language.md, light units); a valid POV-Ray 3.7 file:
//   photon render examples/scenes/parallel.pov -o parallel.png
//   povray -D +W640 +H480 +A0.3 +FN +Oparallel-povray.png examples/scenes/parallel.pov

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

// The sun: parallel rays from the upper left towards the origin; its plane (through the
// location, perpendicular to them) lies beyond the whole scene.
light_source { <-8, 10, -7>, rgb <1.0, 0.92, 0.8> parallel point_at <0, 0, 0> }

// A lamp on the right: its bulb is seen, lit by nothing but its own emission.
light_source {
  <1.3, 1.35, -0.5>, rgb <0.5, 0.45, 0.35>
  fade_distance 1 fade_power 2
  looks_like { sphere { 0, 0.07 pigment { rgb <1, 0.9, 0.7> } finish { ambient 0 diffuse 0 emission 1 } } }
}

// Floor and back wall.
box { <-4, -0.02, -3>, <4, 0, 2.02> texture { White } }
box { <-4, -0.02, 2>, <4, 3, 2.02> texture { White } }

sphere { <-0.9, 0.45, 0.4>, 0.45 texture { White } }
sphere { <0.1, 0.3, -0.6>, 0.3 texture { White } }
box { <0.7, 0, 0.2>, <1.4, 0.8, 0.9> rotate <0, 20, 0> texture { White } }
