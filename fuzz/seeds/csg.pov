#declare Glass = texture { pigment { rgbf 1 } finish { reflection { 0, 1 fresnel on } } }
#declare Lens = intersection { sphere { -0.5*y, 1 } sphere { 0.5*y, 1 } texture { Glass } interior { ior 1.5 } }
object { Lens translate y photons { target } }
difference { box { -1, 1 pigment { rgb 1 } } sphere { 1, 0.8 pigment { rgb <1, 0, 0> } } cylinder { -2*x, 2*x, 0.2 } rotate 30*y }
merge { sphere { 0, 1 } sphere { x, 1 inverse inverse } union { box { -2, -1.5 } sphere { 2, 0.3 } } hollow on }
intersection { sphere { 0, 1 } plane { y, 0.2 inverse } merge { triangle { 0, x, y } sphere { z, 1 } } light_source { 3*y, 1 } }
difference { plane { y, 0 } sphere { 0, 1 } } intersection { sphere { -3*x, 1 } sphere { 3*x, 1 } }
sphere { 2*z, 0.5 inverse texture { Glass } interior { ior 1.33 } }
#declare In = inside(Lens, <0, 0, 0>); #declare N = <0, 0, 0>; #declare P = trace(Lens, <0, 5, 0>, -y, N);
light_source { <2, 4, -3>, 1 }
