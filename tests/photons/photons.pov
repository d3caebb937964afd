// Photon mapping against POV-Ray: caustics from targets of each kind. Declare Kind:
//  0 a glass sphere under a parallel light (spacing, given radius)
//  1 the same under a point light, photons by count (automatic radius)
//  2 a mirror's caustic on a wall (a reflection-only target casts its ordinary shadow)
//  3 a receiver with collect off: the glass casts its filtered shadow, no caustic
//  4 a tinted pass_through pane between the light and the glass
//  5 a spotlight with fade_power, a coloured glass union with fade, phong on the floor
//  6 refraction on at the glass and off at the light: nothing shot, a filtered shadow
//  7 an area light shooting from its grid (photons { area_light })
// File 1 saves the map to photons.ph and File 2 loads it in place of shooting (tests/photons:
// the two renders are the same image).
#ifndef (Kind) #declare Kind = 0; #end
#ifndef (File) #declare File = 0; #end
#version 3.7;
global_settings {
  assumed_gamma 1
  photons {
    #switch (Kind)
    #case (1) count 20000 #break
    #case (7) spacing 0.02 radius 0.08 #break
    #else spacing 0.01 radius 0.06
    #end
    #if (File = 1) save_file "photons.ph" #end
    #if (File = 2) load_file "photons.ph" #end
  }
}
camera { location <0, 3, -4> look_at <0, 0.3, 0> angle 45 }
plane { y, 0 pigment { checker rgb 0.9 rgb 0.7 scale 0.5 }
  #if (Kind = 3) photons { collect off } #end
  #if (Kind = 5) finish { phong 0.5 phong_size 20 } #end }
#declare Glass = material { texture { pigment { rgbt 1 } finish { ambient 0 diffuse 0 } }
                            interior { ior 1.5 } }
#switch (Kind)
#case (0)
#case (3)
  light_source { <-6, 8, 2> rgb 0.8 parallel point_at 0 }
  sphere { <0, 0.5, 0>, 0.5 material { Glass } photons { target refraction on reflection on collect off } }
  #break
#case (1)
  light_source { <-3, 4, 1> rgb 0.6 photons { refraction on } }
  sphere { <0, 0.5, 0>, 0.5 material { Glass } photons { target collect off } }
  #break
#case (2)
  light_source { <-2, 4, -3> rgb 0.7 }
  plane { z, 1.5 pigment { rgb 0.8 } }
  box { <-0.5, 0, -1.5>, <0.5, 1, -1.45> rotate -y * 35 pigment { rgb <0.9, 0.9, 1> }
        finish { reflection 0.8 diffuse 0.1 } photons { target reflection on } }
  #break
#case (4)
  light_source { <-3, 6, 1> rgb 0.8 photons { refraction on } }
  box { <-1.5, 2.5, -1.5>, <1.5, 2.52, 1.5> pigment { rgbf <1, 0.6, 0.3, 0.8> }
        photons { pass_through } }
  sphere { <0, 0.5, 0>, 0.5 material { Glass } photons { target collect off } }
  #break
#case (5)
  light_source { <-2, 5, -1> rgb 1.2 spotlight point_at <0, 0.4, 0> radius 14 falloff 20
                 fade_distance 4 fade_power 2 photons { refraction on reflection on } }
  union {
    sphere { <-0.5, 0.45, 0>, 0.45 }
    cylinder { <0.3, 0.01, 0.1>, <0.3, 0.8, 0.1>, 0.3 }
    pigment { rgbf <0.6, 0.9, 1, 0.9> } finish { ambient 0 diffuse 0.1 }
    interior { ior 1.33 fade_distance 1 fade_power 1001 fade_colour rgb <0.3, 0.8, 1> }
    photons { target collect off }
  }
  #break
#case (6)
  light_source { <-3, 4, 1> rgb 0.6 photons { refraction off } }
  sphere { <0, 0.5, 0>, 0.5 material { Glass } photons { target refraction on collect off } }
  #break
#case (7)
  light_source { <-3, 5, 1> rgb 0.7 area_light x * 0.6, z * 0.6, 3, 3
                 photons { refraction on area_light } }
  sphere { <0, 0.5, 0>, 0.5 material { Glass } photons { target collect off } }
  #break
#end
