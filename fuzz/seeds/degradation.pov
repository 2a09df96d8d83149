// Constructs photon reads but does not render: skipped objects, patterns, effects, camera and light types.
camera { orthographic location <0, 2, -6> look_at 0 angle 60 }
light_source { <0, 6, -3>, 1 parallel point_at 0 }
light_source { <0, 6, -3>, 1 spotlight radius -90 falloff 90 projected_through { sphere { 0, 1 } } }
fog { distance 5 color rgb 0.5 }
sky_sphere { pigment { gradient y color_map { [0 rgb 1] [0.5, 1 color rgb 0 color rgb z] } } }
#declare M = colour_map { [0 rgb 0] [1 rgb <1, 0, 0>] }
#declare Post = superellipsoid { <0.5, 0.5> scale <0.1, 1, 0.1> }
object { Post translate x }
plane { y, 0 pigment { checker rgb x, rgb 1 } }
sphere { 0, 1 pigment { marble color_map { M } turbulence 0.5 octaves 3 warp { repeat x } } normal { bumps 0.5 } }
sphere { 0, 1 texture { pigment { rgb 1 } } texture { gradient x texture_map { [0 pigment { rgb 0 }] [1 pigment { rgb 1 } finish { phong 1 }] } } }
difference { box { -1, 1 } cone { 0, 1, y, 0 } torus { 1, 0.2 } bounded_by { box { -1, 1 } } }
blob { threshold 0.5 sphere { 0, 1, 1 } }
mesh2 { vertex_vectors { 3, 0, x, y } face_indices { 1, <0, 1, 2> } }
sphere { 0, 1 pigment { brick rgb 1, rgb 0 brick_size 2 mortar 0.1 } finish { subsurface { translucency 1 } } }
