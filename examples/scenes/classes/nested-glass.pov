// SPDX-License-Identifier: MIT
// Scene class "nested-glass": two glass cubes (0.4 m, ior 1.5) touching face to face, 0.2 m above a
// white floor, a small glass ball inside the left cube and a glass ball resting on the right one.
// Tests coincident and nested refracting surfaces: at the shared face a ray leaves one cube and
// enters the other at the same point; the inner ball is an air-to-glass interface seen from inside
// glass (photon's materials have one ior against vacuum, so every renderer here treats it alike).
// Many refractions and total internal reflections per path.
// Light paths: L D E, L S+ D E (caustics on the floor), L D S+ E (the floor through the glass),
// L S+ D S+ E.
// Part of the scene-class gallery (docs/scene-classes.md). Metres and watts, as in cornell.pov.
//   photon render examples/scenes/classes/nested-glass.pov -o nested-glass.png

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
union {
  box { <-0.4, 0.2, -0.2>, <0, 0.6, 0.2> }      // left cube
  box { <0, 0.2, -0.2>, <0.4, 0.6, 0.2> }       // right cube, touching it at x = 0
  sphere { <-0.2, 0.4, 0>, 0.12 }               // inside the left cube
  sphere { <0.2, 0.8, 0>, 0.2 }                 // resting on the right cube
  texture { Glass }
  interior { ior 1.5 }
  photons { target reflection on refraction on collect off }
}
