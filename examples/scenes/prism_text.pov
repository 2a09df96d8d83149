// SPDX-License-Identifier: MIT
// POV-Ray's prism and text: a square frame with a square hole (linear_spline, red), a rounded
// diamond through four points (quadratic_spline, green), the same four points as a Catmull-Rom
// loop (cubic_spline, blue), a leaf of two Bezier curves swept to a point (bezier_spline
// conic_sweep, yellow), the word "photon" in POV-Ray's timrom.ttf standing on the floor (orange)
// and "3.7" engraved into a slab by a CSG difference (white), on a white floor before a white
// wall, lit by a spherical light of radius 0.1 m and 4 W/sr (the light of shapes.pov). Units:
// metres, watts; POV-Ray's pixel values are then radiance.
// A valid POV-Ray 3.7 file that photon reads unchanged (the font is on POV-Ray's include path,
// /usr/share/povray-3.7/include):
//   photon render examples/scenes/prism_text.pov -o prism_text.png
//   povray -D +W640 +H480 +A0.3 +AM2 +R3 +HIexamples/scenes/povray/radphot_hq.inc +FE +Oprism_text.exr examples/scenes/prism_text.pov

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

// Two sub-polygons, each closed by repeating its first point: the inner one is a hole.
prism {
  linear_sweep linear_spline 0, 0.3, 10,
  <-1, -1>, <1, -1>, <1, 1>, <-1, 1>, <-1, -1>,
  <-0.5, -0.5>, <0.5, -0.5>, <0.5, 0.5>, <-0.5, 0.5>, <-0.5, -0.5>
  scale 0.32 rotate 20*y translate <-1.2, 0, 0.3>
  texture { Red }
}

// Quadratic spline: each curve runs between two points, shaped by the point before them; the
// first point is only a control point, the last repeats the second to close the loop.
prism {
  quadratic_spline 0, 0.45, 6,
  <0, -1>, <1, 0>, <0, 1>, <-1, 0>, <0, -1>, <1, 0>
  scale 0.32 translate <-0.45, 0, 0.7>
  texture { Green }
}

// Cubic spline: Catmull-Rom through the points, with one control point before and one after.
prism {
  cubic_spline 0, 0.6, 7,
  <0, -1>, <1, 0>, <0, 1>, <-1, 0>, <0, -1>, <1, 0>, <0, 1>
  scale 0.3 translate <0.3, 0, 0.75>
  texture { Blue }
}

// Bezier spline, four points per curve, conic sweep: the outline at height 1 shrinks to the
// origin at height 0; turned over, it stands on its wide end.
prism {
  bezier_spline conic_sweep 0.2, 1, 8,
  <1, 0>, <1, 0.6>, <0.4, 1>, <0, 1>,
  <0, 1>, <-1, 1>, <-1, -1>, <1, 0>
  rotate 180*x translate y scale <0.4, 0.7, 0.4> translate <1.15, 0, 0.45>
  texture { Yellow }
}

// Text: glyphs 1 unit (one em) high on the baseline, from z = 0 to the thickness.
text {
  ttf "timrom.ttf" "photon" 0.15, 0
  scale 0.4 translate <-1.25, 0.0, -0.45>
  texture { Orange }
}

// Engraving: the text, reaching in front of the slab, cut 0.03 deep into its face.
difference {
  box { <-0.05, -0.05, 0>, <1.3, 0.8, 0.1> }
  text { ttf "timrom.ttf" "3.7" 0.2, 0 translate <0.08, 0.12, -0.17> }
  scale 0.5 rotate -15*y translate <0.35, 0.0, -0.5>
  texture { White }
}
