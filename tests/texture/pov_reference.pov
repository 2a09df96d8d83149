// Prints POV-Ray 3.7's own pattern values at a few points, for texture_test.cpp. A pigment
// function with the colour map [0 rgb 0][1 rgb 1] returns the pattern's value as its red channel.
// Run: scripts/pov-pattern-reference.sh (povray +W1 +H1 -D, the values go to the debug stream).
#version 3.7;
global_settings { assumed_gamma 1 }
#macro Probe(Name, Pig)
  #local F = function { pigment { Pig } }
  #debug concat("{\"", Name, "\", {")
  #local Points = array[6] { <0.13, 0.27, 0.41>, <1.7, -0.6, 2.3>, <-3.21, 4.05, -0.77>, <10.5, 0.25, -7.125>, <0.5, 0.5, 0.5>, <-0.35, -1.9, 0.62> }
  #for (I, 0, 5)
    #local P = Points[I];
    #debug concat(str(F(P.x, P.y, P.z).red, 0, 12), #if (I < 5) ", " #else "" #end)
  #end
  #debug "}},\n"
#end
#declare Ramp = color_map { [0 rgb 0] [1 rgb 1] }
Probe("checker", pigment { checker rgb 0, rgb 1 })
Probe("gradient x", pigment { gradient x color_map { Ramp } })
Probe("gradient <1,2,0.5>", pigment { gradient <1, 2, 0.5> color_map { Ramp } })
Probe("bozo", pigment { bozo color_map { Ramp } })
Probe("spotted", pigment { spotted color_map { Ramp } })
Probe("bozo noise_generator 1", pigment { bozo noise_generator 1 color_map { Ramp } })
Probe("bozo noise_generator 3", pigment { bozo noise_generator 3 color_map { Ramp } })
Probe("bozo turbulence", pigment { bozo turbulence 0.3 octaves 3 omega 0.7 lambda 2.5 color_map { Ramp } })
Probe("granite", pigment { granite color_map { Ramp } })
Probe("granite noise_generator 1", pigment { granite noise_generator 1 color_map { Ramp } })
Probe("marble", pigment { marble color_map { Ramp } })
Probe("marble turbulence", pigment { marble turbulence 0.5 color_map { Ramp } })
Probe("wood", pigment { wood color_map { Ramp } })
Probe("wood turbulence", pigment { wood turbulence <0.1, 0.2, 0> color_map { Ramp } })
Probe("agate", pigment { agate color_map { Ramp } })
Probe("agate agate_turb 0.5", pigment { agate agate_turb 0.5 color_map { Ramp } })
Probe("onion", pigment { onion color_map { Ramp } })
Probe("leopard", pigment { leopard color_map { Ramp } })
Probe("radial", pigment { radial color_map { Ramp } })
Probe("ripples", pigment { ripples color_map { Ramp } })
Probe("waves", pigment { waves color_map { Ramp } })
Probe("spherical", pigment { spherical scale 3 color_map { Ramp } })
Probe("sine_wave", pigment { gradient y sine_wave color_map { Ramp } })
Probe("triangle_wave", pigment { gradient y triangle_wave color_map { Ramp } })
Probe("scallop_wave", pigment { gradient y scallop_wave color_map { Ramp } })
Probe("cubic_wave", pigment { gradient y cubic_wave color_map { Ramp } })
Probe("frequency phase", pigment { gradient y frequency 3 phase 0.2 color_map { Ramp } })
Probe("transformed granite", pigment { granite scale <2, 1, 0.5> rotate <10, 20, 30> translate <0.3, -1, 2> color_map { Ramp } })
Probe("color_map", pigment { gradient x color_map { [0.2 rgb 0.1] [0.5 rgb 0.9] [0.5 rgb 0.3] [0.8 rgb 0.6] } })
Probe("cells", pigment { cells color_map { Ramp } })
Probe("crackle", pigment { crackle color_map { Ramp } })
Probe("crackle scaled", pigment { crackle scale 0.37 color_map { Ramp } })
Probe("crackle form", pigment { crackle form <0.3, 0.6, -0.4> scale 0.5 color_map { Ramp } })
Probe("crackle metric 1 offset", pigment { crackle metric 1 offset 0.2 scale 0.5 color_map { Ramp } })
Probe("crackle metric 3", pigment { crackle metric 3 form <1, 0, 0> color_map { Ramp } })
Probe("crackle solid", pigment { crackle solid scale 0.3 color_map { Ramp } })
Probe("bumps", pigment { bumps color_map { Ramp } })
Probe("dents", pigment { dents scale 0.4 color_map { Ramp } })
Probe("wrinkles", pigment { wrinkles color_map { Ramp } })
Probe("wrinkles noise_generator 1", pigment { wrinkles noise_generator 1 scale 0.3 color_map { Ramp } })
Probe("wrinkles noise_generator 3", pigment { wrinkles noise_generator 3 color_map { Ramp } })
Probe("mandel", pigment { mandel 50 scale 3 color_map { Ramp } })
Probe("mandel frequency", pigment { mandel 25 frequency 3 scale 3 color_map { Ramp } })
Probe("mandel interior 1", pigment { mandel 30 interior 1, 2 scale 3 color_map { Ramp } })
Probe("mandel exterior 6", pigment { mandel 40 exterior 6, 0.2 interior 4, 1 scale 3 color_map { Ramp } })
Probe("mandel exterior 7", pigment { mandel 40 exterior 7, 3 interior 6, 0.5 scale 2 color_map { Ramp } })
