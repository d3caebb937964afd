// slope inside nested texture_maps: POV-Ray keeps one perturbed normal per intersection, so a
// slope texture_map shaded as the second entry of an outer map chooses its entries by the
// normal the first entry's bumps left behind. Declare Outer=0: the slope map alone (the surface
// normal); 1: an outer gradient map whose two entries are both the slope map.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 0, -4> look_at 0 angle 40 }
light_source { <200, 200, -200>, color rgb 1.2 }
#ifndef (Outer) #declare Outer = 1; #end
#declare Vege = texture { pigment { color <0.2, 0.5, 0.1> } normal { bumps 0.5 scale 0.05 } }
#declare Soil = texture { pigment { color <0.77, 0.6, 0.35> } }
#declare Rock = texture { pigment { color <0.3, 0.3, 0.3> } }
#declare SlopeTex = texture {
  slope { -y * 3, 0, 0.5 }
  texture_map { [0.45 Vege] [0.55 Soil] [0.65 Soil] [0.65 Rock] }
}
sphere { 0, 1
  #if (Outer)
    texture { gradient y texture_map { [0 SlopeTex] [1 SlopeTex] } }
  #else
    texture { SlopeTex }
  #end
}
