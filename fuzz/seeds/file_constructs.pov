// Every construct that names a file, as a seed: served from memory or refused, never opened.
#include "colors.inc"
#fopen F "data.txt" write
#write (F, 1, ",", <1, 2, 3>, ",", "\"s\"")
#fclose F
#fopen F "data.txt" read
#while (defined(F)) #read (F, A) #end
#fopen G "data.txt" append
#write (G, 2)
#fclose G
#if (file_exists("/etc/passwd")) #declare Seen = 1; #end
#include "../../etc/passwd"
#fopen H "/etc/hostname" read
sphere { 0, 1 pigment { image_map { png "map.png" once interpolate 2 } } normal { bump_map { png "../bump.png" } } }
height_field { png "/dev/urandom" }
mesh { obj "m.obj" }
text { ttf "timrom.ttf" "A" 1, 0 }
box { 0, 1 pigment { density_file df3 "d.df3" interpolate 1 } }
#include "/dev/urandom"
light_source { 5*y, White }
