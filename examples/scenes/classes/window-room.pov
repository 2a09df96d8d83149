// SPDX-License-Identifier: MIT
// Scene class "window-room": a small closed room (interior 2 m x 1.5 m x 2 m, 0.02 m walls) lit
// only through a window in its back wall by a distant sun: a sphere light (radius 0.2 m) 20 m away
// emitting 2000 W/sr into a narrow cone (4 degrees) around the window, so that most photons reach
// the house. The sunlit patch on the floor is lit directly; everything else in the room only
// indirectly, after one or more diffuse bounces. As in room1.pov, the ground slab is the floor
// inside and the sunlit ground outside, 0.02 m apart across each wall (the light-leak case).
// Light paths: L D E (the sunlit patch), L D D+ E (the rest of the room). No specular surface.
// Part of the scene-class gallery (docs/scene-classes.md). Metres and watts, as in cornell.pov.
//   photon render examples/scenes/classes/window-room.pov -o window-room.png

#version 3.7;

global_settings { assumed_gamma 1.0 ambient_light rgb 0 max_trace_level 4 }

#ifdef (photon_version)
global_settings {
  width 320 height 240
  render_mode pm
  global_photons 1000000  // at 400000, k = 100 photons span the corners: dark there (docs/scene-classes.md)
  caustic_photons 0
  global_estimate { count 100 }
  final_gather 256
  shadow_samples 16
  samples_per_pixel 4
}
#end

#declare Light_Intensity = 2000;
#declare Light_Radius = 0.2;
#declare Fade_D = 0.001;
#declare Window_Centre = <0, 0.8, 1.01>;

camera {  // inside, near the front-right corner
  location <0.8, 1.0, -0.9>
  look_at <-0.3, 0.5, 0.9>
  up y
  right x*4/3
  angle 80
}

light_source {  // 20 m from the window, 35 degrees up, from the right
  Window_Centre + 20*vnormalize(<0.35, 0.7, 1>), rgb Light_Intensity / (2*pi*Fade_D*Fade_D)
  spotlight radius 4 falloff 4 tightness 0 point_at Window_Centre
  area_light <2*Light_Radius, 0, 0>, <0, 0, 2*Light_Radius>, 5, 5 circular orient jitter
  fade_distance Fade_D fade_power 2
}

#declare White = texture { pigment { rgb 0.75 } finish { ambient 0 diffuse 1 } }

box { <-5, -0.02, -5>, <5, 0, 5> texture { White } }  // the ground, inside and out

union {  // the room's shell; the walls stand on the ground
  box { <-1.02, 0, -1.02>, <-1, 1.52, 1.02> }     // left
  box { <1, 0, -1.02>, <1.02, 1.52, 1.02> }       // right
  box { <-1.02, 0, -1.02>, <1.02, 1.52, -1> }     // front, behind the camera
  box { <-1.02, 1.5, -1.02>, <1.02, 1.52, 1.02> } // ceiling
  // The back wall around the window opening x in [-0.4, 0.4], y in [0.5, 1.1].
  box { <-1.02, 0, 1>, <1.02, 0.5, 1.02> }        // below the window
  box { <-1.02, 1.1, 1>, <1.02, 1.52, 1.02> }     // above
  box { <-1.02, 0.5, 1>, <-0.4, 1.1, 1.02> }      // left of it
  box { <0.4, 0.5, 1>, <1.02, 1.1, 1.02> }        // right of it
  texture { White }
}

sphere { <0.45, 0.25, 0.3>, 0.25 pigment { rgb <0.25, 0.25, 0.75> } finish { ambient 0 diffuse 1 } }
box { <-0.95, 0, -0.2>, <-0.6, 0.5, 0.4> pigment { rgb <0.75, 0.25, 0.25> } finish { ambient 0 diffuse 1 } }
