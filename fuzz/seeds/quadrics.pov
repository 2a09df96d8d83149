// The round shapes: cylinder, cone, disc and torus, placed by similarities and by general maps,
// with the values POV-Ray reads in its own way (equal cone radii, negative and zero radii).
camera { location <0, 3, -8> look_at <0, 0.5, 0> }
light_source { <3, 6, -4>, rgb 1 fade_distance 1 fade_power 2 }
#default { finish { ambient 0 } }
#declare Post = cylinder { 0, y, 0.1 open }
object { Post translate <-2, 0, 0> }
union { object { Post } cone { y, 0.2, 1.3*y, 0 } translate 2*x }
cylinder { <-1, 0, 1>, <1, 0, 1>, 0.25 scale <1, 2, 0.5> rotate 20*y pigment { rgb <1, 0.5, 0.2> } }
cone { 0, 0.5, <0, 1, 0>, 0.5 open }
cone { <0, 0, -1>, 0.6, <0, 0.8, -1>, 0.1 matrix <1, 0.2, 0, 0, 1, 0, 0, 0.5, 1, 0, 0, 0> }
disc { <0, 0.01, 0>, y, 3, 1 pigment { rgb 0.8 } }
disc { <1, 1, -1> <0, 0, -1> 0.5 0.25 scale <2, 1, 1> }
disc { 0, -y, -1 }
torus { 0.8, 0.2 sturm rotate 90*x translate <0, 1, 1> }
torus { 0.2, 0.4 scale <1, 0.5, 1> translate y }
torus { 0, 0.3 translate <1, 0.3, -2> }
cylinder { 0, y, 0 }
#if (inside(Post, <0, 0.5, 0>)) sphere { trace(Post, <0, 0.5, -5>, z), 0.05 } #end
