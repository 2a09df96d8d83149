#declare Glass = texture { pigment { rgbf <1, 1, 1, 0.9> } finish { reflection 0.1 } }
#declare Ball = sphere { 0, 1 texture { Glass } interior { ior 1.33 } }
union { object { Ball translate x } object { Ball translate -x } box { <-1, -1, -1>, <1, 1, 1> rotate 30*y } }
merge { triangle { <0,0,0>, <1,0,0>, <0,1,0> } smooth_triangle { <0,0,0>, y, <1,0,0>, y, <0,0,1>, y } }
mesh { triangle { <0,0,0>, <1,0,0>, <0,1,0> } triangle { <0,0,1>, <1,0,1>, <0,1,1> } pigment { color red 1 green 0.5 blue 0.2 } }
plane { <0, 1, 0>, 0 pigment { rgb 0.8 } finish { ambient 0 diffuse 0.8 phong 0.3 phong_size 40 } }
light_source { <2, 4, -3> color rgb <1, 1, 1> spotlight point_at 0 radius 10 falloff 20 tightness 5 }
light_source { <0, 3, 0>, rgb 2 area_light x, z, 4, 4 adaptive 1 jitter circular orient looks_like { sphere { 0, 0.2 } } }
#default { finish { ambient 0.1 } }
global_settings { assumed_gamma 1 max_trace_level 5 photons { count 1000 } global_photons 1000 caustic_photons 500 global_estimate { count 50 radius 0.5 } final_gather 16 irradiance_cache 0.2 seed 3 }
