#version 3.7;
// Macros: by value and by reference, #local scope, recursion, macros giving objects.
#macro Set(P, V) #declare P = V; #end
#macro Fact(N) #local R = 1; #if (N > 1) #local R = N * Fact(N - 1); #end R #end
#macro Ball(C, R) sphere { C, R pigment { rgb <1, 0.5, 0> } } #end
#macro Opt(A, optional B) #ifdef (B) A + B #else A #end #end
#declare X = 1;
Set(X, Fact(4))
#declare Y = Opt(1, ) + Opt(1, 2);
Ball(<X, 0, 0>, 0.5)
#declare O = Ball(0, 1);
object { O translate y }
#declare M = material { texture { pigment { rgb 1 } finish { diffuse 0.8 } } }
box { -1, 1 material { M } }
light_source { <0, 5, -5>, rgb 1 }
camera { location <0, 1, -5> look_at 0 }
