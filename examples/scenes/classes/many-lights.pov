// SPDX-License-Identifier: MIT
// Scene class "many-lights": a white floor under 100 small coloured sphere lights (radius 0.02 m,
// 0.02 W/sr each) on a 10 x 10 grid, made by #while loops, at heights from 0.3 m to 0.7 m. Tests
// many lights: the sum of their direct light, how photons are shared out between them (pm-direct
// reads all light from the photon map), and the cost of shadow rays per light.
// Light paths: L D E only (a flat floor does not light itself), so ray tracing (rt) must match the
// judge too.
// Part of the scene-class gallery (docs/scene-classes.md). Metres and watts, as in cornell.pov.
//   photon render examples/scenes/classes/many-lights.pov -o many-lights.png

#version 3.7;

global_settings { assumed_gamma 1.0 ambient_light rgb 0 max_trace_level 4 }

#ifdef (photon_version)
global_settings {
  width 320 height 240
  render_mode pm
  global_photons 200000
  caustic_photons 0
  global_estimate { count 100 }
  final_gather 64
  shadow_samples 1      // one shadow ray per light: a hundred small lights are smooth enough
  samples_per_pixel 4
}
#end

#declare Fade_D = 0.001;

camera {
  location <0, 2.4, -2.2>
  look_at <0, 0, 0.1>
  up y
  right x*4/3
  angle 60
}

#declare I = 0;
#while (I < 10)
  #declare J = 0;
  #while (J < 10)
    // Colours cycle through six hues; heights rise along the diagonal.
    #declare Hue = mod(I + 2*J, 6);
    #if (Hue = 0) #declare Colour = <1, 0.3, 0.3>;
    #elseif (Hue = 1) #declare Colour = <0.3, 1, 0.3>;
    #elseif (Hue = 2) #declare Colour = <0.3, 0.3, 1>;
    #elseif (Hue = 3) #declare Colour = <1, 1, 0.3>;
    #elseif (Hue = 4) #declare Colour = <0.3, 1, 1>;
    #else #declare Colour = <1, 0.3, 1>;
    #end
    light_source {
      <-1.35 + 0.3*I, 0.3 + 0.4*(I + J)/18, -1.35 + 0.3*J>, rgb 0.02*Colour / (2*pi*Fade_D*Fade_D)
      area_light <0.04, 0, 0>, <0, 0, 0.04>, 2, 2 circular orient jitter
      fade_distance Fade_D fade_power 2
    }
    #declare J = J + 1;
  #end
  #declare I = I + 1;
#end

box { <-3, -0.02, -3>, <3, 0, 3> pigment { rgb 0.75 } finish { ambient 0 diffuse 1 } }   // floor
