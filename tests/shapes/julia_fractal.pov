// julia_fractal: POV-Ray's march (steps of the distance estimate, at least 1/precision) and
// bisection, seen on thin features, with the Jacobian normal under a light from the side.
// Declare Kind: 0 quaternion sqr, 1 quaternion cube, 2 hypercomplex sqr, 3 hypercomplex
// function (Fn: 0 exp, 1 sin, 2 reciprocal, 3 pwr(2, 0.3), 4 cos), 5 CSG (the far half cut).
// Declare Iter (max_iteration), Prec (precision), Slice (0: default, 1: tilted slice).
#version 3.7;
#ifndef (Kind) #declare Kind = 0; #end
#ifndef (Fn) #declare Fn = 0; #end
#ifndef (Iter) #declare Iter = 8; #end
#ifndef (Prec) #declare Prec = 20; #end
#ifndef (Slice) #declare Slice = 0; #end
global_settings { assumed_gamma 1 }
camera { location <0, 0.8, -5> look_at <0, 0, 0> angle 45 }
light_source { <-4, 6, -5> rgb 1 }
light_source { <5, -2, -3> rgb <0.3, 0.35, 0.4> }
background { rgb <0.1, 0.15, 0.2> }

#macro Fractal()
  julia_fractal {
    #switch (Kind)
      #case (1) <-0.033, -0.6, -0.93, -0.025> quaternion cube #break
      #case (2) <0.2, 0.1, 0.59, -0.2> hypercomplex sqr #break
      #case (3)
        #switch (Fn)
          #case (0) <0.3, 0.4, 0.2, 0> hypercomplex exp #break
          #case (1) <1, 0.1, 0, 0> hypercomplex sin #break
          #case (2) <-0.4, 0.3, 0.2, 0> hypercomplex reciprocal #break
          #case (3) <-0.3, 0.5, 0.1, 0> hypercomplex pwr(2, 0.3) #break
          #else <0.5, 0.2, 0.1, 0> hypercomplex cos
        #end
        #break
      #else <-0.083, 0.0, -0.83, -0.025> quaternion sqr
    #end
    max_iteration Iter precision Prec
    #if (Slice) slice <0.2, 0.3, 0.1, 1>, 0.1 #end
  }
#end

#if (Kind = 5)
  // The far half cut away: plane hits count where inside the fractal, fractal hits where
  // in front of the plane. (Seen from the cut side, POV-Ray's further crossings of a fractal
  // in CSG are unreliable: its hit list repeats the first depth at points further in.)
  intersection {
    object { Fractal() rotate <-20, 30, 0> }
    plane { z, 0.1 }
    pigment { rgb <1, 0.7, 0.4> }
    finish { phong 0.5 }
    scale 1.2
  }
#else
  object { Fractal()
    pigment { rgb <0.9, 0.8, 0.6> }
    finish { phong 0.4 specular 0.2 }
    rotate <-20, 30, 0>
    scale 1.2
  }
#end
