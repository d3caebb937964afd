// Render benchmark for bicubic_patch (bench/render_vs_povray.sh build/lumen 2 3
// bench/bicubic_patch.pov): a 6 x 6 quilt of curved patches, type 0 and type 1, flatness 0
// at 4 steps and adaptive at 0.02, with shadows and a reflective floor.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 8, -12> look_at <0, 0, 0> angle 50 }
light_source { <-8, 14, -10> rgb 1 }
background { rgb <0.15, 0.18, 0.25> }
plane { y, -0.5 pigment { checker rgb 0.8 rgb 0.5 } finish { reflection 0.2 } }
#macro Patch(T, F, S)
  bicubic_patch { type T flatness F u_steps S v_steps S
    <0,0,0>, <1,0.5,0>, <2,-0.5,0>, <3,0,0>, <0,1,1>, <1,2,1>, <2,1.5,1>, <3,-1,1>,
    <0,-1,2>, <1,1.5,2>, <2,2,2>, <3,1,2>, <0,0,3>, <1,-0.5,3>, <2,0.5,3>, <3,0,3>
    translate <-1.5, 0, -1.5> scale 0.45 }
#end
#for (I, 0, 5)
  #for (J, 0, 5)
    object { Patch(mod(I + J, 2), (J < 3 ? 0 : 0.02), 4)
             rotate (I * 6 + J) * 17 * y translate <(I - 2.5) * 1.6, 0, (J - 2.5) * 1.6>
             pigment { rgb <0.9, 0.5 + I / 12, 0.3 + J / 10> } finish { phong 0.5 } }
  #end
#end
