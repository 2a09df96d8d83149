sphere { 0, 1 material { texture { pigment { rgb <0.8, 0.2, 0.2> } finish { diffuse 0.6 reflection 0.2 } } interior { ior 1.5 } } }
box { -1, 1 material { texture { pigment { rgbt <1, 1, 1, 0.9> } } interior { ior 1.33 } } translate 3*x }
light_source { <0, 5, -5>, rgb 1 }
