// SPDX-License-Identifier: MIT
// The paper's recursive box: the Cornell box (cornell.pov: same camera, light and walls) with two
// mirror panels facing each other on the red and blue walls, the mirror and glass spheres, and a
// mirror cube standing between the spheres at the back: reflections of reflections, cut at ray
// depth 4.
// Units: metres, watts; POV-Ray's pixel values are then radiance (W m^-2 sr^-1), as photon's.
// A valid POV-Ray 3.7 file that photon reads unchanged:
//   photon render examples/scenes/recursive.pov -o recursive.png
//   povray -D +W800 +H600 +A0.3 +AM2 +R3 +HIexamples/scenes/povray/radphot_hq.inc +FE +Orecursive.exr examples/scenes/recursive.pov

#version 3.7;

global_settings {
  assumed_gamma 1.0       // colours are linear
  ambient_light rgb 0     // no fake fill light
  max_trace_level 4       // ray depth 4: primary ray + 3 bounces
}

// photon's own settings (docs/scene-language.md); POV-Ray skips this block.
#ifdef (photon_version)
global_settings {
  width 800 height 600
  render_mode pm
  global_photons 200000
  caustic_photons 200000
  global_estimate { count 100 radius 0.25 }
  caustic_estimate { count 60 radius 0.05 }
  max_photon_depth 10
  final_gather 512
  shadow_samples 16
  samples_per_pixel 4
}
#end

// The light: a sphere of radius Light_Radius emitting Light_Intensity W/sr per channel (power
// 4 pi I = 31.4 W). With fade_power 2 and a tiny fade_distance D, POV-Ray's light falls off as
// 2 D^2 / d^2, so the colour I / (2 pi D^2) makes POV-Ray's brightness the radiance of a light of
// intensity I. The area light is POV-Ray's picture of the sphere: a disc of 9 x 9 point lights of
// diameter 2 R that faces every shaded point.
#declare Light_Intensity = 2.5;
#declare Light_Radius = 0.1;
#declare Fade_D = 0.001;

camera {
  location <0, 0.9, -3.5>
  look_at <0, 0.9, 0>
  up y
  right x*4/3
  angle 53.13             // horizontal field of view: tan(53.13 / 2) = 0.5
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
#declare Mirror = texture { pigment { rgb 0 } finish { ambient 0 diffuse 0 reflection { 1 } } }
#declare Glass = texture {
  pigment { rgbf <1, 1, 1, 1> }
  finish { ambient 0 diffuse 0 reflection { 0, 1 fresnel on } conserve_energy }
}
#declare Glass_Interior = interior { ior 1.5 }

// The walls: 0.02 m slabs whose outer extents overlap at the corners; no front wall.
box { <-1.22, -0.02, -1.2>, <1.22, 0, 1.22>     texture { White } }  // floor
box { <-1.22, 1.8, -1.2>, <1.22, 1.82, 1.22>    texture { White } }  // ceiling
box { <-1.22, -0.02, 1.2>, <1.22, 1.82, 1.22>   texture { White } }  // back
box { <-1.22, -0.02, -1.2>, <-1.2, 1.82, 1.22>  texture { Red } }    // left
box { <1.2, -0.02, -1.2>, <1.22, 1.82, 1.22>    texture { Blue } }   // right

// Mirror panels, 0.02 m thick, facing each other.
box {  // on the red wall
  <-1.2, 0.3, -0.4>, <-1.18, 1.4, 0.9>
  texture { Mirror }
  photons { target reflection on refraction on collect off }
}
box {  // on the blue wall
  <1.18, 0.3, -0.4>, <1.2, 1.4, 0.9>
  texture { Mirror }
  photons { target reflection on refraction on collect off }
}

sphere {  // mirror, back left
  <-0.55, 0.4, 0.45>, 0.4
  texture { Mirror }
  photons { target reflection on refraction on collect off }
}
sphere {  // glass, front right
  <0.55, 0.4, -0.3>, 0.4
  texture { Glass }
  interior { Glass_Interior }
  photons { target reflection on refraction on collect off }
}
box {  // mirror cube on the floor between the spheres, at the back
  <-0.25, 0, -0.25>, <0.25, 0.5, 0.25>
  texture { Mirror }
  photons { target reflection on refraction on collect off }
  rotate <0, 30, 0>
  translate <0.25, 0, 0.85>
}
