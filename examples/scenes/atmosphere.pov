// SPDX-License-Identifier: MIT
// Atmosphere: a ground fog lying in a valley of posts, under a cloudy sky whose clouds are a
// pigment_map of patterned pigments (POV-Ray's skies.inc idiom: a gradient picking between a
// horizon colour and two wrinkles/bozo cloud pigments, each placed by its own transformations).
// A mirror ball shows the fog over the ground it reflects; the glass ball keeps the fog out of its
// inside (docs/scene-language.md, "Fog"). Lit by one sun-like point light; the sky lights the
// scene too in photon (in POV-Ray under radiosity).
// A valid POV-Ray 3.7 file:
//   photon render examples/scenes/atmosphere.pov -o atmosphere.png
//   povray -D +W400 +H300 +A0.3 +AM2 +R3 +HIexamples/scenes/povray/radphot.inc +FE +Oatmosphere.exr examples/scenes/atmosphere.pov

#version 3.7;

global_settings {
  assumed_gamma 1.0
  max_trace_level 10
}

#ifdef (photon_version)
global_settings {
  width 400 height 300
  render_mode pm
  global_photons 400000
  caustic_photons 200000
  final_gather 128
  samples_per_pixel 4
}
#end

camera {
  location <0, 1.2, -7>
  look_at <0, 1.0, 0>
  right x*4/3
  angle 60
}

light_source { <-30, 40, -20>, rgb <1.0, 0.95, 0.85> * 1.0 }

#declare Cloud_Wisps =
  pigment {
    wrinkles
    turbulence 0.3
    color_map { [0.0 rgb <0.25, 0.4, 0.75>] [0.5 rgb <0.8, 0.82, 0.9>] [1.0 rgb 1] }
    scale <0.4, 0.08, 0.4>
  }
#declare Cloud_Heaps =
  pigment {
    bozo
    turbulence 0.6
    color_map { [0.0 rgb <0.3, 0.45, 0.8>] [0.6 rgb <0.35, 0.5, 0.85>] [1.0 rgb <0.95, 0.95, 1.0>] }
    scale 0.25
  }

sky_sphere {
  pigment {
    gradient y
    pigment_map {
      [0.00 rgb <0.85, 0.8, 0.8>]  // horizon
      [0.15 Cloud_Wisps rotate z * 10]
      [0.50 Cloud_Heaps scale <1, 0.6, 1>]
    }
  }
}

// Ground fog: as thick as constant fog of distance 8 below y = 0, half as thick at y = 0.35.
fog {
  fog_type 2
  distance 8
  color rgb <0.85, 0.85, 0.9>
  fog_offset 0
  fog_alt 0.35
  turbulence 0.5
  up y
}

plane { y, 0 pigment { checker rgb <0.45, 0.4, 0.3>, rgb <0.3, 0.28, 0.22> scale 1 } finish { diffuse 0.8 ambient 0 } }

#declare Post = cylinder { 0, y * 2.2, 0.12 pigment { rgb <0.6, 0.35, 0.2> } finish { diffuse 0.8 ambient 0 } }
#for (I, -3, 3)
  object { Post translate <I * 1.6, 0, 4 + abs(I) * 0.8> }
#end

sphere { <-1.4, 0.9, 0.5>, 0.9
  pigment { rgb 1 } finish { reflection 0.95 diffuse 0 ambient 0 } }
sphere { <1.4, 0.9, 0.5>, 0.9
  pigment { rgbf <0.95, 1, 0.95, 1> } finish { diffuse 0 ambient 0 reflection { 0, 1 fresnel on } conserve_energy }
  interior { ior 1.5 } }
