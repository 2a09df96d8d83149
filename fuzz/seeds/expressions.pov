#declare A = (1 + 2) * 3 / 4 - -5;
#declare B = <1, 2, 3> * 2 + <0.5, 0.5, 0.5>.x;
#declare C = (A > 2 ? vlength(B) : vdot(B, B)) + select(-1, 1, 2, 3);
#declare D = atan2(1, 2) + pow(2, 10) + sqrt(2) + max(1, 2, 3) + min(4, 5) + int(2.7) + div(7, 2);
#declare E = vrotate(x, <0, 90, 0>) + vcross(x, y) + vnormalize(<1, 1, 0>);
#declare F = !(A = C) & (A != 1) | (B.y <= 3);
sphere { E, abs(-1) + F translate <C, D, 0> rotate 45*y scale <1, 2, 1> }
camera { location <0, 1, -5> look_at 0 angle 60 right x*4/3 up y sky y }
