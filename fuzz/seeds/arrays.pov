#version 3.7;
// Arrays: sizes, nested initialisers, elements of several types, A[i] as identifiers.
#declare A = array[2][3] { {1, 2, 3}, {4, 5, 6} };
#declare A[1][2] = A[0][0] + dimension_size(A, 2) * dimensions(A);
#declare P = array[2] { pigment { rgb x }, pigment { rgb y } };
#declare O = array[3];
#for (I, 0, 2) #declare O[I] = sphere { <I, A[1][I], 0>, 0.25 }; #end
#declare Mix = array mixed[2] { 1, "two" };
#declare Copy = O;
#macro Count(Arr) #local C = 0; #for (I, 0, dimension_size(Arr, 1) - 1) #ifdef (Arr[I]) #local C = C + 1; #end #end C #end
#if (Count(Copy) = 3) object { O[1] pigment { P[0] } } #end
light_source { <0, 5, -5>, rgb 1 }
