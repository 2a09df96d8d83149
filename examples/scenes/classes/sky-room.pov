// SPDX-License-Identifier: MIT
// Scene class "sky-room": a small closed room (interior 2 m x 1.5 m x 2 m, 0.02 m walls) with one
// window in its back wall, lit by nothing but the sky: a sky_sphere gradient, bright and bluish
// overhead, pale at the horizon, over a warm grey background below the horizon. The floor is a
// checker (a textured diffuse surface: photons and gathers read its colour where they land), the
// walls are coloured. Inside, the floor and walls that see the window get the sky's direct light
// (shadow rays to the sky through the opening); the rest of the room only light that bounced off
// the floor and the walls. The room stands alone under the sky (no ground outside: the sky's
// background shows below the horizon), so that the ball the sky's photons enter through is the
// room's and about one in twenty of them comes through the window.
// Light paths: L D E (the sky through the window), L D D+ E (the rest). No specular surface.
// Part of the scene-class gallery (docs/scene-classes.md). Metres, radiance, as in cornell.pov.
//   photon render examples/scenes/classes/sky-room.pov -o sky-room.png

#version 3.7;

global_settings { assumed_gamma 1.0 ambient_light rgb 0 max_trace_level 4 }

#ifdef (photon_version)
global_settings {
  width 320 height 240
  render_mode pm
  global_photons 1000000
  caustic_photons 0
  global_estimate { count 100 }
  final_gather 256
  samples_per_pixel 4
}
#end

camera {  // inside, near the front-left corner, looking at the window
  location <-0.7, 1.0, -0.85>
  look_at <0.2, 0.6, 1.0>
  up y
  right x*4/3
  angle 80
}

background { rgb <0.3, 0.27, 0.24> }
sky_sphere {
  pigment {
    gradient y
    color_map { [0 rgb <1.6, 1.6, 1.5>] [1 rgb <0.7, 0.9, 1.6>] }
  }
}

#declare Matte = finish { ambient 0 diffuse 1 };

box { <-1.02, -0.02, -1.02>, <1.02, 0, 1.02>  // the floor, under the walls
  pigment { checker rgb 0.8, rgb <0.45, 0.4, 0.35> scale 0.25 } finish { Matte } }

union {  // the room's shell; the walls stand on the ground
  box { <-1.02, 0, -1.02>, <-1, 1.52, 1.02> }     // left
  box { <1, 0, -1.02>, <1.02, 1.52, 1.02> }       // right
  box { <-1.02, 0, -1.02>, <1.02, 1.52, -1> }     // front, behind the camera
  box { <-1.02, 1.5, -1.02>, <1.02, 1.52, 1.02> } // ceiling
  // The back wall around the window opening x in [-0.7, 0.7], y in [0.35, 1.25].
  box { <-1.02, 0, 1>, <1.02, 0.35, 1.02> }       // below the window
  box { <-1.02, 1.25, 1>, <1.02, 1.52, 1.02> }    // above
  box { <-1.02, 0.35, 1>, <-0.7, 1.25, 1.02> }    // left of it
  box { <0.7, 0.35, 1>, <1.02, 1.25, 1.02> }      // right of it
  pigment { rgb <0.8, 0.75, 0.6> } finish { Matte }
}

sphere { <0.45, 0.25, 0.3>, 0.25 pigment { rgb <0.25, 0.3, 0.75> } finish { Matte } }
box { <-0.95, 0, -0.2>, <-0.6, 0.5, 0.4> pigment { rgb <0.75, 0.3, 0.25> } finish { Matte } }
