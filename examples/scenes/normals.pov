// SPDX-License-Identifier: MIT
// Normals: the Cornell box of cornell.pov with POV-Ray 3.7's bump patterns, which photon renders
// as a tilted shading normal used alike by shadow rays, photons and final gathering. Five white
// spheres with a phong highlight show bumps, dents, ripples, waves and wrinkles; the floor leans
// by the slope of a pigment pattern (marble), and the back wall is rippled by `waves`.
// Units and light as in cornell.pov (metres, watts, radiance); a valid POV-Ray 3.7 file:
//   photon render examples/scenes/normals.pov -o normals.png
//   povray -D +W800 +H600 +A0.3 +AM2 +R3 +HIexamples/scenes/povray/radphot_hq.inc +FE +Onormals.exr examples/scenes/normals.pov

#version 3.7;

global_settings {
  assumed_gamma 1.0
  ambient_light rgb 0
  max_trace_level 4
}

#ifdef (photon_version)
global_settings {
  width 800 height 600
  render_mode pm
  global_photons 200000
  global_estimate { count 100 radius 0.25 }
  max_photon_depth 10
  final_gather 256
  shadow_samples 16
  samples_per_pixel 4
}
#end

#declare Light_Intensity = 2.5;
#declare Light_Radius = 0.1;
#declare Fade_D = 0.001;

camera {
  location <0, 0.9, -3.5>
  look_at <0, 0.9, 0>
  up y
  right x*4/3
  angle 53.13
}

light_source {
  <0, 1.5, 0>, rgb Light_Intensity / (2*pi*Fade_D*Fade_D)
  area_light <2*Light_Radius, 0, 0>, <0, 0, 2*Light_Radius>, 9, 9 circular orient jitter
  fade_distance Fade_D fade_power 2
}

#declare Matte = finish { ambient 0 diffuse 1 }
#declare Shiny = finish { ambient 0 diffuse 0.9 phong 0.6 phong_size 60 }
#declare Ripply = normal { waves 0.6 frequency 4 scale 0.5 }

// Floor: grey, leaning by the slope of a marble pattern (POV-Ray takes the pattern's slope).
box { <-1.22, -0.02, -1.2>, <1.22, 0, 1.22>
  texture { pigment { rgb <0.7, 0.68, 0.62> } normal { marble 0.6 turbulence 0.5 scale 0.3 } finish { Matte } } }
// Ceiling: plain white.
box { <-1.22, 1.8, -1.2>, <1.22, 1.82, 1.22> texture { pigment { rgb 0.75 } finish { Matte } } }
// Back wall: white, rippled by POV-Ray's ten wave sources.
box { <-1.22, -0.02, 1.2>, <1.22, 1.82, 1.22>
  texture { pigment { rgb 0.75 } normal { Ripply } finish { Matte } } }
// Left wall: red; right wall: blue.
box { <-1.22, -0.02, -1.2>, <-1.2, 1.82, 1.22> texture { pigment { rgb <0.75, 0.25, 0.25> } finish { Matte } } }
box { <1.2, -0.02, -1.2>, <1.22, 1.82, 1.22> texture { pigment { rgb <0.25, 0.25, 0.75> } finish { Matte } } }

#declare Ball = sphere { <0, 0, 0>, 0.2 }
object { Ball texture { pigment { rgb 0.75 } normal { bumps 0.8 scale 0.05 } finish { Shiny } } translate <-0.88, 0.2, 0.2> }
object { Ball texture { pigment { rgb 0.75 } normal { dents 2 scale 0.08 } finish { Shiny } } translate <-0.44, 0.2, 0.2> }
object { Ball texture { pigment { rgb 0.75 } normal { ripples 0.8 frequency 6 scale 0.2 } finish { Shiny } } translate <0, 0.2, 0.2> }
object { Ball texture { pigment { rgb 0.75 } normal { waves 0.8 frequency 3 scale 0.2 } finish { Shiny } } translate <0.44, 0.2, 0.2> }
object { Ball texture { pigment { rgb 0.75 } normal { wrinkles 0.8 scale 0.15 } finish { Shiny } } translate <0.88, 0.2, 0.2> }
// A plain ball for comparison, up on the left.
sphere { <-0.5, 0.9, 0.7>, 0.2 texture { pigment { rgb 0.75 } finish { Shiny } } }
// And one with a checker's slope: flat squares, tilted only at their edges.
sphere { <0.5, 0.9, 0.7>, 0.2 texture { pigment { rgb 0.75 } normal { checker 1 scale 0.1 } finish { Shiny } } }
