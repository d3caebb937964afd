// finish irid with turbulence: the film thickness varies with the turbulence at the world
// point (5 octaves, omega 0.5, lambda 2), here on a plane moved off the origin.
#version 3.7;
global_settings { assumed_gamma 1 }
camera { orthographic location <0, 0, -10> direction z right 4*x up 3*y }
light_source { <0, 0, -1000> rgb 1 parallel point_at 0 }
plane { -z, 0
  pigment { rgb <0.6, 0.5, 0.4> }
  finish { ambient 0.1 diffuse 0.8 irid { 0.35 thickness 0.4 turbulence 0.6 } }
  translate <0.3, 0.2, 0.37>
}
