// SPDX-License-Identifier: MIT
// Scene class "diffuse-ball": a red diffuse ball (radius 0.4 m) resting on a white floor, lit by
// a small sphere light (radius 0.1 m, 2 W/sr) above and to the side. Tests colour bleeding from a
// convex diffuse object onto the floor next to the contact point (red light the floor receives
// from the ball), the soft contact shadow, and the density estimate on a curved surface (the ball).
// Light paths: L D E (direct light on the ball and the floor), L D D+ E (the floor lit by the
// ball, the ball's underside lit by the floor). No specular surface.
// Part of the scene-class gallery (docs/scene-classes.md). Metres and watts, as in cornell.pov.
//   photon render examples/scenes/classes/diffuse-ball.pov -o diffuse-ball.png

#version 3.7;

global_settings { assumed_gamma 1.0 ambient_light rgb 0 max_trace_level 4 }

#ifdef (photon_version)
global_settings {
  width 320 height 240
  render_mode pm
  global_photons 200000
  caustic_photons 0
  global_estimate { count 100 }
  final_gather 256
  shadow_samples 16
  samples_per_pixel 4
}
#end

// Light colour rule as in cornell.pov: intensity I W/sr, fade_power 2 with a tiny fade_distance.
#declare Light_Intensity = 2;
#declare Light_Radius = 0.1;
#declare Fade_D = 0.001;

camera {
  location <0, 1.3, -2.4>
  look_at <0, 0.3, 0>
  up y
  right x*4/3
  angle 50
}

light_source {
  <0.9, 1.6, -0.4>, rgb Light_Intensity / (2*pi*Fade_D*Fade_D)
  area_light <2*Light_Radius, 0, 0>, <0, 0, 2*Light_Radius>, 5, 5 circular orient jitter
  fade_distance Fade_D fade_power 2
}

box { <-3, -0.02, -3>, <3, 0, 3> pigment { rgb 0.75 } finish { ambient 0 diffuse 1 } }   // floor
sphere { <0, 0.4, 0>, 0.4 pigment { rgb <0.75, 0.25, 0.25> } finish { ambient 0 diffuse 1 } }
