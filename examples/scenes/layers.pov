// SPDX-License-Identifier: MIT
// POV-Ray's layered textures (docs/scene-language.md, "Layered textures"): each `texture` written
// after the first lies on top of the ones before it, and where its pigment has `filter` or
// `transmit` the layers below show through (filter tinted by the layer's colour, transmit not).
// From left to right: red and clear spots (bozo) over white; blue stripes that filter the orange
// below; a clear coat (`rgbt 1` with a phong highlight) over marble; three layers. The wall is a
// declared layered texture, the floor a checker under a fading gradient. Every layer's own finish
// weighs its colour, as in POV-Ray (the floor's bottom has ambient 0 and diffuse 0.8, the layer
// on top POV-Ray's defaults). A valid POV-Ray 3.7 file without radiosity, so the two renderers
// compute the same terms:
//   photon render examples/scenes/layers.pov --mode rt -o layers.png
//   povray -D +W640 +H360 +A0.3 +AM2 +R3 +FE +Olayers.exr examples/scenes/layers.pov

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

light_source { <-3, 5, -4>, rgb 1.1 }

// Floor: a grey checker under a blue gradient that fades from clear (left) to opaque (right).
box { <-5, -0.02, -3>, <5, 0, 2.02>
  texture { pigment { checker rgb 0.75, rgb 0.35 scale 0.5 } finish { ambient 0 diffuse 0.8 } }
  texture { pigment { gradient x color_map { [0 rgbt <0.2, 0.3, 0.9, 1>] [1 rgb <0.2, 0.3, 0.9>] } scale 10 translate -5*x } }
}

// Wall: a declared layered texture, green stripes (filter 0.6) over a warm white.
#declare Striped = texture { pigment { rgb <0.85, 0.8, 0.7> } }
  texture { pigment { gradient y color_map { [0.5 rgbf <0.2, 0.9, 0.3, 0.6>] [0.5 rgbt 1] } scale 0.4 } }
box { <-5, -0.02, 2>, <5, 3, 2.02> texture { Striped } }

// Red and clear spots over white.
sphere { <-2.1, 0.5, 0>, 0.5
  texture { pigment { rgb 0.9 } }
  texture { pigment { bozo color_map { [0.45 rgb <0.9, 0.1, 0.1>] [0.55 rgbt 1] } scale 0.15 } }
}
// Blue stripes filtering the orange below: where they lie, only the orange's blue passes.
sphere { <-0.7, 0.5, 0>, 0.5
  texture { pigment { rgb <1, 0.55, 0.1> } finish { diffuse 0.8 } }
  texture { pigment { gradient y color_map { [0.5 rgbf <0.3, 0.5, 1, 0.7>] [0.5 rgbt 1] } scale 0.25 } }
}
// A clear coat over marble: the highlight lives on the top layer, the colour below it.
sphere { <0.7, 0.5, 0>, 0.5
  texture { pigment { marble turbulence 0.6 color_map { [0 rgb <0.9, 0.85, 0.75>] [1 rgb <0.3, 0.2, 0.15>] } scale 0.4 } }
  texture { pigment { rgbt 1 } finish { phong 0.9 phong_size 60 } }
}
// Three layers: a yellow base, a half-clear magenta checker, grey wisps (transmit) on top.
sphere { <2.1, 0.5, 0>, 0.5
  texture { pigment { rgb <0.9, 0.8, 0.2> } }
  texture { pigment { checker rgbt <0.8, 0.1, 0.6, 0.5>, rgbt 1 scale 0.25 } }
  texture { pigment { spotted color_map { [0.4 rgbt 1] [0.8 rgbt <0.2, 0.2, 0.2, 0.3>] } scale 0.2 } }
}
