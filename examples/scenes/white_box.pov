// SPDX-License-Identifier: MIT
// The white box: an open-fronted box of 0.02 m wall slabs, interior [-1.3,1.3] x [0,2.6] x
// [-1.3,1.3] (white floor, ceiling and back wall, red wall left, green wall right), lit by a point
// light of 3 W/sr 0.25 m below the ceiling. No mirror or glass: every light path is diffuse, the
// scene on which the irradiance caches of both renderers (photon's final gather, POV-Ray's
// radiosity) are compared most directly (scripts/povray-accuracy-study.sh). Units: metres, watts,
// as cornell.pov. A valid POV-Ray 3.7 file that photon reads unchanged:
//   photon render examples/scenes/white_box.pov -o white_box.png
//   povray -D +W512 +H512 +A0.3 +AM2 +R3 +HIexamples/scenes/povray/rad.inc +FE +Owhite_box.exr examples/scenes/white_box.pov

#version 3.7;

global_settings {
  assumed_gamma 1.0       // colours are linear
  ambient_light rgb 0     // no fake fill light
  max_trace_level 4
}

// photon's own settings (docs/scene-language.md); POV-Ray skips this block. No caustics here.
#ifdef (photon_version)
global_settings {
  width 512 height 512
  render_mode pm
  global_photons 200000
  caustic_photons 0
  global_estimate { count 100 radius 0.25 }
  max_photon_depth 10
  final_gather 256
  samples_per_pixel 4
}
#end

// A point light of intensity Light_Intensity W/sr per channel; the fade makes POV-Ray's light
// the physical inverse-square one (docs/scene-language.md, light units).
#declare Light_Intensity = 3;
#declare Fade_D = 0.001;

camera {
  location <0, 1.3, -4.2>
  look_at <0, 1.3, 0>
  up y
  right x
  angle 50                // square image; the opening (2.64 m wide at 2.9 m) just fills it
}

light_source {
  <0, 2.35, 0>, rgb Light_Intensity / (2*pi*Fade_D*Fade_D)
  fade_distance Fade_D fade_power 2
}

#declare White = texture { pigment { rgb <0.75, 0.75, 0.75> } finish { ambient 0 diffuse 1 } }
#declare Red   = texture { pigment { rgb <0.75, 0.25, 0.25> } finish { ambient 0 diffuse 1 } }
#declare Green = texture { pigment { rgb <0.25, 0.75, 0.25> } finish { ambient 0 diffuse 1 } }

// The walls: 0.02 m slabs whose outer extents overlap at the corners; no front wall.
box { <-1.32, -0.02, -1.3>, <1.32, 0, 1.32>     texture { White } }  // floor
box { <-1.32, 2.6, -1.3>, <1.32, 2.62, 1.32>    texture { White } }  // ceiling
box { <-1.32, -0.02, 1.3>, <1.32, 2.62, 1.32>   texture { White } }  // back
box { <-1.32, -0.02, -1.3>, <-1.3, 2.62, 1.32>  texture { Red } }    // left
box { <1.3, -0.02, -1.3>, <1.32, 2.62, 1.32>    texture { Green } }  // right
