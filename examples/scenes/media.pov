// SPDX-License-Identifier: MIT
// Media: participating media as POV-Ray 3.7 renders them (docs/scene-language.md, "Media").
// A glowing ball (emission whose density falls off from its centre), a box of absorbing media
// that tints the checker seen through it, and a spotlight's beam scattered by a thin haze that
// fills the room (atmospheric media). The containers are clear (`rgbt 1`, `hollow`) and cast no
// shadow of their own; the lamp that lights the room is kept out of the haze
// (`media_interaction off`), so the beam is the spotlight's alone.
// A valid POV-Ray 3.7 file:
//   photon render examples/scenes/media.pov -o media.png
//   povray -D +W400 +H300 +A0.3 +Omedia.png examples/scenes/media.pov

#version 3.7;

global_settings { assumed_gamma 1.0 }

#ifdef (photon_version)
global_settings {
  width 400 height 300
  render_mode pm
  global_photons 200000
  caustic_photons 100000
  samples_per_pixel 4
}
#end

camera {
  location <0, 2.2, -7>
  look_at <0, 1.2, 0>
  right x*4/3
  angle 55
}

// The room's lamp: lights the surfaces, not the haze.
light_source { <3, 6, -6>, rgb 0.6 media_interaction off }

// The spotlight whose beam the haze shows.
light_source {
  <-1, 6, 1>, rgb <1.0, 0.9, 0.7> * 1.5
  spotlight
  point_at <0.6, 0, -0.4>
  radius 7
  falloff 10
}

// A thin haze everywhere outside the objects: the beam.
media { scattering { 1, rgb 0.04 } intervals 2 samples 12 }

plane { y, 0 pigment { checker rgb 0.8, rgb 0.35 } finish { diffuse 0.7 ambient 0 } }
plane { -z, -4 pigment { rgb <0.7, 0.72, 0.75> } finish { diffuse 0.7 ambient 0 } }

// Glowing ball: emission whose density is 1 at the centre and 0 at the surface.
sphere { 0, 1
  pigment { rgbt 1 }
  finish { ambient 0 diffuse 0 }
  hollow
  no_shadow
  interior {
    media {
      emission <1.6, 0.7, 0.25>
      density { spherical color_map { [0 rgb 0] [1 rgb 1] } }
    }
  }
  scale 0.9
  translate <-1.8, 1.1, 0.5>
}

// A box of absorbing media: blue and green are absorbed more than red.
box { <-0.5, 0, -0.5>, <0.5, 1.4, 0.5>
  pigment { rgbt 1 }
  finish { ambient 0 diffuse 0 }
  hollow
  no_shadow
  interior { media { absorption <0.3, 1.2, 1.8> } }
  rotate y*25
  translate <1.7, 0, 0.3>
}
