// SPDX-License-Identifier: MIT
// Sky light: a few objects lit by nothing but a sky_sphere, a blue gradient overhead fading to a
// pale horizon, and the background colour under it (POV-Ray 3.7 shows the background through a
// sky_sphere's transparent parts; here the ground hides the lower half). No light_source: photon
// lights the scene with its sky (shadow rays to it for direct light, photons from it for the rest,
// docs/scene-language.md, "Sky"), as POV-Ray does under radiosity. A mirror ball shows the sky, and
// a small hut with one open side shows light coming in only through its opening.
// A valid POV-Ray 3.7 file:
//   photon render examples/scenes/sky.pov -o sky.png
//   povray -D +W400 +H300 +A0.3 +AM2 +R3 +HIexamples/scenes/povray/radphot.inc +FE +Osky.exr examples/scenes/sky.pov

#version 3.7;

global_settings {
  assumed_gamma 1.0
  ambient_light rgb 0
  max_trace_level 10
}

#ifdef (photon_version)
global_settings {
  width 400 height 300
  render_mode pm
  global_photons 1000000
  caustic_photons 0
  global_estimate { count 100 radius 0.3 }
  final_gather 256
  samples_per_pixel 4
}
#end

camera {
  location <0, 1.6, -5.5>
  look_at <0, 0.6, 0>
  right x*4/3
  angle 55
}

background { rgb <0.25, 0.22, 0.2> }

sky_sphere {
  pigment {
    gradient y
    color_map { [0 rgb <0.9, 0.95, 1.0>] [1 rgb <0.25, 0.45, 0.9>] }
  }
}

#declare Matte = finish { ambient 0 diffuse 1 };

// Ground: a large slab (bounded, so the sky's photons cover it).
box { <-8, -0.1, -8>, <8, 0, 8> pigment { checker rgb 0.7, rgb 0.45 } finish { Matte } }

sphere { <-1.6, 0.6, 0.2>, 0.6 pigment { rgb <0.85, 0.25, 0.2> } finish { Matte } }
sphere { <0, 0.5, -0.6>, 0.5 pigment { rgb 0 } finish { ambient 0 diffuse 0 reflection 0.9 } }
cylinder { <1.4, 0, 0.6>, <1.4, 1.2, 0.6>, 0.35 pigment { rgb <0.3, 0.7, 0.35> } finish { Matte } }

// A hut open towards the camera: inside, only the light that comes in through its opening.
union {
  box { <-0.6, 0, 1.6>, <0.6, 1.0, 1.65> }        // back wall
  box { <-0.65, 0, 0.8>, <-0.6, 1.0, 1.65> }      // left wall
  box { <0.6, 0, 0.8>, <0.65, 1.0, 1.65> }        // right wall
  box { <-0.65, 1.0, 0.8>, <0.65, 1.05, 1.65> }   // roof
  pigment { rgb 0.8 } finish { Matte }
}
