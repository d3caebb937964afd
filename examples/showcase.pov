// lumen showcase: the core of the scene language (camera, lights, sphere, plane, box, solid
// colours and simple finishes). `make render` draws it to build/showcase.png.
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera {
  location <0, 2.2, -6>
  look_at  <0, 0.8, 0>
  angle 50
}

light_source { <-6, 9, -7> color rgb <1.0, 0.96, 0.9> }
light_source { <7, 5, -3> color rgb <0.35, 0.4, 0.5> }

background { color rgb <0.55, 0.7, 0.9> }

// Ground
plane {
  y, 0
  pigment { color rgb <0.75, 0.72, 0.65> }
  finish { ambient 0.1 diffuse 0.8 }
}

// A shiny red ball
sphere {
  <-1.1, 1, 0.3>, 1
  pigment { color rgb <0.85, 0.12, 0.1> }
  finish { ambient 0.1 diffuse 0.7 phong 0.8 phong_size 60 }
}

// A blue box, turned a little
box {
  <-0.7, 0, -0.7>, <0.7, 1.4, 0.7>
  rotate y * 30
  translate <1.5, 0, 0.8>
  pigment { color rgb <0.2, 0.35, 0.85> }
  finish { ambient 0.1 diffuse 0.75 phong 0.4 phong_size 25 }
}

// A small green ball in front
sphere {
  <0.45, 0.45, -1.3>, 0.45
  pigment { color rgb <0.2, 0.7, 0.25> }
  finish { ambient 0.1 diffuse 0.7 phong 0.6 phong_size 40 }
}
