// warp { repeat }: one tile per variant (plain, offset, flip on the repeat axis, flip across
// it with an offset), over a pattern that varies in x, y and z.
#version 3.7;
global_settings { assumed_gamma 1 }
camera { orthographic location <0, 0, -10> direction z right 4*x up 3*y }
#declare Base = pigment {
  onion scale 0.35 rotate <20, 30, 0> translate <0.1, 0.2, 0.3>
  color_map { [0 rgb <1, 0.2, 0>] [0.35 rgb <0, 0.3, 1>] [0.7 rgb <0.9, 1, 0.2>] [1 rgb <1, 0.2, 0>] }
}
#declare F = finish { ambient 1 diffuse 0 }
box { <-2, 0, 0>, <0, 1.5, 1> pigment { Base warp { repeat x * 0.7 } } finish { F } }
box { <0, 0, 0>, <2, 1.5, 1> pigment { Base warp { repeat y * 0.5 offset <0.1, 0, 0.2> } } finish { F } }
box { <-2, -1.5, 0>, <0, 0, 1> pigment { Base warp { repeat x * 0.6 flip x } } finish { F } }
box { <0, -1.5, 0>, <2, 0, 1> pigment { Base warp { repeat -y * 0.4 flip <1, 1, 0> offset x * 0.3 } } finish { F } }
