// Ground fog with turbulence under global_settings { noise_generator 3 }.
#version 3.7;
global_settings { assumed_gamma 1 noise_generator 3 }
camera { location <0, 1, -6> look_at <0, 0.5, 0> }
plane { y, -1 pigment { checker rgb <0.2, 0.3, 0.5> rgb <0.8, 0.7, 0.4> } finish { ambient 1 diffuse 0 } }
sphere { <-0.5, 0.3, 2>, 1 pigment { rgb <0.1, 0.6, 0.2> } finish { ambient 1 diffuse 0 } }
fog { fog_type 2 fog_offset 0.2 fog_alt 0.6 distance 3 color rgb <0.9, 0.9, 0.95>
      turbulence 0.8 turb_depth 0.7 }
