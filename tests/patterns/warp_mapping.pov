// The mapping warps: cylindrical (default; orientation y with dist_exp 1), spherical
// (dist_exp 0.5), toroidal (major_radius 0.8, orientation x), planar (y, 0.2) and cubic,
// each over a pattern that varies in x, y and z, viewed through a rotation so the warps see
// all three coordinates.
#version 3.7;
global_settings { assumed_gamma 1 }
camera { orthographic location <0, 0, -10> direction z right 4*x up 3*y }
#declare Base = pigment {
  onion scale 0.35 translate <0.4, 0.25, 0.3>
  color_map { [0 rgb <1, 0.2, 0>] [0.35 rgb <0, 0.3, 1>] [0.7 rgb <0.9, 1, 0.2>] [1 rgb <1, 0.2, 0>] }
}
#declare F = finish { ambient 1 diffuse 0 }
#declare View = transform { rotate <50, 20, 0> }
box { <-2, 0.5, 0>, <-0.67, 1.5, 1> pigment { Base warp { cylindrical } transform { View } } finish { F } }
box { <-0.67, 0.5, 0>, <0.67, 1.5, 1> pigment { Base warp { cylindrical orientation y dist_exp 1 } transform { View } translate x * 0.3 } finish { F } }
box { <0.67, 0.5, 0>, <2, 1.5, 1> pigment { Base warp { spherical dist_exp 0.5 } transform { View } translate x * 1.3 } finish { F } }
box { <-2, -0.5, 0>, <-0.67, 0.5, 1> pigment { Base warp { toroidal major_radius 0.8 orientation x } transform { View } translate -x * 1.3 } finish { F } }
box { <-0.67, -0.5, 0>, <0.67, 0.5, 1> pigment { Base warp { planar y, 0.2 } transform { View } } finish { F } }
box { <0.67, -0.5, 0>, <2, 0.5, 1> pigment { Base warp { cubic } transform { View } translate x * 1.3 } finish { F } }
box { <-2, -1.5, 0>, <0, -0.5, 1> pigment { Base warp { spherical orientation <1, 1, 0> } transform { View } translate <-1, -1, 0> } finish { F } }
box { <0, -1.5, 0>, <2, -0.5, 1> pigment { Base warp { toroidal dist_exp 1.5 } transform { View } translate <1, -1, 0> } finish { F } }
