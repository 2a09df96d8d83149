// SPDX-License-Identifier: MIT
// Textures: the Cornell box of cornell.pov with patterned pigments that photon evaluates at every
// point (POV-Ray 3.7's patterns and noise): a checker floor, a marble back wall, wood and
// granite side walls, and spheres of agate, bozo and leopard spots beside a glass sphere whose
// caustic lands on the checker floor. Photons take the colour of the square they land on, so the
// floor bleeds its colours onto the walls and spheres.
// Units and light as in cornell.pov (metres, watts, radiance); a valid POV-Ray 3.7 file:
//   photon render examples/scenes/textures.pov -o textures.png
//   povray -D +W800 +H600 +A0.3 +AM2 +R3 +HIexamples/scenes/povray/radphot_hq.inc +FE +Otextures.exr examples/scenes/textures.pov

#version 3.7;

global_settings {
  assumed_gamma 1.0
  ambient_light rgb 0
  max_trace_level 4
}

#ifdef (photon_version)
global_settings {
  width 800 height 600
  render_mode pm
  global_photons 200000
  caustic_photons 200000
  global_estimate { count 100 radius 0.25 }
  caustic_estimate { count 60 radius 0.05 }
  max_photon_depth 10
  final_gather 256
  shadow_samples 16
  samples_per_pixel 4
}
#end

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

#declare Matte = finish { ambient 0 diffuse 1 }

// Floor: checker squares of 0.3 m, cream and dark red.
box { <-1.22, -0.02, -1.2>, <1.22, 0, 1.22>
  texture { pigment { checker rgb <0.8, 0.75, 0.6>, rgb <0.45, 0.08, 0.06> scale 0.3 } finish { Matte } } }
// Ceiling: plain white.
box { <-1.22, 1.8, -1.2>, <1.22, 1.82, 1.22> texture { pigment { rgb 0.75 } finish { Matte } } }
// Back wall: veined marble.
box { <-1.22, -0.02, 1.2>, <1.22, 1.82, 1.22>
  texture {
    pigment {
      marble turbulence 0.9 octaves 5
      color_map { [0 rgb <0.78, 0.78, 0.74>] [0.75 rgb <0.62, 0.64, 0.66>] [0.9 rgb <0.25, 0.27, 0.35>] [1 rgb <0.1, 0.1, 0.15>] }
      scale 0.45 rotate <0, 0, 60>
    }
    finish { Matte }
  } }
// Left wall: wood, rings around a vertical axis seen across the grain.
box { <-1.22, -0.02, -1.2>, <-1.2, 1.82, 1.22>
  texture {
    pigment {
      wood turbulence 0.04
      color_map { [0 rgb <0.7, 0.45, 0.22>] [0.7 rgb <0.55, 0.3, 0.12>] [1 rgb <0.3, 0.14, 0.05>] }
      scale 0.08 rotate <90, 0, 0>
    }
    finish { Matte }
  } }
// Right wall: blue granite.
box { <1.2, -0.02, -1.2>, <1.22, 1.82, 1.22>
  texture {
    pigment { granite color_map { [0 rgb <0.2, 0.25, 0.7>] [0.5 rgb <0.35, 0.4, 0.75>] [1 rgb <0.05, 0.05, 0.2>] } scale 0.6 }
    finish { Matte }
  } }

sphere {  // agate, back left
  <-0.6, 0.35, 0.55>, 0.35
  texture { pigment { agate scale 0.25 } finish { Matte } }
}
sphere {  // bozo in three colours, back right, moved with its texture
  <0, 0, 0>, 0.3
  texture {
    pigment { bozo color_map { [0 rgb <0.75, 0.7, 0.2>] [0.5 rgb <0.2, 0.6, 0.3>] [1 rgb <0.1, 0.25, 0.6>] } scale 0.12 }
    finish { Matte }
  }
  translate <0.6, 0.3, 0.7>
}
sphere {  // leopard spots, front left
  <-0.55, 0.25, -0.55>, 0.25
  texture {
    pigment { leopard color_map { [0 rgb <0.8, 0.6, 0.25>] [0.3 rgb <0.8, 0.6, 0.25>] [0.45 rgb <0.08, 0.05, 0.02>] [1 rgb <0.08, 0.05, 0.02>] } scale 0.03 }
    finish { Matte }
  }
}
sphere {  // glass, front right; its caustic falls on the checker floor
  <0.45, 0.35, -0.45>, 0.35
  texture { pigment { rgbf <1, 1, 1, 1> } finish { ambient 0 diffuse 0 reflection { 0, 1 fresnel on } conserve_energy } }
  interior { ior 1.5 }
  photons { target reflection on refraction on collect off }
}
