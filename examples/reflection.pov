// Reflection: three mirror balls of different reflectivity on a checkered floor, reflecting
// each other and the floor (recursive reflection, max_trace_level).
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 6 }

camera {
  location <0, 2.2, -6>
  look_at  <0, 0.8, 0>
  right x*image_width/image_height
  angle 50
}

light_source { <-6, 9, -7> color rgb 1 }
background { color rgb <0.15, 0.2, 0.35> }

plane {
  y, 0
  pigment { checker color rgb 0.9 color rgb 0.1 }
  finish { ambient 0.05 diffuse 0.8 }
}

sphere { <-1.6, 0.8, 0>, 0.8
  pigment { color rgb <0.8, 0.2, 0.2> }
  finish { ambient 0 diffuse 0.6 specular 0.6 roughness 0.02 reflection 0.3 }
}
sphere { <0, 1, 0.8>, 1
  pigment { color rgb 0.02 }
  finish { ambient 0 diffuse 0.1 specular 0.9 roughness 0.005 reflection 0.95 }
}
sphere { <1.6, 0.7, -0.2>, 0.7
  pigment { color rgb <0.9, 0.75, 0.3> }
  finish { ambient 0 diffuse 0.3 specular 0.8 roughness 0.01 reflection { 0.6 metallic } metallic }
}
