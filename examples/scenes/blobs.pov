// SPDX-License-Identifier: MIT
// POV-Ray's blob in the Cornell box of cornell.pov: two crossed rods with a hollow carved by a
// negative sphere (POV-Ray's blob1a, red), three sphere components melting into one drop (green),
// a rod whose components are turned and stretched by their own transformations with a squashed
// ball at its foot (blue), and a glass blob of two spheres whose caustic lands on the floor.
// Units and light as in cornell.pov (metres, watts, radiance); a valid POV-Ray 3.7 file:
//   photon render examples/scenes/blobs.pov -o blobs.png
//   povray -D +W800 +H600 +A0.3 +AM2 +R3 +HIexamples/scenes/povray/radphot_hq.inc +FE +Oblobs.exr examples/scenes/blobs.pov

#version 3.7;

global_settings {
  assumed_gamma 1.0
  ambient_light rgb 0
  max_trace_level 4
}

#ifdef (photon_version)
global_settings {
  width 800 height 600
  render_mode pm
  global_photons 200000
  caustic_photons 200000
  global_estimate { count 100 radius 0.25 }
  caustic_estimate { count 60 radius 0.05 }
  max_photon_depth 10
  final_gather 256
  shadow_samples 16
  samples_per_pixel 4
}
#end

#declare Light_Intensity = 2.5;
#declare Light_Radius = 0.1;
#declare Fade_D = 0.001;

camera {
  location <0, 0.9, -3.5>
  look_at <0, 0.9, 0>
  up y
  right x*4/3
  angle 53.13
}

light_source {
  <0, 1.5, 0>, rgb Light_Intensity / (2*pi*Fade_D*Fade_D)
  area_light <2*Light_Radius, 0, 0>, <0, 0, 2*Light_Radius>, 9, 9 circular orient jitter
  fade_distance Fade_D fade_power 2
  photons { refraction on reflection on }
}

#declare Matte = finish { ambient 0 diffuse 1 }
#declare White = texture { pigment { rgb 0.75 } finish { Matte } }

box { <-1.22, -0.02, -1.2>, <1.22, 0, 1.22>       texture { White } }  // floor
box { <-1.22, 1.8, -1.2>, <1.22, 1.82, 1.22>      texture { White } }  // ceiling
box { <-1.22, -0.02, 1.2>, <1.22, 1.82, 1.22>     texture { White } }  // back wall
box { <-1.22, -0.02, -1.2>, <-1.2, 1.82, 1.22>    texture { pigment { rgb <0.75, 0.25, 0.25> } finish { Matte } } }
box { <1.2, -0.02, -1.2>, <1.22, 1.82, 1.22>      texture { pigment { rgb <0.25, 0.25, 0.75> } finish { Matte } } }

// blob1a's crossed cylinders, a negative sphere carving a hollow where they meet; back left.
blob {
  threshold 0.5
  cylinder { <-7, 0, 0>, <7, 0, 0>, 4, 2 }
  cylinder { <0, 0, -7>, <0, 0, 7>, 4, 2 }
  sphere { <0, 3, 0>, 2.5, -4 }
  scale 0.05 rotate -35*y translate <-0.4, 0.15, 0.6>
  texture { pigment { rgb <0.75, 0.25, 0.22> } finish { Matte } }
}

// Three spheres (the old `component` syntax) melting into one drop; front left.
blob {
  threshold 0.6
  component 1.0, 1.0, <0.75, 0, 0>
  component 1.0, 1.0, <-0.375, 0.64952, 0>
  component 1.0, 1.0, <-0.375, -0.64952, 0>
  rotate <90, 30, 0> scale 0.3 translate <-0.6, 0.14, -0.55>
  texture { pigment { rgb <0.3, 0.7, 0.35> } finish { Matte } }
}

// A leaning rod with a squashed ball at its foot: each component placed by its own transforms.
blob {
  threshold 0.4
  cylinder { <0, 0, 0>, <0, 1.1, 0>, 0.16, 1 rotate 12*z translate <0.05, 0, 0> }
  sphere { <0, 0, 0>, 0.4, 1.5 scale <1, 0.45, 1> }
  translate <0.75, 0.13, 0.6>
  texture { pigment { rgb <0.25, 0.35, 0.75> } finish { Matte } }
}

// Glass: two spheres joined by a neck; its caustic falls on the floor in front of it.
blob {
  threshold 0.5
  sphere { <-0.17, 0, 0>, 0.3, 1 }
  sphere { <0.17, 0, 0>, 0.3, 1 }
  rotate 30*y translate <0.35, 0.17, -0.5>
  texture { pigment { rgbf <1, 1, 1, 1> } finish { ambient 0 diffuse 0 reflection { 0, 1 fresnel on } conserve_energy } }
  interior { ior 1.5 }
  photons { target reflection on refraction on collect off }
}
