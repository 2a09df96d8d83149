// SPDX-License-Identifier: MIT
// POV-Ray's image-based objects: a height field of rolling hills with a crater (images_hills.png,
// 16-bit grey, smooth, water_level), draped with the image map images_tiles.png laid flat on it
// (map_type 0); a ball wrapped in the same image (map_type 1, bilinear interpolation), and a
// panel, on a white floor before a white wall, lit by a spherical light of radius
// 0.1 m and 4 W/sr (the light of shapes.pov). Units: metres, watts; POV-Ray's pixel values are
// then radiance. make_images_pngs.py writes the two images.
// A valid POV-Ray 3.7 file that photon reads unchanged:
//   photon render examples/scenes/images.pov -o images.png
//   povray -D +W640 +H480 +A0.3 +AM2 +R3 +HIexamples/scenes/povray/radphot_hq.inc +Lexamples/scenes +FE +Oimages.exr examples/scenes/images.pov

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
  location <0, 1.5, -3.3>
  look_at <0, 0.35, 0.2>
  up y
  right x*4/3
  angle 52
}

light_source {
  <-0.6, 2.2, -1.4>, rgb Light_Intensity / (2*pi*Fade_D*Fade_D)
  area_light <2*Light_Radius, 0, 0>, <0, 0, 2*Light_Radius>, 9, 9 circular orient jitter
  fade_distance Fade_D fade_power 2
}

#declare Matte = finish { ambient 0 diffuse 1 }
#declare White = texture { pigment { rgb 0.75 } finish { Matte } }

box { <-3, -0.02, -2>, <3, 0, 1.5>      texture { White } }  // floor
box { <-3, 0, 1.5>, <3, 2.5, 1.52>      texture { White } }  // back wall

// The hills: the unit square's heights (0 to 1) scaled to 1.6 x 0.45 x 1.6; below 0.12 of the
// height range is water (not drawn). The tiles image, turned from the x-y plane onto x-z, covers
// the field once.
height_field {
  png "images_hills.png"
  smooth
  water_level 0.12
  texture {
    pigment { image_map { png "images_tiles.png" } rotate 90*x }
    finish { Matte }
  }
  scale <1.6, 0.45, 1.6>
  translate <-1.5, 0, -0.6>
}

// A ball wrapped in the image: longitude across its width, latitude up its height.
sphere {
  0, 0.35
  texture {
    pigment { image_map { png "images_tiles.png" map_type 1 interpolate 2 } }
    finish { Matte }
  }
  rotate -60*y
  translate <0.75, 0.35, -0.3>
}

// A panel leaning on the wall, the image on its unit square (normalized-distance interpolation), 0.8 m wide.
box {
  <0, 0, 0>, <1, 1, 0.02>
  texture {
    pigment { image_map { png "images_tiles.png" interpolate 4 } }
    finish { Matte }
  }
  scale 0.8
  rotate 10*x
  translate <0.45, 0, 1.1>
}
