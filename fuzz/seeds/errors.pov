/* nested /* comment */ still */
sphere { <0, 0, 0>, -1 }
box { 0, 1 matrix < 0,0,0, 0,0,0, 0,0,0, 0,0,0 > }
#declare X = 1 / 0;
