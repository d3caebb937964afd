// bicubic_patch: a saddle-and-bulge net seen from above at an angle, shaded by its exact corner
// normals, with a checker in 3D that shows where each triangle of the subdivision lies.
// Declare Type (0/1), Flat (flatness), Steps (u_steps = v_steps), Scale (object scale).
#version 3.7;
#ifndef (Type) #declare Type = 1; #end
#ifndef (Flat) #declare Flat = 0; #end
#ifndef (Steps) #declare Steps = 3; #end
#ifndef (Scale) #declare Scale = 1; #end
global_settings { assumed_gamma 1 }
camera { location <0, 5, -6> look_at <0, 0, 0> angle 40 }
light_source { <3, 8, -4> rgb 1 }
background { rgb <0.2, 0.3, 0.4> }
bicubic_patch { type Type flatness Flat u_steps Steps v_steps Steps
    <0,0,0>, <1,0.5,0>, <2,-0.5,0>, <3,0,0>,
    <0,1,1>, <1,2,1>,   <2,1.5,1>,  <3,-1,1>,
    <0,-1,2>, <1,1.5,2>, <2,2,2>,   <3,1,2>,
    <0,0,3>, <1,-0.5,3>, <2,0.5,3>, <3,0,3>
    pigment { checker rgb <1,0.3,0.2> rgb 1 scale 0.4 }
    finish { phong 0.6 }
    translate <-1.5, 0, -1.5> scale Scale / 2 rotate 20*y
}
