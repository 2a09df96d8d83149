#version 3.7;
// #switch with fall-through, #range, #else, #break; #for with a step; #break out of loops.
#for (I, 0, 6, 2)
  #switch (I)
    #case (0)
    #case (2) sphere { <I, 0, 0>, 0.3 } #break
    #range (3, 4.5) box { <I, 0, 0>, <I + 0.5, 0.5, 0.5> }
    #else #if (I > 5) #break #end plane { y, -1 }
  #end
#end
#declare N = 0;
#while (1) #declare N = N + 1; #if (N > 3) #break #end #end
#for (J, 3, 1, -1) #declare N = N + J; #end
light_source { <0, 5, -5>, rgb 1 }
