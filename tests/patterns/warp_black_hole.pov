// warp { black_hole }: plain; falloff and strength; inverse, repeated with turbulence (each
// cell's centre moved at random), the centre and repeat raised by POV-Ray to fit the cell;
// type 1 (no effect). Over a gradient with a periodic colour map (continuous where the
// pattern wraps).
#version 3.7;
global_settings { assumed_gamma 1 }
camera { orthographic location <0, 0, -10> direction z right 4*x up 3*y }
#declare Base = pigment {
  gradient x scale 0.3 rotate <0, 30, 40>
  color_map { [0 rgb <1, 0.2, 0>] [0.35 rgb <0, 0.3, 1>] [0.7 rgb <0.9, 1, 0.2>] [1 rgb <1, 0.2, 0>] }
}
#declare F = finish { ambient 1 diffuse 0 }
box { <-2, 0, 0>, <0, 1.5, 1> pigment { Base warp { black_hole <-1, 0.75, 0>, 0.7 } } finish { F } }
box { <0, 0, 0>, <2, 1.5, 1> pigment { Base warp { black_hole <1, 0.75, 0>, 0.8 falloff 0.7 strength 1.6 } } finish { F } }
box { <-2, -1.5, 0>, <0, 0, 1> pigment { Base warp { black_hole <0.1, 0.2, 0>, 0.3 repeat <0.7, 0.5, 0> turbulence <0.2, 0.1, 0> inverse falloff 3 } } finish { F } }
box { <0, -1.5, 0>, <2, 0, 1> pigment { Base warp { black_hole <1, -0.75, 0>, 0.7 type 1 } } finish { F } }
