// SPDX-License-Identifier: MIT
// Scene class "csg-glass": glass made by CSG, 0.2 m above a white floor: a lens (the intersection
// of two spheres of radius 0.35 whose centres are 0.4 m apart) and a glass block with a spherical
// hole cut through its top (a difference), ior 1.5. Tests refraction at CSG surfaces: photons and
// camera rays enter and leave where the membership of the whole changes, the lens's rim where its
// two caps meet, the hole's wall with its normal turned out of the result.
// Light paths: L D E, L S+ D E (the lens's and the block's caustics on the floor), L D S+ E (the
// floor through the glass), L S+ D S+ E.
// Part of the scene-class gallery (docs/scene-classes.md). Metres and watts, as in cornell.pov.
//   photon render examples/scenes/classes/csg-glass.pov -o csg-glass.png

#version 3.7;

global_settings { assumed_gamma 1.0 ambient_light rgb 0 max_trace_level 10 }

#ifdef (photon_version)
global_settings {
  width 320 height 240
  render_mode pm
  global_photons 100000
  caustic_photons 200000
  global_estimate { count 100 }
  caustic_estimate { count 60 }
  max_photon_depth 20
  final_gather 256
  shadow_samples 16
  samples_per_pixel 4
}
#end

#declare Light_Intensity = 3;
#declare Light_Radius = 0.2;
#declare Fade_D = 0.001;

camera {
  location <0.3, 1.4, -2.0>
  look_at <0, 0.35, 0>
  up y
  right x*4/3
  angle 50
}

light_source {
  <0.4, 1.9, -0.3>, rgb Light_Intensity / (2*pi*Fade_D*Fade_D)
  area_light <2*Light_Radius, 0, 0>, <0, 0, 2*Light_Radius>, 5, 5 circular orient jitter
  fade_distance Fade_D fade_power 2
  photons { refraction on reflection on }
}

#declare Glass = texture {
  pigment { rgbf <1, 1, 1, 1> }
  finish { ambient 0 diffuse 0 reflection { 0, 1 fresnel on } conserve_energy }
}

box { <-3, -0.02, -3>, <3, 0, 3> pigment { rgb 0.75 } finish { ambient 0 diffuse 1 } }   // floor
intersection {                                   // a lens, its axis along x
  sphere { <-0.45, 0.45, 0>, 0.35 }
  sphere { <-0.05, 0.45, 0>, 0.35 }
  texture { Glass }
  interior { ior 1.5 }
  photons { target reflection on refraction on collect off }
}
difference {                                     // a block with a hole cut through its top
  box { <0.05, 0.2, -0.2>, <0.45, 0.6, 0.2> }
  sphere { <0.25, 0.62, 0>, 0.15 }
  texture { Glass }
  interior { ior 1.5 }
  photons { target reflection on refraction on collect off }
}
