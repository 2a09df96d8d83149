#declare S = seed(2026);
#declare R = rand(S) + rand(seed(-5)) + clock + clock_delta + frame_number + final_clock;
#declare F = function(a, b) { a*b + select(a - 1, 10, 20, 30) + sum(i, 1, 3, i*a) + prod(j, 1, 2, j) }
#declare G = function { x + 2*y - z/4 + u + pow(x, 2) }
#declare H = function { F(x, y) + G(x, y, z) / (1 + abs(z)) }
#declare P = function { pigment { rgb <0.25, 0.5, 0.75> } }
#declare T = function { transform { rotate 90*z translate x } }
#declare Q = function { pattern { checker scale 2 } }
#declare f_sphere = function { internal(61) }
#declare K = H(1, 2, 3) + P(0, 0, 0).green + T(1, 0, 0).y + acosh(2) + atanh(0.5) + bitwise_xor(12, 10);
#declare O = sphere { <1, 2, 3>, 2 rotate 30*z }
#declare E = max_extent(O) - min_extent(O) + vaxis_rotate(x, z, 90) * inside(O, <1, 2, 3>);
sphere { E, 0.5 translate <R, K, 0> }
light_source { <0, 5, 0>, rgb 1 }
