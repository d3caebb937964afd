// mesh_camera distribution 2 (meshes side by side, each W / 2 columns, POV-Ray's face
// numbering) and 1 (meshes joined), with the rays reversed by a negative direction.z.
#version 3.7;
global_settings { assumed_gamma 1.0 }
#declare W = 48; #declare H = 36;
#macro Grid(Width, Shift)
mesh {
  #local J = 0;
  #while (J < H)
    #local I = 0;
    #while (I < Width)
      #local C = <(I + 0.5) / Width - 0.5 + Shift, 0.5 - (J + 0.5) / H, 0> * <2, 3, 1>;
      triangle { C, C + <0.02, 0, 0>, C + <0, 0.02, 0> }  // facing -z: reversed below
      #local I = I + 1;
    #end
    #local J = J + 1;
  #end
}
#end
camera {
  #ifndef (Joined)
    mesh_camera { 1 2 Grid(W / 2, -0.5) Grid(W / 2, 0.5) }
  #else
    mesh_camera { 1 1 Grid(W, 0) }
  #end
  direction <0, 0, -1>
}
light_source { <-3, 4, -5> rgb 1 }
plane { z, 4 pigment { checker rgb <1, 0.9, 0.7> rgb <0.2, 0.3, 0.6> scale 0.5 } }
sphere { <0.5, 0, 2>, 1 pigment { rgb <1, 0.3, 0.2> } finish { phong 0.6 } }
