#declare M = color_map { [0 rgb 0] [0.5 rgbt <1, 0, 0, 0.5>] [0.5 rgb 1] [1 rgb <0, 0, 1>] }
#declare P = pigment { bozo color_map { M } scale 0.3 }
camera { location <0, 2, -5> look_at 0 }
light_source { <0, 5, -5>, rgb 1 }
plane { y, 0 pigment { checker rgb 1, rgb <0.2, 0.2, 0.6> scale 0.5 } finish { ambient 0 diffuse 1 } }
sphere { 0, 1 pigment { P turbulence 0.5 octaves 3 omega 0.6 lambda 2.5 } translate x }
sphere { 0, 1 pigment { marble turbulence <0.5, 0.2, 0> sine_wave frequency 2 phase 0.1 color_map { M } } }
sphere { 0, 1 pigment { wood noise_generator 3 triangle_wave rotate x * 90 } translate -2 * x }
box { -1, 1 pigment { granite scallop_wave } scale 0.5 translate 2 * y }
box { -1, 1 pigment { agate agate_turb 0.4 cubic_wave } texture { pigment { gradient <1, 2, 0> poly_wave 2 } } }
union { sphere { 0, 1 pigment { onion } } sphere { x, 1 } pigment { leopard scale 0.1 } translate y }
sphere { 0, 1 pigment { radial frequency 6 } } sphere { 0, 1 pigment { ripples } } sphere { 0, 1 pigment { waves warp { turbulence 1 } } }
sphere { 0, 1 pigment { spherical } } sphere { 0, 1 pigment { planar } } sphere { 0, 1 pigment { boxed } } sphere { 0, 1 pigment { cylindrical } }
