// SPDX-License-Identifier: MIT
// The paper's room 2: room 1 unchanged (room1.pov: camera, light, room, settings) plus four
// objects outside. None blocks the direct sunlight through the window; the red facade 3.25 m
// behind the light is by far the brightest surface, fills the window and turns the room pink.
// Its radiance clips 8-bit images: write .exr, or use --exposure 0.5. (The file repeats room 1
// rather than #include it: POV-Ray looks for include files in the current directory.)
//   photon render examples/scenes/room2.pov -o room2.png --exposure 0.5
//   povray -D +W800 +H600 +A0.3 +AM2 +R3 +HIexamples/scenes/povray/radphot_hq.inc +FE +Oroom2.exr examples/scenes/room2.pov

#version 3.7;

global_settings {
  assumed_gamma 1.0
  ambient_light rgb 0
  max_trace_level 4
}

// photon's own settings (docs/scene-language.md); POV-Ray skips this block. The light is
// outside, so most photons land on the ground around the house: the room needs many more global
// photons than the Cornell box (the paper used 2,000,000).
#ifdef (photon_version)
global_settings {
  width 800 height 600
  render_mode pm
  global_photons 2000000
  global_estimate { count 100 radius 0.25 }
  // The glass ball throws a wide, dim caustic over the lower left wall (a third of its light
  // there). The paper's 200,000 caustic photons with 60 per estimate within 0.05 m drew it as
  // blotches; 2,000,000 with 200 per estimate, the radius from their density, draw it smooth.
  caustic_photons 2000000
  caustic_estimate { count 200 }
  max_photon_depth 10
  final_gather 1024
  cache_gather_noise 0.015  // the walls see the small sunlit patch: more rays where a gather varies
  shadow_samples 16
  samples_per_pixel 4
}
#end

// The sun: radius 0.2 m, 1000 W/sr per channel (power 12566 W); colour rule as in cornell.pov.
#declare Light_Intensity = 1000;
#declare Light_Radius = 0.2;
#declare Fade_D = 0.001;

camera {  // inside, near the front-right corner
  location <1.6, 1.3, -1.8>
  look_at <-0.6, 0.7, 1.5>
  up y
  right x*4/3
  angle 75                // horizontal field of view
}

light_source {
  <2.5, 4, 5>, rgb Light_Intensity / (2*pi*Fade_D*Fade_D)
  area_light <2*Light_Radius, 0, 0>, <0, 0, 2*Light_Radius>, 9, 9 circular orient jitter
  fade_distance Fade_D fade_power 2
  photons { refraction on reflection on }
}

#declare White = texture { pigment { rgb <0.75, 0.75, 0.75> } finish { ambient 0 diffuse 1 } }
#declare Red   = texture { pigment { rgb <0.75, 0.25, 0.25> } finish { ambient 0 diffuse 1 } }
#declare Green = texture { pigment { rgb <0.25, 0.75, 0.25> } finish { ambient 0 diffuse 1 } }
#declare Blue  = texture { pigment { rgb <0.25, 0.25, 0.75> } finish { ambient 0 diffuse 1 } }
#declare Glass = texture {
  pigment { rgbf <1, 1, 1, 1> }
  finish { ambient 0 diffuse 0 reflection { 0, 1 fresnel on } conserve_energy }
}
#declare Glass_Interior = interior { ior 1.5 }

box { <-20, -0.02, -20>, <20, 0, 20> texture { White } }  // the ground, inside and out

union {  // the room's shell; the walls stand on the ground
  box { <-2.02, 0, -2.02>, <-2, 2.52, 2.02> }     // left
  box { <2, 0, -2.02>, <2.02, 2.52, 2.02> }       // right
  box { <-2.02, 0, -2.02>, <2.02, 2.52, -2> }     // front, behind the camera
  box { <-2.02, 2.5, -2.02>, <2.02, 2.52, 2.02> } // ceiling
  // The back wall around the window opening x in [-0.8, 0.8], y in [0.9, 1.9].
  box { <-2.02, 0, 2>, <2.02, 0.9, 2.02> }        // below the window
  box { <-2.02, 1.9, 2>, <2.02, 2.52, 2.02> }     // above
  box { <-2.02, 0.9, 2>, <-0.8, 1.9, 2.02> }      // left of it
  box { <0.8, 0.9, 2>, <2.02, 1.9, 2.02> }        // right of it
  texture { White }
}

box { <-1.9, 0, 0.3>, <-1.3, 0.9, 1.5> texture { Red } }     // cabinet
sphere { <0.9, 0.35, 0.9>, 0.35 texture { Blue } }           // in the shade
sphere {  // in the sunlit patch: a caustic inside its own shadow
  <-0.9, 0.3, 0.3>, 0.3
  texture { Glass }
  interior { Glass_Interior }
  photons { target reflection on refraction on collect off }
}

// Outside.
box { <-8, 0, 8>, <8, 5, 8.5> texture { Red } }          // facade, facing the room
box { <4, 0, -3>, <4.3, 2, 6> texture { Blue } }         // fence wall
box { <-3, 0, 3.5>, <-1.5, 1.5, 5> texture { Green } }   // block
sphere { <3.2, 1, 3>, 1 texture { White } }              // ball
