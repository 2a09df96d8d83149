// SPDX-License-Identifier: MIT
// Fractal, spiral and quilted patterns: the Cornell box of cornell.pov with a Mandelbrot back
// wall (`mandel`, its outside coloured by escape time), a `spiral2` floor, a `quilted` left wall
// and a `spiral1` right wall, a ball with `quilted` bumps and one with `mandel`'s inside
// coloured by its orbit (`interior 1`), beside a glass sphere whose caustic lands on the floor.
// Photons take the colour where they land, so the patterns bleed onto the walls and spheres.
// Units and light as in cornell.pov (metres, watts, radiance); a valid POV-Ray 3.7 file:
//   photon render examples/scenes/patterns.pov -o patterns.png
//   povray -D +W800 +H600 +A0.3 +AM2 +R3 +HIexamples/scenes/povray/radphot_hq.inc +FE +Opatterns.exr examples/scenes/patterns.pov

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
  caustic_photons 200000
  global_estimate { count 100 radius 0.25 }
  caustic_estimate { count 60 radius 0.05 }
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
  photons { refraction on reflection on }
}

#declare Matte = finish { ambient 0 diffuse 1 }

// Floor: two crossing spirals of five arms, about the vertical axis.
box { <-1.22, -0.02, -1.2>, <1.22, 0, 1.22>
  texture {
    pigment { spiral2 5 color_map { [0 rgb <0.8, 0.75, 0.6>] [1 rgb <0.45, 0.08, 0.06>] } rotate <90, 0, 0> scale 0.4 }
    finish { Matte }
  } }
// Ceiling: plain white.
box { <-1.22, 1.8, -1.2>, <1.22, 1.82, 1.22> texture { pigment { rgb 0.75 } finish { Matte } } }
// Back wall: the Mandelbrot set, 1.6 m across, dark inside, banded outside by escape time.
box { <-1.22, -0.02, 1.2>, <1.22, 1.82, 1.22>
  texture {
    pigment {
      mandel 60
      color_map { [0 rgb <0.78, 0.78, 0.74>] [0.1 rgb <0.62, 0.64, 0.66>] [0.3 rgb <0.3, 0.35, 0.55>] [1 rgb <0.1, 0.1, 0.15>] }
      translate <0.6, 0, 0> scale 0.62 translate <0, 0.95, 0>
    }
    finish { Matte }
  } }
// Left wall: quilted squares, seen face on.
box { <-1.22, -0.02, -1.2>, <-1.2, 1.82, 1.22>
  texture {
    pigment { quilted control0 0.4 control1 0.9 color_map { [0 rgb <0.75, 0.25, 0.22>] [0.25 rgb <0.8, 0.65, 0.5>] } scale 0.3 }
    finish { Matte }
  } }
// Right wall: a single spiral of three arms.
box { <1.2, -0.02, -1.2>, <1.22, 1.82, 1.22>
  texture {
    pigment { spiral1 3 color_map { [0 rgb <0.2, 0.3, 0.7>] [1 rgb <0.7, 0.75, 0.8>] } rotate <0, 90, 0> scale 0.3 translate <0, 0.9, 0> }
    finish { Matte }
  } }

sphere {  // quilted bumps on white, back left
  <-0.6, 0.35, 0.55>, 0.35
  texture { pigment { rgb 0.7 } normal { quilted 0.6 scale 0.12 } finish { Matte } }
}
sphere {  // the set's inside coloured by its orbit's nearest approach (interior 1), front left
  <-0.55, 0.25, -0.55>, 0.25
  texture {
    pigment {
      mandel 40 interior 1, 1.5
      color_map { [0 rgb <0.1, 0.25, 0.6>] [0.5 rgb <0.2, 0.6, 0.3>] [1 rgb <0.75, 0.7, 0.2>] }
      scale 0.2 translate <-0.45, 0.25, -0.8>
    }
    finish { Matte }
  }
}
sphere {  // glass, front right; its caustic falls on the spiral floor
  <0.45, 0.35, -0.45>, 0.35
  texture { pigment { rgbf <1, 1, 1, 1> } finish { ambient 0 diffuse 0 reflection { 0, 1 fresnel on } conserve_energy } }
  interior { ior 1.5 }
  photons { target reflection on refraction on collect off }
}
