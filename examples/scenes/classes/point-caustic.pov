// SPDX-License-Identifier: MIT
// Scene class "point-caustic": a POINT light (no area) above a glass ball (radius 0.3 m, ior 1.5)
// that floats 0.5 m above a white floor. The ball focuses the light into a bright caustic on the
// floor inside its own shadow. A path tracer cannot find this light: a diffuse bounce would have to
// hit a point through the glass, so --mode reference is blind to it; only photon tracing (pm, and
// the stochastic progressive photon mapping judge, sppm) sees it.
// Light paths: L D E (the floor around the ball), L S+ D E (the caustic), L D S+ E (the floor seen
// through the ball), L S+ D S+ E.
// Part of the scene-class gallery (docs/scene-classes.md). Metres and watts, as in cornell.pov.
//   photon render examples/scenes/classes/point-caustic.pov -o point-caustic.png

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
  shadow_samples 1
  samples_per_pixel 4
}
#end

#declare Light_Intensity = 3;
#declare Fade_D = 0.001;

camera {
  location <0, 1.4, -2.2>
  look_at <0, 0.2, 0>
  up y
  right x*4/3
  angle 50
}

light_source {  // a point light: no area_light
  <0.1, 1.8, 0.1>, rgb Light_Intensity / (2*pi*Fade_D*Fade_D)
  fade_distance Fade_D fade_power 2
  photons { refraction on reflection on }
}

box { <-3, -0.02, -3>, <3, 0, 3> pigment { rgb 0.75 } finish { ambient 0 diffuse 1 } }   // floor
sphere {
  <0, 0.5, 0>, 0.3
  pigment { rgbf <1, 1, 1, 1> }
  finish { ambient 0 diffuse 0 reflection { 0, 1 fresnel on } conserve_energy }
  interior { ior 1.5 }
  photons { target reflection on refraction on collect off }
}
