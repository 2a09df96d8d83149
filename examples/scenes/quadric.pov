// SPDX-License-Identifier: MIT
// POV-Ray's quadric and polygon: an ellipsoid tilted on the floor (red), shapes.inc's infinite
// Cylinder_Y cut to a post by a box (green), a hyperboloid of one sheet cut by a slab into a
// waisted tower (blue), a paraboloid cut by a plane into a dome (yellow), and a five-pointed star
// drawn as one polygon loop, whose inner pentagon the even-odd rule leaves open (orange), on a
// white floor before a white wall, lit by a spherical light of radius 0.1 m and 4 W/sr (the
// light of shapes.pov). Units: metres, watts; POV-Ray's pixel values are then radiance.
// A valid POV-Ray 3.7 file that photon reads unchanged:
//   photon render examples/scenes/quadric.pov -o quadric.png
//   povray -D +W640 +H480 +A0.3 +AM2 +R3 +HIexamples/scenes/povray/radphot_hq.inc +FE +Oquadric.exr examples/scenes/quadric.pov

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
#declare Orange = texture { pigment { rgb <0.85, 0.45, 0.15> } finish { Matte } }

box { <-3, -0.02, -2>, <3, 0, 1.5>      texture { White } }  // floor
box { <-3, 0, 1.5>, <3, 2.5, 1.52>      texture { White } }  // back wall

// x^2 + y^2 + z^2 - 1 = 0 squashed to semi-axes 0.35, 0.22, 0.25 and tilted: it stands on the
// floor at height 0.26 (the tilted extent sqrt((0.35 sin 30)^2 + (0.22 cos 30)^2) = 0.259).
quadric {
  <1, 1, 1>, <0, 0, 0>, <0, 0, 0>, -1
  scale <0.35, 0.22, 0.25>
  rotate 30*z
  translate <-1.2, 0.26, 0.3>
  texture { Red }
}

// Cylinder_Y of shapes.inc (x^2 + z^2 - 1 = 0, infinite along y) cut to a post.
intersection {
  quadric { <1, 0, 1>, <0, 0, 0>, <0, 0, 0>, -1 }
  box { <-2, 0, -2>, <2, 4, 2> }
  scale <0.18, 0.25, 0.18>
  translate <-0.45, 0, 0.8>
  texture { Green }
}

// x^2 + z^2 - y^2 - 0.16 <= 0: the inside of a hyperboloid of one sheet (waist radius 0.4),
// from y = -0.7 to 0.7, scaled to a tower 0.7 high.
intersection {
  quadric { <1, -1, 1>, <0, 0, 0>, <0, 0, 0>, -0.16 }
  box { <-2, -0.7, -2>, <2, 0.7, 2> }
  scale 0.5
  translate <0.35, 0.35, 0.55>
  texture { Blue }
}

// x^2 + z^2 - y <= 0 (Paraboloid_Y) up to y = 1, turned over onto its flat face: a dome.
intersection {
  quadric { <1, 0, 1>, <0, 0, 0>, <0, -1, 0>, 0 }
  plane { y, 1 }
  rotate 180*x
  translate y
  scale <0.3, 0.4, 0.3>
  translate <1.2, 0, 0.0>
  texture { Yellow }
}

// A five-pointed star in one loop: its edges cross, and the even-odd rule leaves the inner
// pentagon open (the wall shows through). 2D points, in the xy plane; stood up before the wall.
polygon {
  6, <0.0000, 0.4500>, <-0.2645, -0.3641>, <0.4280, 0.1391>, <-0.4280, 0.1391>, <0.2645, -0.3641>, <0.0000, 0.4500>
  rotate -10*y
  translate <1.0, 1.05, 1.2>
  texture { Orange }
}
