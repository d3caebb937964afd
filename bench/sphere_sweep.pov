// Render benchmark for sphere_sweep (bench/render_vs_povray.sh build/lumen 2 3
// bench/sphere_sweep.pov): a 4 x 3 grid of sweeps, alternately b_spline coils, cubic_spline
// waves and linear_spline zigzags of 40 spheres each, with shadows and a reflective floor.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 7, -14> look_at <0, 0.5, 0> angle 50 }
light_source { <-10, 20, -12> rgb 1 }
background { rgb <0.15, 0.18, 0.25> }
plane { y, -1 pigment { checker rgb 0.8 rgb 0.5 } finish { reflection 0.2 } }
#declare S = seed(11);
#for (i, 0, 3) #for (j, 0, 2)
  #declare Kind = mod(i + j, 3);
  #declare Phase = 2 * pi * rand(S);
  sphere_sweep {
    #switch (Kind)
      #case (0) b_spline #break
      #case (1) cubic_spline #break
      #else linear_spline
    #end
    40,
    #for (k, 0, 39)
      #declare A = Phase + k * 0.55;
      #declare H = k / 39;
      #if (Kind = 0)
        <0.9 * cos(A), 3 * H - 0.6, 0.9 * sin(A)>, 0.12 + 0.08 * rand(S)
      #elseif (Kind = 1)
        <1.6 * (H - 0.5), 0.8 * sin(3 * A) + 0.8, 0.6 * cos(2 * A)>, 0.15 + 0.05 * sin(A)
      #else
        <1.5 * (H - 0.5), 2.6 * H - 0.6 + 0.3 * rand(S), 0.5 * (rand(S) - 0.5)>, 0.1 + 0.06 * rand(S)
      #end
    #end
    tolerance 1e-3
    texture { pigment { rgb <0.3 + 0.6 * rand(S), 0.3 + 0.5 * rand(S), 0.4 + 0.5 * rand(S)> }
              finish { phong 0.6 } }
    translate <(i - 1.5) * 3.2, 0, (j - 1) * 3>
  }
#end #end
