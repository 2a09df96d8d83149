#include "nested.inc"
#include "colors.inc"
#local L = <1, 2, 3>;
sphere { L, 1 pigment { White } finish { diffuse 0.5 reflection { 0.1, 0.3 fresnel on } conserve_energy } interior { ior 1.5 } }
light_source { <0, 5, 0>, Red fade_distance 2 fade_power 2 }
