#version 3.7;
#declare N = 0;
#while (N < 3)
  #if (mod(N, 2) = 0) sphere { <N, 0, 0>, 0.5 } #elseif (N > 5) box { -1, 1 } #else plane { y, -1 } #end
  #declare N = N + 1;
#end
#ifdef (photon_version) global_settings { width 32 height 24 render_mode pm } #end
#ifndef (Missing) #warning "no Missing" #end
#undef N
light_source { <0, 5, 0>, rgb 1 }
