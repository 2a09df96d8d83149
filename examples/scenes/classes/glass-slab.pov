// SPDX-License-Identifier: MIT
// Scene class "glass-slab": a 10 cm thick glass slab (1 m x 0.8 m, ior 1.5) floating 0.5 m above
// a white floor, lit from above by a sphere light (radius 0.2 m, 3 W/sr). The floor under the slab
// receives light only through the glass (two refractions, Fresnel losses and internal reflections):
// ray tracing shows a shadow there, photon mapping's caustic map must fill it.
// Light paths: L D E (the floor around the slab), L S+ D E (the floor under the slab, through the
// glass), L D S+ E (the floor seen through or mirrored in the slab), L S+ D S+ E, L D S+ D E (floor
// light the slab sends back to the floor). The floor is the only diffuse surface and it is flat,
// so there is no L D D E.
// Part of the scene-class gallery (docs/scene-classes.md). Metres and watts, as in cornell.pov.
//   photon render examples/scenes/classes/glass-slab.pov -o glass-slab.png

#version 3.7;

global_settings { assumed_gamma 1.0 ambient_light rgb 0 max_trace_level 8 }

#ifdef (photon_version)
global_settings {
  width 320 height 240
  render_mode pm
  global_photons 100000
  caustic_photons 200000
  global_estimate { count 100 }
  caustic_estimate { count 60 }
  final_gather 256
  shadow_samples 16
  samples_per_pixel 4
}
#end

#declare Light_Intensity = 3;
#declare Light_Radius = 0.2;
#declare Fade_D = 0.001;

camera {
  location <0, 2.3, -1.9>
  look_at <0, 0.2, 0>
  up y
  right x*4/3
  angle 55
}

light_source {
  <0.3, 1.8, 0.1>, rgb Light_Intensity / (2*pi*Fade_D*Fade_D)
  area_light <2*Light_Radius, 0, 0>, <0, 0, 2*Light_Radius>, 5, 5 circular orient jitter
  fade_distance Fade_D fade_power 2
  photons { refraction on reflection on }
}

box { <-3, -0.02, -3>, <3, 0, 3> pigment { rgb 0.75 } finish { ambient 0 diffuse 1 } }   // floor
box {  // the slab
  <-0.5, 0.5, -0.4>, <0.5, 0.6, 0.4>
  pigment { rgbf <1, 1, 1, 1> }
  finish { ambient 0 diffuse 0 reflection { 0, 1 fresnel on } conserve_energy }
  interior { ior 1.5 }
  photons { target reflection on refraction on collect off }
}
