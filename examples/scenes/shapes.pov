// SPDX-License-Identifier: MIT
// The round shapes: a closed cylinder (red), a pointed cone (green), a ring-shaped disc standing
// on its edge (blue), a torus lying on the floor (yellow) and an open tube squashed into an
// elliptic section (white, photon places it as a Transformed cone), on a white floor before a
// white wall, lit by a spherical light of radius 0.1 m and 4 W/sr.
// Units: metres, watts; POV-Ray's pixel values are then radiance (W m^-2 sr^-1), as photon's.
// A valid POV-Ray 3.7 file that photon reads unchanged:
//   photon render examples/scenes/shapes.pov -o shapes.png
//   povray -D +W640 +H480 +A0.3 +AM2 +R3 +HIexamples/scenes/povray/radphot_hq.inc +FE +Oshapes.exr examples/scenes/shapes.pov

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

// The light, as in cornell.pov: intensity I W/sr per channel; with fade_power 2 and a tiny
// fade_distance D the colour I / (2 pi D^2) makes POV-Ray's brightness the radiance of a light of
// intensity I. POV-Ray's picture of the sphere is a disc of 9 x 9 point lights facing every point.
#declare Light_Intensity = 4;
#declare Light_Radius = 0.1;
#declare Fade_D = 0.001;

camera {
  location <0, 1.3, -3.4>
  look_at <0, 0.4, 0.2>
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

cylinder { <-1.25, 0, 0.45>, <-1.25, 0.9, 0.45>, 0.3  texture { Red } }
cone { <-0.4, 0, 0.7>, 0.35, <-0.4, 1.05, 0.7>, 0     texture { Green } }
disc {  // a ring on its edge, turned a little towards the light
  <0, 0, 0>, <0, 0, -1>, 0.42, 0.16
  rotate -25*y
  translate <0.45, 0.42, 0.75>
  texture { Blue }
}
torus { 0.32, 0.11  translate <1.2, 0.11, 0.1>       texture { Yellow } }
cylinder {  // an open tube of elliptic section: a non-uniform scale
  0, 0.3*y, 0.2 open
  scale <1.7, 1, 1>
  translate <0.2, 0, -0.75>
  texture { White }
}
