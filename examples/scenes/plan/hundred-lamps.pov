// SPDX-License-Identifier: MIT
// Light-path plan example "hundred-lamps": a building of 5 x 5 sealed rooms (3 m square, 2.5 m
// high, walls 0.1 m thick), four small lamps under each ceiling: 100 lights, of which the camera,
// in the middle room, sees the light of 4. No wall is one closed solid, so the plan cannot prove
// the other 96 hidden (docs/effects-plan.md); its pilot pass finds that none of their light lands
// on what the camera sees and gives the global photons to the middle room's lamps instead of
// sharing them by power, keeping each hidden lamp a floor of 10% of its share by power.
//   photon render examples/scenes/plan/hundred-lamps.pov -o hundred-lamps.png
//   photon render examples/scenes/plan/hundred-lamps.pov -o by-power.png --effects lights=on

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
  shadow_samples 4
  samples_per_pixel 4
}
#end

#declare Fade_D = 0.001;
#declare Room = 3;
#declare Height = 2.5;
#declare Wall = 0.05;  // half a wall's thickness

// The camera stands in room (2, 2), whose floor spans [6, 9] x [6, 9].
camera { location <6.5, 1.6, 6.4> look_at <8.4, 0.8, 8.6> up y right x*4/3 angle 70 }

#declare White = texture { pigment { rgb 0.75 } finish { ambient 0 diffuse 1 } }

box { <-Wall, -0.1, -Wall>, <5*Room + Wall, 0, 5*Room + Wall> texture { White } }                 // floor
box { <-Wall, Height, -Wall>, <5*Room + Wall, Height + 0.1, 5*Room + Wall> texture { White } }   // ceiling
#declare K = 0;
#while (K <= 5)
  box { <K*Room - Wall, 0, -Wall>, <K*Room + Wall, Height, 5*Room + Wall> texture { White } }     // along z
  box { <-Wall, 0, K*Room - Wall>, <5*Room + Wall, Height, K*Room + Wall> texture { White } }     // along x
  #declare K = K + 1;
#end
sphere { <7.9, 0.45, 7.9>, 0.45 pigment { rgb <0.75, 0.3, 0.25> } finish { ambient 0 diffuse 1 } }

#declare I = 0;
#while (I < 10)
  #declare J = 0;
  #while (J < 10)
    light_source {
      <0.75 + 1.5*I, Height - 0.3, 0.75 + 1.5*J>, rgb 0.3 / (2*pi*Fade_D*Fade_D)
      area_light <0.1, 0, 0>, <0, 0, 0.1>, 2, 2 circular orient jitter
      fade_distance Fade_D fade_power 2
    }
    #declare J = J + 1;
  #end
  #declare I = I + 1;
#end
