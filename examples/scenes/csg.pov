// SPDX-License-Identifier: MIT
// Constructive solid geometry in the Cornell box of cornell.pov: a glass lens made as the
// intersection of two spheres (its caustic on the floor), a white cube with a sphere cut out of
// a corner whose cut takes the red of the sphere that cut it (a CSG child's own texture), a
// glass merge of two spheres (no inner surface), and a blue dome, a sphere intersected with the
// half-space below a plane and an inverse sphere hollowing it.
// Units: metres, watts; POV-Ray's pixel values are then radiance (W m^-2 sr^-1), as photon's.
// A valid POV-Ray 3.7 file that photon reads unchanged:
//   photon render examples/scenes/csg.pov -o csg.png
//   povray -D +W800 +H600 +A0.3 +AM2 +R3 +HIexamples/scenes/povray/radphot_hq.inc +FE +Ocsg.exr examples/scenes/csg.pov

#version 3.7;

global_settings {
  assumed_gamma 1.0       // colours are linear
  ambient_light rgb 0     // no fake fill light
  max_trace_level 6       // the merge and the lens: in, out, and a reflection
}

// photon's own settings (docs/scene-language.md); POV-Ray skips this block.
#ifdef (photon_version)
global_settings {
  width 800 height 600
  render_mode pm
  global_photons 200000
  caustic_photons 400000
  global_estimate { count 100 radius 0.25 }
  caustic_estimate { count 60 radius 0.05 }
  max_photon_depth 10
  final_gather 256
  shadow_samples 16
  samples_per_pixel 4
}
#end

// The light as in cornell.pov: a sphere of radius Light_Radius emitting Light_Intensity W/sr per
// channel, which POV-Ray sees as a faded area light.
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

#declare White = texture { pigment { rgb <0.75, 0.75, 0.75> } finish { ambient 0 diffuse 1 } }
#declare Red   = texture { pigment { rgb <0.75, 0.25, 0.25> } finish { ambient 0 diffuse 1 } }
#declare Blue  = texture { pigment { rgb <0.25, 0.25, 0.75> } finish { ambient 0 diffuse 1 } }
#declare Glass = texture {
  pigment { rgbf <1, 1, 1, 1> }
  finish { ambient 0 diffuse 0 reflection { 0, 1 fresnel on } conserve_energy }
}
#declare Glass_Interior = interior { ior 1.5 }

box { <-1.22, -0.02, -1.2>, <1.22, 0, 1.22>     texture { White } }  // floor
box { <-1.22, 1.8, -1.2>, <1.22, 1.82, 1.22>    texture { White } }  // ceiling
box { <-1.22, -0.02, 1.2>, <1.22, 1.82, 1.22>   texture { White } }  // back
box { <-1.22, -0.02, -1.2>, <-1.2, 1.82, 1.22>  texture { Red } }    // left
box { <1.2, -0.02, -1.2>, <1.22, 1.82, 1.22>    texture { Blue } }   // right

// A biconvex lens, axis vertical, 0.2 m thick and 0.49 m across, 0.55 m above the floor.
intersection {
  sphere { <0, -0.25, 0>, 0.35 }
  sphere { <0, 0.25, 0>, 0.35 }
  translate <0.55, 0.55, -0.35>
  texture { Glass }
  interior { Glass_Interior }
  photons { target reflection on refraction on collect off }
}

// A white cube with a corner cut by a red sphere: the cut surface is the sphere's, red.
difference {
  box { <-0.25, 0, -0.25>, <0.25, 0.5, 0.25> texture { White } }
  sphere { <0.25, 0.5, -0.25>, 0.3 texture { Red } }
  rotate <0, 25, 0>
  translate <-0.6, 0, 0.45>
}

// Two glass spheres merged: one surface, no inner wall between them.
merge {
  sphere { <-0.12, 0, 0>, 0.18 }
  sphere { <0.12, 0, 0>, 0.18 }
  translate <-0.45, 0.18, -0.55>
  texture { Glass }
  interior { Glass_Interior }
  photons { target reflection on refraction on collect off }
}

// A blue dome: a ball below the plane y = 0.15, hollowed by an inverse ball (kept where it is not).
intersection {
  sphere { <0, 0, 0>, 0.3 }
  plane { y, 0.15 }
  sphere { <0, 0.15, 0>, 0.18 inverse }
  translate <0.45, 0.3, 0.55>
  texture { Blue }
}
