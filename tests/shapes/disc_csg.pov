// A disc in CSG, as POV-Ray treats it: its inside is the half-space behind it (opposite the
// normal) whatever its radius, and an intersection is bounded by the overlap of its members'
// boxes, the disc's being flat: Kind 0, a sphere cut by a disc of radius 0.5, shows the dome
// only where rays meet the disc's box; 1 a ringed disc off centre; 2 a sphere minus a tilted
// disc (the half-space removed, the sphere's box kept); 3 a glass dome (sphere cut by a disc
// below it): rays reflected totally off the flat base from inside reach the dome's top only
// because the disc's box is POV-Ray's, 0.001 deep on each side; 4 a box cut by a tilted disc:
// what shows is the extent of POV-Ray's disc box (a square in the disc's frame), not the
// disc's tightest box.
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 2, -4> look_at 0 angle 40 }
light_source { <-3, 5, -4> rgb 1 }
background { rgb 0.2 }
#ifndef (Kind) #declare Kind = 0; #end
#switch (Kind)
  #case (0) intersection { sphere { 0, 1 } disc { 0, -y, 0.5 } pigment { rgb <1, 0.6, 0.3> } } #break
  #case (1) intersection { sphere { 0, 1 } disc { <0.2, 0.1, 0>, y, 2, 0.3 } pigment { rgb <1, 0.6, 0.3> } } #break
  #case (2) difference { sphere { 0, 1 } disc { 0, <0.3, 1, 0>, 0.5 } pigment { rgb <1, 0.6, 0.3> } } #break
  #case (3)
    plane { y, -0.6 pigment { checker rgb <0.6, 0.2, 0.1> rgb <0.3, 0.6, 0.2> scale 0.4 } }
    intersection { sphere { -0.5 * y, 1 } disc { 0, -y, 1.01 } translate -0.3 * y
      pigment { rgbf <0.8, 1, 0.95, 0.9> } finish { ambient 0.1 diffuse 0.1 phong 1 } interior { ior 1.5 } }
    #break
  #case (4) intersection { box { -3, 3 } disc { 0, <1, 2, 3>, 0.8 } pigment { rgb <1, 0.6, 0.3> } } #break
#end
