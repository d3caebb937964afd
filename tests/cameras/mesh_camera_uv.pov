// mesh_camera distribution 3 (uv baking): each pixel's ray starts where the mesh's uv map puts
// the pixel, along the face normal (the blended vertex normal with smooth). The mesh is a
// sheet bent on a cylinder, its uvs filling [0.06, 0.96] x [0.11, 0.91] (the border stays
// black: no ray; no pixel centre lies on a grid line of the uvs), with a last face that
// repeats the first face's uvs elsewhere (never used: the first face wins).
// Bake=1 (default): rays start 0.05 outside the sheet and run back onto it, baking its
// checker. Bake=0: rays run outwards from 0.3 outside onto a surrounding checkered sphere.
// Smooth=1: the `smooth` keyword.
#version 3.7;
global_settings { assumed_gamma 1.0 }
#ifndef (Bake) #declare Bake = 1; #end
#ifndef (Smooth) #declare Smooth = 0; #end
#declare N = 6;
#declare R = 2;
#macro V(I, J) <R * sin(radians(-60 + 120 * I / N)), -1 + 2 * J / N, -R * cos(radians(-60 + 120 * I / N))> #end
#macro Nrm(I, J) <sin(radians(-60 + 120 * I / N)), 0, -cos(radians(-60 + 120 * I / N))> #end
#declare Sheet = mesh2 {
  vertex_vectors { (N + 1) * (N + 1) + 3
    #local J = 0; #while (J <= N) #local I = 0; #while (I <= N)
      , V(I, J)
    #local I = I + 1; #end #local J = J + 1; #end
    , <0, 0, 10>, <1, 0, 10>, <0, 1, 10>
  }
  normal_vectors { (N + 1) * (N + 1) + 3
    #local J = 0; #while (J <= N) #local I = 0; #while (I <= N)
      , Nrm(I, J)
    #local I = I + 1; #end #local J = J + 1; #end
    , -z, -z, -z
  }
  uv_vectors { (N + 1) * (N + 1)
    #local J = 0; #while (J <= N) #local I = 0; #while (I <= N)
      , <0.06 + 0.9 * I / N, 0.11 + 0.8 * J / N>
    #local I = I + 1; #end #local J = J + 1; #end
  }
  face_indices { 2 * N * N + 1
    #local J = 0; #while (J < N) #local I = 0; #while (I < N)
      #local A = J * (N + 1) + I;
      , <A, A + 1, A + N + 1>, <A + 1, A + N + 2, A + N + 1>
    #local I = I + 1; #end #local J = J + 1; #end
    , <(N + 1) * (N + 1), (N + 1) * (N + 1) + 1, (N + 1) * (N + 1) + 2>
  }
  uv_indices { 2 * N * N + 1
    #local J = 0; #while (J < N) #local I = 0; #while (I < N)
      #local A = J * (N + 1) + I;
      , <A, A + 1, A + N + 1>, <A + 1, A + N + 2, A + N + 1>
    #local I = I + 1; #end #local J = J + 1; #end
    , <0, 1, N + 1>
  }
}
camera {
  mesh_camera { 1 3 mesh { Sheet rotate 10 * x translate <0.2, 0, 0> } #if (Smooth) smooth #end }
  #if (Bake)
    location <0, 0, 0.05> direction <0, 0, -1>
  #else
    location <0, 0, 0.3>
  #end
}
#if (Bake)
  object { Sheet rotate 10 * x translate <0.2, 0, 0>
    pigment { checker rgb <1, 0.9, 0.6> rgb <0.2, 0.3, 0.7> scale 0.23 }
    finish { diffuse 0.8 ambient 0.1 }
  }
  light_source { <-3, 4, -8> rgb 1 }
#else
  sphere { 0, 10 pigment { checker rgb <1, 0.4, 0.2> rgb <0.1, 0.6, 0.3> scale 0.7 }
    finish { emission 1 diffuse 0 } }
#end
