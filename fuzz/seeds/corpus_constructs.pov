// Constructs of POV-Ray's sample scenes: light groups, empty unions, nested objects, looks_like by
// name, optional commas, .gray, a stray #, weightless average maps, out-of-range values.
#include "colors.inc"
#macro Sub(A, B) (A - B) #end
#macro Place(O, V) object { O translate V } #end
#macro MT(A, B, C, D) transform { matrix <A.x, A.y, A.z, B.x, B.y, B.z, C.x, C.y, C.z, D.x, D.y, D.z> } #end
#macro Pick(V) #if (V) <1, 2> ; #else <3, 4> ; #end #end
#local T = MT(x, y, z, <0, 0, 0,>)
#declare P = Pick(1)
#declare Q = <1, 2> < <3, 1>;
#declare Arr = array[3] { <0.1, 9.4> <1, 2>, <3, 4> }
#declare Bulb = sphere { 0, 0.1 }
#declare G = (rgb <0.5, 1, 0.25>).gray + (color Red).grey;
camera { location <0, 1, -5> look_at <0, 1, 0>#
}
light_group {
  light_source { <0, 9, 0>, rgb <1, -1, 1> looks_like { Bulb pigment { rgb 1 } } }
  object { object { sphere { 0, Sub(2, -1) } transform T } }
  union { }
  global_lights on
}
light_source { 0, rgb -0.9 }
sphere { y, 1
  pigment { rgb <-0.5, G, 0.5> transmit 100 }
  finish { phong 1 phong_size 0 }
}
box { 0, 1 texture { average texture_map { [pigment { Red } finish { phong 1 }] [pigment { Blue }] } } }
mesh { smooth_triangle { 0, y, x, y, z, y uv_vectors <0, 0>, <1, 0>, <0, 1> } }
sphere { 0, frame_number + clock + 1 pigment { density_file df3 "none.df3" interpolate 1 } }
Place(sphere { 0, 1 } -y)
