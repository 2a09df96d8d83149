// SPDX-License-Identifier: MIT
// POV-Ray's polynomial surfaces: shapesq.inc's torus Torus_40_12 as a `quartic` (red), its Piriform
// (a Hershey's kiss: 4x^4 - 4x^3 + y^2 + z^2 = 0, green) with a `bounded_by` sphere, the rounded
// cube x^4 + y^4 + z^4 = 1 written with 3.7's `polynomial` (blue), and the monkey saddle
// y = x^3 - 3xz^2 as a `cubic` cut by a box in an `intersection` (yellow), on a white floor before a
// white wall, lit as prism_text.pov. Units: metres, watts; POV-Ray's pixel values are then radiance.
// A valid POV-Ray 3.7 file that photon reads unchanged:
//   photon render examples/scenes/polynomials.pov -o polynomials.png
//   povray -D +W640 +H480 +A0.3 +AM2 +R3 +HIexamples/scenes/povray/radphot_hq.inc +FE +Opolynomials.exr examples/scenes/polynomials.pov

#version 3.7;

global_settings {
  assumed_gamma 1.0       // colours are linear
  ambient_light rgb 0     // no fake fill light
  max_trace_level 4       // ray depth 4: primary ray + 3 bounces
}

// photon's own settings (docs/scene-language.md); POV-Ray skips this block.
#ifdef (photon_version)
global_settings {
  width 640 height 480
  render_mode pm
  global_photons 200000
  caustic_photons 100000
  global_estimate { count 100 radius 0.25 }
  caustic_estimate { count 60 radius 0.05 }
  max_photon_depth 10
  final_gather 256
  shadow_samples 16
  samples_per_pixel 4
}
#end

#declare Light_Intensity = 4;
#declare Light_Radius = 0.1;
#declare Fade_D = 0.001;

camera {
  location <0, 1.3, -3.4>
  look_at <0, 0.45, 0.2>
  up y
  right x*4/3
  angle 52
}

light_source {
  <0.8, 2.0, -1.2>, rgb Light_Intensity / (2*pi*Fade_D*Fade_D)
  area_light <2*Light_Radius, 0, 0>, <0, 0, 2*Light_Radius>, 9, 9 circular orient jitter
  fade_distance Fade_D fade_power 2
}

#declare Matte = finish { ambient 0 diffuse 1 }
#declare White  = texture { pigment { rgb 0.75 } finish { Matte } }
#declare Red    = texture { pigment { rgb <0.75, 0.25, 0.25> } finish { Matte } }
#declare Green  = texture { pigment { rgb <0.25, 0.7, 0.3> } finish { Matte } }
#declare Blue   = texture { pigment { rgb <0.25, 0.3, 0.75> } finish { Matte } }
#declare Yellow = texture { pigment { rgb <0.8, 0.7, 0.2> } finish { Matte } }

box { <-3, -0.02, -2>, <3, 0, 1.5>      texture { White } }  // floor
box { <-3, 0, 1.5>, <3, 2.5, 1.52>      texture { White } }  // back wall

// shapesq.inc's Torus_40_12 (major radius sqrt 40, minor sqrt 12, around y), 0.04 times as large.
quartic {
  < 1,   0,   0,    0,     2,   0,   0,   2,   0, -104,
    0,   0,   0,    0,     0,   0,   0,   0,   0,    0,
    1,   0,   0,    2,     0,  56,   0,   0,   0,    0,
    1,   0, -104,   0,   784>
  sturm
  scale 0.04 translate <-1.15, 0.04*sqrt(12), 0.45>
  texture { Red }
}

// shapesq.inc's Piriform, about the x axis from its tip at 0 to its round end at 1; stood on its
// round end. The bound is POV-Ray's: rays that miss it skip the surface.
quartic {
  < 4,   0,   0,   -4,  0,   0,   0,   0,   0,  0,
    0,   0,   0,    0,  0,   0,   0,   0,   0,  0,
    0,   0,   0,    0,  0,   1,   0,   0,   0,  0,
    0,   0,   1,    0,  0>
  bounded_by { sphere { <0.5, 0, 0>, 0.75 } }
  rotate -90*z translate y scale 0.5 translate <-0.4, 0, 0.8>
  texture { Green }
}

// 3.7's polynomial: only the terms that are not 0, by their powers of x, y and z.
polynomial {
  4, xyz(4, 0, 0): 1, xyz(0, 4, 0): 1, xyz(0, 0, 4): 1, xyz(0, 0, 0): -1
  scale 0.2 rotate 30*y translate <0.35, 0.2, 0.75>
  texture { Blue }
}

// The monkey saddle's underside, y <= x^3 - 3xz^2 (a cubic's 20 terms: x^3, x^2y, x^2z, x^2, xy^2,
// xyz, xy, xz^2, xz, x, y^3, y^2z, y^2, yz^2, yz, y, z^3, z^2, z, 1), cut by a box.
intersection {
  cubic {
    < -1,  0,  0,  0,  0,  0,  0,  3,  0,  0,
       0,  0,  0,  0,  0,  1,  0,  0,  0,  0>
  }
  box { -1, 1 }
  scale 0.22 rotate -20*y translate <1.1, 0.22, 0.35>
  texture { Yellow }
}
