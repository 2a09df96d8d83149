// SPDX-License-Identifier: MIT
// POV-Ray's finish terms as POV-Ray 3.7 computes them (docs/scene-language.md, "Finish"): from
// left to right a Phong highlight, a sharp Blinn highlight (`specular`, `roughness`), a gold
// `metallic` highlight that takes the pigment's colour, `brilliance 5` (direct light falls off as
// cos^5 towards the edge), and a sphere lit by `ambient` and `emission` alone. The floor and wall
// keep POV-Ray's default `ambient 0.1`, the constant fill that lifts their shadows; highlights and
// ambient light nothing else (photon adds them, as POV-Ray does, to direct light only).
// A valid POV-Ray 3.7 file without radiosity, so the two renderers compute the same terms:
//   photon render examples/scenes/finish.pov --mode rt -o finish.png
//   povray -D +W640 +H360 +A0.3 +AM2 +R3 +FE +Ofinish.exr examples/scenes/finish.pov

#version 3.7;

global_settings {
  assumed_gamma 1.0
  max_trace_level 4
}

#ifdef (photon_version)
global_settings {
  width 640 height 360
  render_mode rt
  samples_per_pixel 4
}
#end

camera {
  location <0, 1.4, -6.2>
  look_at <0, 0.45, 0>
  up y
  right x*16/9
  angle 50
}

// POV-Ray's brightness, no fade: every point of the scene sees the light at full strength.
light_source { <-3, 5, -4>, rgb 1.1 }

#declare Floor = texture { pigment { rgb 0.7 } }  // POV-Ray's default finish: ambient 0.1, diffuse 0.6
box { <-5, -0.02, -3>, <5, 0, 2.02> texture { Floor } }
box { <-5, -0.02, 2>, <5, 3, 2.02> texture { Floor } }

sphere { <-2.2, 0.45, 0>, 0.45
  pigment { rgb <0.7, 0.15, 0.1> }
  finish { ambient 0 diffuse 0.8 phong 0.8 phong_size 60 }
}
sphere { <-1.1, 0.45, 0>, 0.45
  pigment { rgb <0.1, 0.2, 0.7> }
  finish { ambient 0 diffuse 0.8 specular 0.9 roughness 0.004 }
}
sphere { <0, 0.45, 0>, 0.45
  pigment { rgb <1, 0.7, 0.25> }
  finish { ambient 0 diffuse 0.3 specular 1 roughness 0.03 metallic }
}
sphere { <1.1, 0.45, 0>, 0.45
  pigment { rgb 0.9 }
  finish { ambient 0 diffuse 0.9 brilliance 5 }
}
sphere { <2.2, 0.45, 0>, 0.45
  pigment { rgb <1, 0.55, 0.2> }
  finish { ambient 0.5 emission 0.3 diffuse 0 }
}
