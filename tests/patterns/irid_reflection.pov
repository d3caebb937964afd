// irid tints reflections as well as lights (POV's film, with the mirror direction as the light's).
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0,0,-4> look_at 0 angle 45 }
light_source { <-10, 10, -10> rgb 1 }
plane { y, -1 pigment { checker rgb 1 rgb <0.2,0.4,0.8> } finish { ambient 1 diffuse 0 } }
sphere { 0, 1 pigment { rgb 0.8 } finish { diffuse 0.6 reflection 0.5 irid { 0.65 thickness 0.8 } } }
