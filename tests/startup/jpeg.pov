// A height field from a JPEG file: read by lumen's own JPEG reader, without OpenImageIO.
#version 3.7;
camera { location <0.5, 2, -1> look_at <0.5, 0, 0.5> }
light_source { <2, 5, -3> rgb 1 }
height_field { jpeg "/usr/share/povray-3.7/scenes/textures/patterns/slopemt_dat_36.jpg"
  pigment { rgb 0.8 } }
