#declare T = transform { rotate <10, 20, 30> scale 2 translate <1, 2, 3> }
sphere { 0, 1 transform { T inverse } matrix <1,0,0, 0,1,0, 0,0,1, 0,0,0> }
camera { perspective location <0, 0, -10> direction z right x up y look_at <0, 0, 0> rotate y*10 translate 1 }
light_source { 0, rgb 1 translate <0, 5, 0> }
