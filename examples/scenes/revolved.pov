// SPDX-License-Identifier: MIT
// POV-Ray's superellipsoid, lathe and sor: three superellipsoids from a rounded cube to a star
// (red, <0.2, 0.2>; green, <1, 1>, a sphere; blue, <2.5, 2.5>, pinched along its axes), a vase
// turned from a Bezier profile (lathe, yellow), a goblet of a cubic-spline lathe (white), a bowl of
// a sor left open at the top (orange), and a cup cut into a block by a CSG difference whose lathe
// gives the cup its shape (white), on a white floor before a white wall, lit by a spherical light
// of radius 0.1 m and 4 W/sr (the light of shapes.pov). Units: metres, watts; POV-Ray's pixel
// values are then radiance.
// A valid POV-Ray 3.7 file that photon reads unchanged:
//   photon render examples/scenes/revolved.pov -o revolved.png
//   povray -D +W640 +H480 +A0.3 +AM2 +R3 +HIexamples/scenes/povray/radphot_hq.inc +FE +Orevolved.exr examples/scenes/revolved.pov

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

// Superellipsoids: <e, n>, e shaping the cross-sections in xy, n the profile along z; each in the
// cube [-1, 1]^3, scaled to 0.2 m and set on the floor.
superellipsoid { <0.2, 0.2>  scale 0.2 rotate 30*y translate <-1.3, 0.2, 0.2>   texture { Red } }
superellipsoid { <1, 1>      scale 0.2 translate <-0.8, 0.2, 0.5>              texture { Green } }
superellipsoid { <2.5, 2.5>  scale 0.25 rotate <20, 30, 0> translate <-0.35, 0.25, 0.9> texture { Blue } }

// A vase turned from two Bezier curves (four points each: <radius, height>).
lathe {
  bezier_spline 8,
  <0.0, 0.0>, <0.35, 0.0>, <0.45, 0.25>, <0.25, 0.45>,
  <0.25, 0.45>, <0.12, 0.6>, <0.12, 0.75>, <0.2, 0.85>
  translate <0.3, 0, 0.8>
  texture { Yellow }
}

// A goblet: Catmull-Rom through the points (the first and last only steer the ends).
lathe {
  cubic_spline 9,
  <0.0, -0.1>, <0.0, 0.0>, <0.15, 0.01>, <0.03, 0.05>, <0.03, 0.3>, <0.2, 0.45>, <0.25, 0.65>, <0.24, 0.66>, <0.2, 0.7>
  translate <1.05, 0, 0.5>
  texture { White }
}

// A bowl: the squared radius a cubic in the height between the second and the second-last point,
// open at the top (no cap), so its inside shows.
sor {
  6,
  <0.0, -0.05>, <0.0, 0.0>, <0.25, 0.08>, <0.32, 0.2>, <0.34, 0.28>, <0.3, 0.35>
  open
  translate <0.95, 0, -0.35>
  texture { Orange }
}

// A cup cut into a block: the lathe's solid (its profile closed along the axis) removed.
difference {
  box { <-0.25, 0, -0.25>, <0.25, 0.3, 0.25> }
  lathe { linear_spline 5, <0, 0.1>, <0.15, 0.1>, <0.2, 0.25>, <0.2, 0.4>, <0, 0.4> }
  rotate 25*y translate <-0.2, 0, -0.3>
  texture { White }
}
