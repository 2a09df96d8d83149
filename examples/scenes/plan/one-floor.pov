// SPDX-License-Identifier: MIT
// Light-path plan example "one-floor": one diffuse floor under a small sphere light, nothing
// else, at the photon defaults (200000 global and 200000 caustic photons, 256-ray final
// gathers). The floor cannot light itself, so the plan (docs/effects-plan.md) keeps only the
// direct light: no photon map, no precomputation, no irradiance cache, no final gather, and the
// image equals `--mode rt`.
//   photon render examples/scenes/plan/one-floor.pov -o one-floor.png
//   photon render examples/scenes/plan/one-floor.pov -o forced.png --effects indirect=on

#version 3.7;

global_settings { assumed_gamma 1.0 ambient_light rgb 0 max_trace_level 4 }

#ifdef (photon_version)
global_settings { width 320 height 240 shadow_samples 16 samples_per_pixel 4 }
#end

#declare Fade_D = 0.001;

camera { location <0, 1.3, -2.4> look_at <0, 0.3, 0> up y right x*4/3 angle 50 }

light_source {
  <0.9, 1.6, -0.4>, rgb 2 / (2*pi*Fade_D*Fade_D)
  area_light <0.2, 0, 0>, <0, 0, 0.2>, 5, 5 circular orient jitter
  fade_distance Fade_D fade_power 2
}

box { <-3, -0.02, -3>, <3, 0, 3> pigment { rgb 0.75 } finish { ambient 0 diffuse 1 } }   // floor
