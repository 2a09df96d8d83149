// SPDX-License-Identifier: MIT
// Scene class "mirror-plane": a white floor ending at a mirror `plane` (z = 1) that stands on it,
// lit by a small sphere light (radius 0.15 m, 2 W/sr) 0.7 m in front of the mirror. Tests light
// that reaches a diffuse surface by way of a mirror (the floor next to the mirror receives the
// light's mirror image as well as the light), and a mirror seen by the camera.
// Light paths: L D E (direct light), L S D E (floor lit by the light's mirror image: a caustic
// path), L D S E (the floor seen in the mirror), L S D S E, L D S D E (the floor lit by its own
// mirror image).
// Part of the scene-class gallery (docs/scene-classes.md). Metres and watts, as in cornell.pov.
//   photon render examples/scenes/classes/mirror-plane.pov -o mirror-plane.png

#version 3.7;

global_settings { assumed_gamma 1.0 ambient_light rgb 0 max_trace_level 4 }

#ifdef (photon_version)
global_settings {
  width 320 height 240
  render_mode pm
  global_photons 200000
  caustic_photons 200000
  global_estimate { count 100 }
  caustic_estimate { count 60 }
  final_gather 256
  shadow_samples 16
  samples_per_pixel 4
}
#end

#declare Light_Intensity = 2;
#declare Light_Radius = 0.15;
#declare Fade_D = 0.001;

camera {
  location <-1.2, 1.4, -2.0>
  look_at <0.1, 0.3, 0.8>
  up y
  right x*4/3
  angle 55
}

light_source {
  <0.2, 0.9, 0.3>, rgb Light_Intensity / (2*pi*Fade_D*Fade_D)
  area_light <2*Light_Radius, 0, 0>, <0, 0, 2*Light_Radius>, 5, 5 circular orient jitter
  fade_distance Fade_D fade_power 2
}

box { <-3, -0.02, -3>, <3, 0, 1> pigment { rgb 0.75 } finish { ambient 0 diffuse 1 } }   // floor
plane {  // the mirror, standing on the floor's far edge
  z, 1
  pigment { rgb 0 } finish { ambient 0 diffuse 0 reflection { 1 } }
  photons { target reflection on refraction on collect off }
}
