// Prints POV-Ray 3.7's hexagon pattern (0, 1 or 2) on a 21 x 21 grid of the x-z plane, over
// both signs of x and z, for texture_test.cpp (pov_hexagon_values.inc).
// Run: scripts/pov-pattern-reference.sh (povray +W1 +H1 -D, the values go to the debug stream).
#version 3.7;
global_settings { assumed_gamma 1 }
#declare F = function { pigment { hexagon rgb 0, rgb 0.5, rgb 1 } }
#for (I, 0, 20)
  #for (K, 0, 20)
    #local X = -3.1 + 0.31 * I;
    #local Z = -3.05 + 0.29 * K;
    #debug concat("{", str(X, 0, 4), ", ", str(Z, 0, 4), ", ", str(2 * F(X, 0.3, Z).red, 0, 0), "},\n")
  #end
#end
