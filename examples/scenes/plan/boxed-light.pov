// SPDX-License-Identifier: MIT
// Light-path plan example "boxed-light": the diffuse-ball class (a red ball on a white floor,
// lit by a sphere light) plus a crate to the right with a bright lamp shut inside it, 5 times the
// visible light's power. The crate is closed and opaque and the camera is outside it, so the plan
// (docs/effects-plan.md) gives the lamp no photons: all 200000 global photons go to the light
// that reaches the image, instead of one in six. Forced with --effects lights=on, 5/6 of them
// are spent inside the crate.
//   photon render examples/scenes/plan/boxed-light.pov -o boxed-light.png
//   photon render examples/scenes/plan/boxed-light.pov -o forced.png --effects lights=on

#version 3.7;

global_settings { assumed_gamma 1.0 ambient_light rgb 0 max_trace_level 4 }

#ifdef (photon_version)
global_settings {
  width 320 height 240
  render_mode pm
  global_photons 200000
  caustic_photons 0
  global_estimate { count 100 radius 0.25 }
  final_gather 256
  shadow_samples 16
  samples_per_pixel 4
}
#end

#declare Light_Intensity = 2;
#declare Fade_D = 0.001;

camera { location <0, 1.3, -2.4> look_at <0, 0.3, 0> up y right x*4/3 angle 50 }

light_source {
  <0.9, 1.6, -0.4>, rgb Light_Intensity / (2*pi*Fade_D*Fade_D)
  area_light <0.2, 0, 0>, <0, 0, 0.2>, 5, 5 circular orient jitter
  fade_distance Fade_D fade_power 2
}

light_source {  // the lamp in the crate
  <1.6, 0.35, 1.0>, rgb 5 * Light_Intensity / (2*pi*Fade_D*Fade_D)
  fade_distance Fade_D fade_power 2
}

box { <-3, -0.02, -3>, <3, 0, 3> pigment { rgb 0.75 } finish { ambient 0 diffuse 1 } }   // floor
sphere { <0, 0.4, 0>, 0.4 pigment { rgb <0.75, 0.25, 0.25> } finish { ambient 0 diffuse 1 } }
box { <1.3, 0, 0.7>, <1.9, 0.7, 1.3> pigment { rgb 0.6 } finish { ambient 0 diffuse 1 } }   // the crate
