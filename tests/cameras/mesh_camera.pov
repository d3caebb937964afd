// mesh_camera, distribution 0 with two rays per pixel (two meshes a third of a pixel apart,
// averaged), faces one per pixel in POV-Ray's order (row by row from the top; the first two
// image rows share the first row of faces), rays starting 0.5 behind the faces.
#version 3.7;
global_settings { assumed_gamma 1.0 }
#declare W = 48; #declare H = 36;
#declare Grid = mesh {
  #local J = 0;
  #while (J < H)
    #local I = 0;
    #while (I < W)
      #local C = <(I + 0.5) / W - 0.5, 0.5 - (J + 0.5) / H, 0> * <4, 3, 1>;
      triangle { C, C + <0, 0.02, 0>, C + <0.02, 0, 0> }  // facing +z
      #local I = I + 1;
    #end
    #local J = J + 1;
  #end
}
camera {
  mesh_camera { 2 0 mesh { Grid } mesh { Grid translate <4 / W / 3, 0, 0> } }
  location <0, 0, -0.5>
}
light_source { <-3, 4, -5> rgb 1 }
plane { z, 4 pigment { checker rgb <1, 0.9, 0.7> rgb <0.2, 0.3, 0.6> scale 0.5 } }
sphere { <0.5, 0, 2>, 1 pigment { rgb <1, 0.3, 0.2> } finish { phong 0.6 } }
box { <-2, -1, 1>, <-1, 0.2, 2> pigment { rgb <0.3, 0.9, 0.4> } }
