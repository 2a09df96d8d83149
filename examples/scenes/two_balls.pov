// SPDX-License-Identifier: MIT
// The box with two balls: the white box (white_box.pov: an open-fronted box, interior
// [-1.3,1.3] x [0,2.6] x [-1.3,1.3], white floor, ceiling and back wall, red wall left, green wall
// right, a point light of 3 W/sr 0.25 m below the ceiling) with a mirror ball at the back left and
// a glass ball of ior 1.6 at the front right, whose caustic lands on the floor beside it. A point
// light's caustic is seen only by photon tracing (POV-Ray's photons, photon's caustic map and
// sppm); photon's path tracer renders it black. Units: metres, watts, as cornell.pov. A valid
// POV-Ray 3.7 file that photon reads unchanged:
//   photon render examples/scenes/two_balls.pov -o two_balls.png
//   povray -D +W512 +H512 +A0.3 +AM2 +R3 +HIexamples/scenes/povray/radphot.inc +FE +Otwo_balls.exr examples/scenes/two_balls.pov

#version 3.7;

global_settings {
  assumed_gamma 1.0       // colours are linear
  ambient_light rgb 0     // no fake fill light
  max_trace_level 4
}

// photon's own settings (docs/scene-language.md); POV-Ray skips this block.
#ifdef (photon_version)
global_settings {
  width 512 height 512
  render_mode pm
  global_photons 200000
  caustic_photons 200000
  global_estimate { count 100 radius 0.25 }
  caustic_estimate { count 60 radius 0.05 }
  max_photon_depth 10
  final_gather 256
  samples_per_pixel 4
}
#end

#declare Light_Intensity = 3;
#declare Fade_D = 0.001;

camera {
  location <0, 1.3, -4.2>
  look_at <0, 1.3, 0>
  up y
  right x
  angle 50
}

light_source {
  <0, 2.35, 0>, rgb Light_Intensity / (2*pi*Fade_D*Fade_D)
  fade_distance Fade_D fade_power 2
  photons { refraction on reflection on }
}

#declare White = texture { pigment { rgb <0.75, 0.75, 0.75> } finish { ambient 0 diffuse 1 } }
#declare Red   = texture { pigment { rgb <0.75, 0.25, 0.25> } finish { ambient 0 diffuse 1 } }
#declare Green = texture { pigment { rgb <0.25, 0.75, 0.25> } finish { ambient 0 diffuse 1 } }
#declare Mirror = texture { pigment { rgb 0 } finish { ambient 0 diffuse 0 reflection { 1 } } }
#declare Glass = texture {
  pigment { rgbf <1, 1, 1, 1> }
  finish { ambient 0 diffuse 0 reflection { 0, 1 fresnel on } conserve_energy }
}

box { <-1.32, -0.02, -1.3>, <1.32, 0, 1.32>     texture { White } }  // floor
box { <-1.32, 2.6, -1.3>, <1.32, 2.62, 1.32>    texture { White } }  // ceiling
box { <-1.32, -0.02, 1.3>, <1.32, 2.62, 1.32>   texture { White } }  // back
box { <-1.32, -0.02, -1.3>, <-1.3, 2.62, 1.32>  texture { Red } }    // left
box { <1.3, -0.02, -1.3>, <1.32, 2.62, 1.32>    texture { Green } }  // right

sphere {  // mirror, back left
  <-0.6, 0.5, 0.5>, 0.5
  texture { Mirror }
  photons { target reflection on refraction on collect off }
}
sphere {  // glass, front right
  <0.6, 0.5, -0.35>, 0.5
  texture { Glass }
  interior { ior 1.6 }
  photons { target reflection on refraction on collect off }
}
