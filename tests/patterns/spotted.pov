// spotted through a three-entry colour map
#version 3.7;
global_settings { assumed_gamma 1  }
camera { orthographic location <0, 0, -10> direction z right 4*x up 3*y }
plane { z, 0.37
  pigment { spotted scale 0.2 color_map { [0 rgb <0.1, 0.2, 0.6>] [0.5 rgb <0.9, 0.8, 0.2>] [1 rgb <0.2, 0.6, 0.1>] } }
  finish { ambient 1 diffuse 0 }
}
