// SPDX-License-Identifier: MIT
// Scene class "mesh": a diffuse green triangle mesh read from an OBJ file (blob.obj: a lumpy,
// bunny-like blob of 320 flat-shaded triangles, 0.85 m long, written by make-blob-obj.py) resting
// on a white floor, lit by a small sphere light (radius 0.1 m, 2 W/sr). Tests mesh intersection,
// flat shading and density estimates on a faceted, concave-and-convex surface, and the shadow the
// mesh casts on the floor. POV-Ray cannot read OBJ files, so it sees a sphere in the mesh's place
// (the #else branch): the file stays valid POV-Ray, the mesh is photon's only.
// Light paths: L D E, L D D+ E (the floor lit by the mesh and the mesh by the floor). No specular
// surface.
// Part of the scene-class gallery (docs/scene-classes.md). Metres and watts, as in cornell.pov.
//   photon render examples/scenes/classes/mesh.pov -o mesh.png

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
  shadow_samples 16
  samples_per_pixel 4
}
#end

#declare Light_Intensity = 2;
#declare Light_Radius = 0.1;
#declare Fade_D = 0.001;

camera {
  location <-0.4, 1.1, -1.9>
  look_at <0.05, 0.25, 0>
  up y
  right x*4/3
  angle 50
}

light_source {
  <-0.7, 1.5, -0.6>, rgb Light_Intensity / (2*pi*Fade_D*Fade_D)
  area_light <2*Light_Radius, 0, 0>, <0, 0, 2*Light_Radius>, 5, 5 circular orient jitter
  fade_distance Fade_D fade_power 2
}

#declare Green = texture { pigment { rgb <0.25, 0.75, 0.25> } finish { ambient 0 diffuse 1 } }

box { <-3, -0.02, -3>, <3, 0, 3> pigment { rgb 0.75 } finish { ambient 0 diffuse 1 } }   // floor
#ifdef (photon_version)
  mesh { obj "blob.obj" rotate <0, -30, 0> texture { Green } }
#else
  sphere { <0, 0.28, 0>, 0.28 texture { Green } }
#end
