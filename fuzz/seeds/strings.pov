#declare A = "Hello";
#declare B = concat(A, " ", strupr("world"), chr(33), str(3.14159, 8, 3), vstr(3, <1, 2, 3>, ", ", 0, 1));
#declare C = substr(B, 2, 3);
#declare N = strlen(B) + val("3.5e2") + asc("A") + strcmp("abc", "abd") + file_exists("colors.inc");
#declare D = strlwr(concat(datetime(1.5, "%Y/%m/%d"), datetime(0)));
#include concat("col", "ors.inc")
#warning concat("N = ", str(N, 0, -1), " ", C)
#debug D
#if (strcmp(C, "ell") = 0) sphere { 0, 1 pigment { Red } } #end
light_source { <0, 5, 0>, rgb 1 }
