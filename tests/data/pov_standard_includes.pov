// Every standard include photon is expected to read, with one declaration from each in use.
// Read with the includes of Debian's povray-includes (tests/dsl/pov_includes_test.sh).
#version 3.7;
global_settings { assumed_gamma 1.0 }
#include "colors.inc"
#include "textures.inc"
#include "finish.inc"
#include "metals.inc"
#include "glass.inc"
#include "golds.inc"
#include "woods.inc"
#include "stones.inc"
#include "shapes.inc"
#include "math.inc"
#include "transforms.inc"
#include "consts.inc"

camera { location <0, 2, -6> look_at <0, 0.5, 0> }
light_source { <3, 6, -4> color White }
plane { y, 0 pigment { color Gray50 } finish { Phong_Glossy } }
sphere { <-2, 1, 0>, 0.8 texture { T_Silver_3A } }
sphere { <0, 1, 0>, 0.8 texture { T_Gold_3C } }
sphere { <2, 1, 0>, 0.8 material { M_Glass } }
box { <-3, 0, 2>, <-2, 1, 3> texture { T_Wood1 } }
box { <2, 0, 2>, <3, 1, 3> texture { T_Stone1 } }
box { <-0.5, 0, 2>, <0.5, 1, 3> texture { Polished_Chrome } transform { Axis_Rotate_Trans(y, 30) } }
object { Round_Box(<-1, 0, -2>, <1, 0.5, -1.5>, 0.1, 0) pigment { color rgb VPow(<0.5, 0.5, 0.5>, 2) } }
sphere { o + <0, 3, 2>, 0.2 pigment { color Red } }
