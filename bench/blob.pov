// Render benchmark for blob (bench/render_vs_povray.sh build/lumen 2 3 bench/blob.pov): a
// blob of 1000 components (a jittered 10 x 10 x 10 lattice of spheres and 100 cylinders,
// some negative), with shadows and a reflective floor.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 9, -16> look_at <0, 0, 0> angle 50 }
light_source { <-10, 20, -12> rgb 1 }
background { rgb <0.15, 0.18, 0.25> }
plane { y, -5.5 pigment { checker rgb 0.8 rgb 0.5 } finish { reflection 0.2 } }
#declare S = seed(7);
blob { threshold 0.6
  #for (i, 0, 9) #for (j, 0, 8) #for (k, 0, 9)
    sphere { <i - 4.5 + 0.6 * rand(S), j - 4 + 0.6 * rand(S), k - 4.5 + 0.6 * rand(S)>,
             0.55 + 0.4 * rand(S), (rand(S) < 0.15 ? -1 : 1) }
  #end #end #end
  #for (i, 0, 99)
    cylinder { <rand(S) * 10 - 5, rand(S) * 10 - 5, rand(S) * 10 - 5>,
               <rand(S) * 10 - 5, rand(S) * 10 - 5, rand(S) * 10 - 5>, 0.4, 1 }
  #end
  texture { pigment { rgb <0.9, 0.5, 0.3> } finish { phong 0.6 } }
  rotate 20*y }
