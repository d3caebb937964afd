// The SDL as a language: a #macro that builds one object, an array of colours filled with a
// #for loop, and a #while loop placing a spiral of spheres read back from the array.
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera {
  location <0, 7, -9>
  look_at  <0, 0.8, 0>
  right x*image_width/image_height
  angle 45
}

light_source { <-6, 10, -8> color rgb 1 }
light_source { < 6, 5, -4> color rgb 0.3 }
background { color rgb <0.1, 0.1, 0.15> }

plane { y, 0 pigment { color rgb 0.6 } finish { ambient 0.1 diffuse 0.8 } }

#macro Ball(Pos, Radius, Colour)
  sphere { Pos + y*Radius, Radius
    pigment { color Colour }
    finish { ambient 0.1 diffuse 0.7 specular 0.5 roughness 0.02 }
  }
#end

#declare N = 24;
#declare Colours = array[N];
#for (I, 0, N - 1)
  #declare T = I / (N - 1);
  #declare Colours[I] = rgb <T, 0.3 + 0.5*sin(T*pi), 1 - T>;
#end

#declare Spiral = union {
  #declare I = 0;
  #while (I < N)
    #declare A = I * 30;
    #declare R = 0.8 + I * 0.13;
    Ball(<R*cos(radians(A)), 0, R*sin(radians(A))>, 0.15 + I*0.012, Colours[I])
    #declare I = I + 1;
  #end
}
object { Spiral }

// a small pyramid of boxes from nested loops
#for (L, 0, 2)
  #for (X, 0, 2 - L)
    box { <0, 0, 0>, <0.4, 0.4, 0.4>
      translate <X*0.45 + L*0.225 - 0.45, L*0.4, -0.2>
      pigment { color rgb <1, 0.9 - L*0.3, 0.2> }
    }
  #end
#end
