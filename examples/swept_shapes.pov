// The swept shapes: a lathe vase (cubic_spline), a sor goblet, a bezier prism star with a
// conic_sweep spire beside it, and a linear prism arch, in glass, metal and stone.
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 8 }

camera {
  location <0, 3.2, -8>
  look_at  <0, 1.2, 0>
  right x*image_width/image_height
  angle 50
}
light_source { <-6, 11, -8> color rgb 1 }
light_source { <8, 6, -3> color rgb 0.3 shadowless }
background { color rgb <0.55, 0.62, 0.75> }

plane { y, 0
  pigment { checker color rgb 0.85 color rgb 0.55 }
  finish { diffuse 0.8 reflection 0.1 }
}

// A vase turned on a lathe: cubic spline (the first and last points steer the ends).
lathe { cubic_spline 9,
  <0.0, -0.2>, <0.45, 0>, <0.7, 0.4>, <0.55, 1.1>, <0.3, 1.6>, <0.35, 2.0>, <0.5, 2.3>,
  <0.45, 2.35>, <0.3, 2.5>
  pigment { color rgb <0.2, 0.45, 0.8> }
  finish { phong 0.8 phong_size 90 reflection 0.12 }
  translate <-2.6, 0, 0.6>
}

// A goblet: surface of revolution, open at the top, with a cap at the foot.
sor { 8,
  <0.0, -0.1>, <0.6, 0.0>, <0.15, 0.2>, <0.08, 0.9>, <0.3, 1.1>, <0.55, 1.5>, <0.6, 1.9>,
  <0.62, 2.1>
  open
  pigment { color rgbf <0.95, 0.9, 0.7, 0.85> }
  finish { specular 0.6 reflection 0.1 }
  interior { ior 1.45 }
  translate <-0.6, 0, 1.2>
}

// A five-pointed star, bezier segments, extruded.
#declare R1 = 0.9; #declare R2 = 0.38;
prism { bezier_spline 0, 0.35, 40
  #for (I, 0, 9)
    #local A0 = I * 36; #local A1 = (I + 1) * 36;
    #local Ra = (mod(I, 2) = 0 ? R1 : R2); #local Rb = (mod(I, 2) = 0 ? R2 : R1);
    , <Ra * sin(radians(A0)), Ra * cos(radians(A0))>
    , <Ra * sin(radians(A0 + 8)), Ra * cos(radians(A0 + 8))>
    , <Rb * sin(radians(A1 - 8)), Rb * cos(radians(A1 - 8))>
    , <Rb * sin(radians(A1)), Rb * cos(radians(A1))>
  #end
  pigment { color rgb <1, 0.7, 0.15> }
  finish { phong 0.9 metallic reflection 0.25 }
  rotate <-70, 0, 0>
  translate <1.3, 1.0, -0.4>
}

// A spire: conic sweep of a square.
prism { conic_sweep linear_spline 0.0, 1.0, 5,
  <0.35, 0.35>, <-0.35, 0.35>, <-0.35, -0.35>, <0.35, -0.35>, <0.35, 0.35>
  pigment { color rgb <0.75, 0.3, 0.25> }
  finish { specular 0.4 }
  rotate 180 * x
  scale <1, 2.2, 1>
  translate <2.9, 2.2, 1.3>
}

// An arch: a linear prism, its outline with a notch.
prism { linear_sweep linear_spline -0.25, 0.25, 9,
  <-1.4, 0>, <-1.4, 1.6>, <1.4, 1.6>, <1.4, 0>, <0.9, 0>, <0.9, 1.0>, <-0.9, 1.0>, <-0.9, 0>,
  <-1.4, 0>
  pigment { granite color_map { [0 rgb 0.75] [1 rgb 0.45] } scale 0.8 }
  finish { diffuse 0.9 }
  rotate -90 * x
  translate <0.4, 0, 3.2>
}
